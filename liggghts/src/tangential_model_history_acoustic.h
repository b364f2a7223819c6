/* ----------------------------------------------------------------------
    ACOUSTIC for LIGGGHTS-PUBLIC 3.8: the tangential model history/acoustic.

    LIGGGHTS is open-source, distributed under the terms of the GNU Public
    License, version 2 or later.  This file is part of the ACOUSTIC
    package and distributed under the same terms.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   pair_style gran model <normal> tangential history/acoustic (and the same
   in fix wall/gran, for primitive walls and meshes): LIGGGHTS's tangential
   model "history" with a per-contact friction factor s, kept as one more
   value of the contact history.  The factor scales the Coulomb limit to
   s coeffFrict |F_n| and nothing else; fix acoustic/mindlin sets it from
   the ultrasonic vibration of the contact.

   The history stores 1 - s (name "acousticFrictionReduction"), so that a
   new contact, whose history LIGGGHTS zeroes, starts at s = 1; the value is
   the same seen from either grain (newton flag 0).  It is zeroed again when
   the contact opens (surfacesClose), as the shear displacement is.

   The model wraps LIGGGHTS's own TangentialModel<TANGENTIAL_HISTORY>
   rather than copying it: the history model uses the normal force F_n in
   one place only, its Coulomb limit coeffFrict |F_n|, so it is handed the
   contact data with F_n scaled by s.  With s = 1 the product is exact and
   the forces are bitwise those of "tangential history" (tested).
------------------------------------------------------------------------- */

#ifdef TANGENTIAL_MODEL
TANGENTIAL_MODEL(TANGENTIAL_HISTORY_ACOUSTIC,history/acoustic,21)
#else
#ifndef TANGENTIAL_MODEL_HISTORY_ACOUSTIC_H_
#define TANGENTIAL_MODEL_HISTORY_ACOUSTIC_H_
#include "contact_models.h"
#include "tangential_model_base.h"
#include "tangential_model_history.h"

namespace LIGGGHTS {
namespace ContactModels
{
  // what the ACOUSTIC styles read and write of a history/acoustic contact
  struct AcousticFrictionFactor
  {
    static const char *history_name() { return "acousticFrictionReduction"; }
    // the factor s kept at slot = contact history + offset of history_name()
    static double friction_factor(const double *slot) { return 1.0 - *slot; }
    static void set_friction_factor(double *slot, double s) { *slot = 1.0 - s; }
  };

  template<>
  class TangentialModel<TANGENTIAL_HISTORY_ACOUSTIC> : public TangentialModelBase
  {
  public:
    TangentialModel(LAMMPS * lmp, IContactHistorySetup * hsetup, class ContactModelBase *c) :
        TangentialModelBase(lmp, hsetup, c),
        history_model(lmp, hsetup, c),
        factor_offset(hsetup->add_history_value(AcousticFrictionFactor::history_name(), "0"))
    {
        // fix acoustic/mindlin finds the value by its name (get_history_offset)
        if (c) c->add_history_offset(AcousticFrictionFactor::history_name(), factor_offset);
    }

    inline void registerSettings(Settings& settings)
    { history_model.registerSettings(settings); }

    inline void postSettings(IContactHistorySetup * hsetup, ContactModelBase *cmb)
    { history_model.postSettings(hsetup, cmb); }

    inline void connectToProperties(PropertyRegistry & registry)
    { history_model.connectToProperties(registry); }

    inline void surfacesIntersect(const SurfacesIntersectData & sidata, ForceData & i_forces, ForceData & j_forces)
    {
        const double s = AcousticFrictionFactor::friction_factor(&sidata.contact_history[factor_offset]);
        if (s == 1.0) {
            history_model.surfacesIntersect(sidata, i_forces, j_forces);
            return;
        }
        SurfacesIntersectData scaled(sidata);
        scaled.Fn = s * sidata.Fn;
        history_model.surfacesIntersect(scaled, i_forces, j_forces);
        sidata.P_diss = scaled.P_diss;    // the heating option's tally (mutable)
    }

    inline void surfacesClose(SurfacesCloseData & scdata, ForceData & i_forces, ForceData & j_forces)
    {
        history_model.surfacesClose(scdata, i_forces, j_forces);
        if (scdata.contact_history)
            AcousticFrictionFactor::set_friction_factor(&scdata.contact_history[factor_offset], 1.0);
    }

    inline void beginPass(SurfacesIntersectData & sidata, ForceData & i_forces, ForceData & j_forces)
    { history_model.beginPass(sidata, i_forces, j_forces); }
    inline void endPass(SurfacesIntersectData & sidata, ForceData & i_forces, ForceData & j_forces)
    { history_model.endPass(sidata, i_forces, j_forces); }

  private:
    TangentialModel<TANGENTIAL_HISTORY> history_model;
    int factor_offset;
  };
}
}
#endif // TANGENTIAL_MODEL_HISTORY_ACOUSTIC_H_
#endif
