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
   The current contacts of pair_style granular, read from the pair style's
   own models and history (as fix granular/mdr walks them), those of the
   planes of fix wall/gran (read through FixWallGran::extract(), which
   cmake/patches/fix-wall-gran-extract.patch adds to LAMMPS) and those of
   the regions of fix wall/gran/region (its public region and histories),
   linearised for the vibration network of the ACOUSTIC package:
     k_n = dF_n/d(delta) of the contact's normal model (closed form for
           hooke, hertz, hertz/material, dmt; a centred difference of the
           model's own force for jkr and any other model without history),
     k_t, mu from its tangential model, and the history slot of the
     contact's friction factor: the tangential models of pair granular must
     be /acoustic ones; a wall contact without one keeps its friction.
------------------------------------------------------------------------- */

#ifndef LMP_GRANULAR_CONTACT_WALKER_H
#define LMP_GRANULAR_CONTACT_WALKER_H

#include "pointers.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

namespace Granular_NS {
  class GranularModel;
}

// one touching contact of an owned atom, with another atom or with a wall
struct GranularContact {
  int i, j;             // local indices: i owned, j owned or ghost; j = -1 for a wall
  int wall;             // the wall plane (GranularContactWalker::walls()), -1 for two atoms
  bool owned;           // this processor counts the contact (newton off lists a
                        // contact across sub-domains on both of its processors)
  double n[3];          // unit normal (x_i - x_j) / |x_i - x_j|, from the wall for a wall
  double radi, radj;    // radj = 0 for a (flat) wall
  double delta;         // overlap
  double fn;            // elastic normal force F_n(delta), damping excluded
  double fncrit;        // normal force of the Coulomb limit (F_n,crit of the normal
                        // model, damping excluded; = fn unless the model is cohesive)
  double kn;            // dF_n/d(delta)
  double kt;            // stiffness of the tangential spring
  double mu;            // friction coefficient of the tangential model
  double *factor;       // history slot of the friction factor (see AcousticFrictionFactor);
                        // nullptr for a wall whose tangential model has none
};

// a rigid wall of the network: a plane of fix wall/gran (one fix may have a
// lower and an upper plane), or the surface of the region of a fix
// wall/gran/region (its contacts found by the region, as the fix finds them)
struct WallPlane {
  std::string fix_id;
  int side;           // 0: the lower plane of the fix, 1: the upper one (region: 0)
  int axis;           // 0, 1, 2: normal along x, y, z; -1: a region's surface
  double position;    // coordinate of the plane along its axis (region: unused)
  bool region;        // a fix wall/gran/region
};

class GranularContactWalker : protected Pointers {
 public:
  // `command` names the style in error messages
  GranularContactWalker(class LAMMPS *, const std::string &command);

  // find pair granular and its history, check that every model can be
  // linearised and has an /acoustic tangential model; call from init().
  // with_regions: the walls of fix wall/gran/region are walls of the network
  // (otherwise free surfaces, with a WARNING)
  void init(bool with_regions);

  // the touching contacts of owned atoms with both atoms in groupbit, then
  // the contacts of owned atoms in groupbit with the wall planes; a contact
  // that cannot be linearised (coincident atoms, a non-finite force) is
  // reported to `errors` with its atom IDs and left out
  void collect(std::vector<GranularContact> &contacts, int groupbit, class CollectiveError &errors);

  // the planes of the fix wall/gran instances, in the order of the fixes
  // (every rank the same); valid after init()
  const std::vector<WallPlane> &walls() const { return planes; }

  // Between runs: set the friction factor of every contact of the group
  // with history to 1 and hand the histories to the history fix, which
  // restores the neighbor lists from its per-atom copy at the next setup.
  // The neighbor lists must still match the atoms (no exchange of atoms
  // since the last run).  Collective; false, doing nothing, when pair
  // granular, its history or its neighbor list are gone.
  bool reset_factors_between_runs(int groupbit);

  // the friction factor kept in a contact's history slot
  static double friction_factor(const double *factor);
  static void set_friction_factor(double *factor, double s);

  // linearise the contact whose geometry (check_contact) is set in `model`
  static void linearise(Granular_NS::GranularModel *model, GranularContact &contact);

 private:
  std::string command;
  class PairGranular *pair;
  class FixNeighHistory *history;

  // the planes; their fixes are looked up by ID when used (a fix may be
  // deleted between runs)
  std::vector<WallPlane> planes;
  bool region_walls = true;    // the argument of the last init()

  void check_model(Granular_NS::GranularModel *model, const std::string &where, bool needs_factor);
  void locate();    // pair granular and its history fix, nullptr if absent
  void locate_walls(bool with_regions);
  bool neighbor_history_ready() const;    // collective
  void collect_pair(std::vector<GranularContact> &contacts, int groupbit,
                    class CollectiveError &errors);
  void add_wall_contact(Granular_NS::GranularModel *model, int i, int wall,
                        std::vector<GranularContact> &contacts, class CollectiveError &errors);
  void collect_region_wall(std::vector<GranularContact> &contacts, int groupbit, int wall,
                           class CollectiveError &errors);
  void collect_walls(std::vector<GranularContact> &contacts, int groupbit,
                     class CollectiveError &errors);
};

}    // namespace LAMMPS_NS

#endif
