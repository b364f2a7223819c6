/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Tangential sub-models <model>/acoustic of pair_style granular and fix
   wall/gran: the tangential model <model> with a per-contact friction
   factor s, kept as one more value of the contact's history.  The factor
   scales the Coulomb limit to s mu F_n,crit and nothing else (through
   GranSubModTangential::coulomb_mu(), which the LAMMPS patch
   cmake/patches/gran-sub-mod-tangential-coulomb-mu.patch adds); fix
   acoustic/mindlin sets it from the ultrasonic vibration of the contact.

   The history stores 1 - s, so that a new contact (history zero) starts
   at s = 1; the value is the same seen from either grain (transfer
   factor +1).  One class template wraps every tangential model.
------------------------------------------------------------------------- */

#ifdef GRAN_SUB_MOD_CLASS
// clang-format off
GranSubModStyle(linear_nohistory/acoustic,GranSubModTangentialLinearNoHistoryAcoustic,TANGENTIAL);
GranSubModStyle(linear_history/acoustic,GranSubModTangentialLinearHistoryAcoustic,TANGENTIAL);
GranSubModStyle(linear_history_classic/acoustic,GranSubModTangentialLinearHistoryClassicAcoustic,TANGENTIAL);
GranSubModStyle(mindlin_classic/acoustic,GranSubModTangentialMindlinClassicAcoustic,TANGENTIAL);
GranSubModStyle(mindlin/acoustic,GranSubModTangentialMindlinAcoustic,TANGENTIAL);
GranSubModStyle(mindlin/force/acoustic,GranSubModTangentialMindlinForceAcoustic,TANGENTIAL);
GranSubModStyle(mindlin_rescale/acoustic,GranSubModTangentialMindlinRescaleAcoustic,TANGENTIAL);
GranSubModStyle(mindlin_rescale/force/acoustic,GranSubModTangentialMindlinRescaleForceAcoustic,TANGENTIAL);
// clang-format on
#else

#ifndef GRAN_SUB_MOD_TANGENTIAL_ACOUSTIC_H
#define GRAN_SUB_MOD_TANGENTIAL_ACOUSTIC_H

#include "gran_sub_mod_tangential.h"

namespace LAMMPS_NS {
namespace Granular_NS {

  // what the ACOUSTIC package reads and writes of an /acoustic tangential model
  class AcousticFrictionFactor {
   public:
    virtual ~AcousticFrictionFactor() noexcept(false) = default;    // as Pointers

    // position of the factor in a contact's history (the model's history block
    // starts at history_index, set when the pair style or wall lays out the history)
    virtual int friction_factor_index() const = 0;

    // stiffness of the tangential spring at contact radius a (k, or k a for
    // the models that scale k by the contact radius; 0 for linear_nohistory)
    virtual double tangential_stiffness(double contact_radius) const = 0;

    // the factor s kept at `slot` = history + friction_factor_index()
    static double friction_factor(const double *slot) { return 1.0 - *slot; }
    static void set_friction_factor(double *slot, double s) { *slot = 1.0 - s; }
  };

  template <class Model>
  class GranSubModTangentialAcoustic : public Model, public AcousticFrictionFactor {
   public:
    GranSubModTangentialAcoustic(class GranularModel *, class LAMMPS *);
    // the wrapped model's mu times the factor of the current contact
    double coulomb_mu() const override;
    int friction_factor_index() const override;
    double tangential_stiffness(double contact_radius) const override;

   private:
    int model_size_history;    // history values of the wrapped model
  };

  using GranSubModTangentialLinearNoHistoryAcoustic =
      GranSubModTangentialAcoustic<GranSubModTangentialLinearNoHistory>;
  using GranSubModTangentialLinearHistoryAcoustic =
      GranSubModTangentialAcoustic<GranSubModTangentialLinearHistory>;
  using GranSubModTangentialLinearHistoryClassicAcoustic =
      GranSubModTangentialAcoustic<GranSubModTangentialLinearHistoryClassic>;
  using GranSubModTangentialMindlinClassicAcoustic =
      GranSubModTangentialAcoustic<GranSubModTangentialMindlinClassic>;
  using GranSubModTangentialMindlinAcoustic =
      GranSubModTangentialAcoustic<GranSubModTangentialMindlin>;
  using GranSubModTangentialMindlinForceAcoustic =
      GranSubModTangentialAcoustic<GranSubModTangentialMindlinForce>;
  using GranSubModTangentialMindlinRescaleAcoustic =
      GranSubModTangentialAcoustic<GranSubModTangentialMindlinRescale>;
  using GranSubModTangentialMindlinRescaleForceAcoustic =
      GranSubModTangentialAcoustic<GranSubModTangentialMindlinRescaleForce>;

  // instantiated once, in gran_sub_mod_tangential_acoustic.cpp
  extern template class GranSubModTangentialAcoustic<GranSubModTangentialLinearNoHistory>;
  extern template class GranSubModTangentialAcoustic<GranSubModTangentialLinearHistory>;
  extern template class GranSubModTangentialAcoustic<GranSubModTangentialLinearHistoryClassic>;
  extern template class GranSubModTangentialAcoustic<GranSubModTangentialMindlinClassic>;
  extern template class GranSubModTangentialAcoustic<GranSubModTangentialMindlin>;
  extern template class GranSubModTangentialAcoustic<GranSubModTangentialMindlinForce>;
  extern template class GranSubModTangentialAcoustic<GranSubModTangentialMindlinRescale>;
  extern template class GranSubModTangentialAcoustic<GranSubModTangentialMindlinRescaleForce>;

}    // namespace Granular_NS
}    // namespace LAMMPS_NS

#endif /* GRAN_SUB_MOD_TANGENTIAL_ACOUSTIC_H */
#endif /* GRAN_SUB_MOD_CLASS */
