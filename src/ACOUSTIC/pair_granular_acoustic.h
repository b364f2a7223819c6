/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   Steve Plimpton, sjplimp@sandia.gov

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(granular/acoustic,PairGranularAcoustic);
// clang-format on
#else

#ifndef LMP_PAIR_GRANULAR_ACOUSTIC_H
#define LMP_PAIR_GRANULAR_ACOUSTIC_H

#include "granular_contact_law.h"
#include "pair.h"

#include <vector>

namespace LAMMPS_NS {

class PairGranularAcoustic : public Pair {
 public:
  // one current contact of an owned atom, as seen by the package's fixes and computes
  struct ContactState {
    int i, j;               // local indices; i is owned, j owned or ghost
    double n[3];            // unit normal (x_i - x_j)/|x_i - x_j|
    double delta;           // overlap
    double radi, radj;
    double fn;              // elastic normal force (no damping)
    double mu;              // friction coefficient of the type pair
    double kn, kt;          // linearised stiffnesses dF_n/d(delta) and tangential
    double *history;        // the contact's history values
  };

  PairGranularAcoustic(class LAMMPS *);
  ~PairGranularAcoustic() override;

  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void reset_dt() override;
  double single(int, int, int, int, double, double, double, double &) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;
  double atom2cut(int) override;
  double radii2cut(double, double) override;
  void transfer_history(double *, double *) override;

  // contacts of owned atoms with both atoms in groupbit, touching now;
  // with newton_pair off a contact across a sub-domain boundary is listed on
  // both of its processors
  void current_contacts(std::vector<ContactState> &contacts, int groupbit);

  // the friction factor s of a contact, kept in its history as 1 - s so that
  // a new contact (history zero) starts at s = 1
  double friction_factor(const double *history) const
  {
    return 1.0 - history[layout.reduction];
  }
  void set_friction_factor(double *history, double s) const
  {
    history[layout.reduction] = 1.0 - s;
  }
  // factors changed between two runs (not during a run) must be handed to the
  // history fix, which otherwise restores the copy it took at the end of the run
  void store_history_between_runs();

 protected:
  double dt;
  int freeze_group_bit;
  int ntypes_allocated;

  std::vector<GranularContactLaw> laws;    // (ntypes+1)^2 type pairs
  GranularContactLaw::HistoryLayout layout;
  int history_size_created;    // history size of the fix, fixed at its creation
  std::vector<int> history_transfer_factors;
  double cutoff_global;
  int beyond_contact_any;

  double *onerad_dynamic, *onerad_frozen;
  double *maxrad_dynamic, *maxrad_frozen;

  class FixDummy *fix_dummy;
  class FixNeighHistory *fix_history;

  class Fix *fix_rigid;    // rigid body fix, nullptr if none
  double *mass_rigid;      // rigid body mass of owned + ghost atoms
  int nmax;
  int neighprev;

  GranularContactLaw &law(int itype, int jtype) { return laws[itype * (ntypes_allocated + 1) + jtype]; }
  const GranularContactLaw &law(int itype, int jtype) const
  {
    return laws[itype * (ntypes_allocated + 1) + jtype];
  }
  void allocate();
  void update_rigid_masses();
  double effective_mass(int i, int j) const;
  void fill_contact(GranularContactLaw::Contact &c, int i, int j, double delx, double dely,
                    double delz, double rsq) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
