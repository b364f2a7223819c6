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

/* ----------------------------------------------------------------------
   The contact law of one type pair of pair_style granular/acoustic: the
   sub-models (normal, damping, tangential, rolling, twisting) with their
   coefficients, parsed from the pair_coeff syntax of pair_style granular,
   and the evaluation of the force of one contact split into the steps of
   the model.  The arithmetic of each step reproduces pair_style granular
   of this LAMMPS version, so that with all friction factors equal to 1 the
   two pair styles give the same trajectories.

   The friction factor s of a contact scales its Coulomb limit: the
   tangential force is capped at s * mu * F_n,crit.
------------------------------------------------------------------------- */

#ifndef LMP_GRANULAR_CONTACT_LAW_H
#define LMP_GRANULAR_CONTACT_LAW_H

#include <string>
#include <vector>

namespace LAMMPS_NS {

class GranularContactLaw {
 public:
  enum NormalModel { HOOKE, HERTZ, HERTZ_MATERIAL, DMT, JKR };
  enum DampingModel { VELOCITY, MASS_VELOCITY, VISCOELASTIC, TSUJI };
  enum TangentialModel {
    LINEAR_NOHISTORY,
    LINEAR_HISTORY,
    MINDLIN,
    MINDLIN_RESCALE,
    MINDLIN_FORCE,
    MINDLIN_RESCALE_FORCE
  };
  enum RollModel { ROLL_NONE, ROLL_SDS };
  enum TwistModel { TWIST_NONE, TWIST_SDS, TWIST_MARSHALL };

  // where the pieces of a contact's history live (same for all type pairs)
  struct HistoryLayout {
    int tangential = -1;    // 3 values: shear displacement or force
    int rescale = -1;       // 1 value: contact radius at the last step
    int roll = -1;          // 3 values: rolling displacement
    int twist = -1;         // 1 value: twist angle
    int reduction = -1;     // 1 value: 1 - s (zero for a new contact: s = 1)
    int size = 0;
  };

  // one touching pair: inputs of the evaluation, and what it leaves behind
  struct Contact {
    // inputs
    double del[3];         // x_i - x_j
    double rsq;            // |del|^2
    double radi, radj;
    double vr[3];          // v_i - v_j
    const double *omegai, *omegaj;
    double meff;           // effective mass (frozen partner already handled)
    double dt;
    bool history_update;   // false during setup, as in pair granular
    // results of the normal step
    double r, rinv, n[3], Reff, delta, a, knfac;
    double vnnr;           // normal relative velocity
    double Fne;            // elastic normal force (no damping)
    double damp_normal_prefactor;
    double Fntot;          // normal force including damping
    double Fncrit;         // normal force entering the Coulomb limits
    // results of the tangential, rolling and twisting steps
    double k_tangential, damp_tangential;
    double fs[3], fsmag;   // tangential force on i
    double fr[3], frmag;   // rolling resistance force
    double magtortwist;    // twisting torque magnitude about n
  };

  NormalModel normal = HOOKE;
  DampingModel damping = VISCOELASTIC;
  TangentialModel tangential = LINEAR_NOHISTORY;
  RollModel roll = ROLL_NONE;
  TwistModel twist = TWIST_NONE;
  int limit_damping = 0;

  double kn = 0.0;            // Hooke/Hertz stiffness, or 4/3 E* for material models
  double damp = 0.0;          // normal damping coefficient (Tsuji: from the restitution coefficient)
  double cohesion = 0.0;      // DMT/JKR surface energy
  double Emod = 0.0, poisson = 0.0;    // material models only (used for mixing)
  double kt = 0.0;            // tangential stiffness (Mindlin: 8 G* when given as NULL)
  double damp_tangential = 0.0;    // tangential damping relative to normal damping
  double mu = 0.0;            // sliding friction coefficient
  double kroll = 0.0, damp_roll = 0.0, mu_roll = 0.0;
  double ktwist = 0.0, damp_twist = 0.0, mu_twist = 0.0;
  double cutoff = -1.0;       // user cutoff, -1 = from radii

  // parse the model words of a pair_coeff line; on error returns a message
  // that names the problem and the accepted syntax, else an empty string
  std::string parse(const std::vector<std::string> &words);

  // coefficients of the pair i-j mixed from those of i-i and j-j;
  // returns an empty string or the reason why they cannot be mixed
  std::string mix(const GranularContactLaw &ii, const GranularContactLaw &jj);

  // flat serialisation for restart files
  static constexpr int NINT = 6;
  static constexpr int NDOUBLE = 16;
  void pack(int *ivalues, double *dvalues) const;
  void unpack(const int *ivalues, const double *dvalues);

  bool has_tangential_history() const { return tangential != LINEAR_NOHISTORY; }
  bool has_rescale_history() const
  {
    return tangential == MINDLIN_RESCALE || tangential == MINDLIN_RESCALE_FORCE;
  }
  bool beyond_contact() const { return normal == JKR; }

  // squared distance below which i and j interact; `was_touching` matters for JKR
  double touch_distance_sq(double radi, double radj, bool was_touching) const
  {
    if (normal == JKR && was_touching) return jkr_touch_distance_sq(radi, radj);
    const double radsum = radi + radj;
    return radsum * radsum;
  }
  // pull-off distance beyond contact (JKR), 0 otherwise
  double pulloff_distance(double radi, double radj) const;

  // normal step: geometry, elastic and damped normal force
  void normal_force(Contact &c) const;
  // linearised normal stiffness dF_n/d(delta) at the state of the last normal_force()
  double normal_stiffness(const Contact &c) const;
  // tangential stiffness at that state (0 for linear_nohistory)
  double tangential_stiffness(const Contact &c) const;

  // tangential step with Coulomb limit s * mu * Fncrit; updates history
  void tangential_force(Contact &c, double *history, const HistoryLayout &layout,
                        double s) const;
  void rolling_force(Contact &c, double *history, const HistoryLayout &layout) const;
  void twisting_torque(Contact &c, double *history, const HistoryLayout &layout) const;

  static std::string supported_models();

 private:
  double jkr_touch_distance_sq(double radi, double radj) const;
  void relative_tangential_velocity(const Contact &c, double *vtr) const;
};

}    // namespace LAMMPS_NS

#endif
