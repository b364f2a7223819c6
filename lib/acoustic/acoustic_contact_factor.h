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
   ACOUSTIC package numerics, C++98 facade (acoustic_facade.h): the
   tangential vibration amplitude and the Mindlin friction factor of one
   contact, from the complex DOF values of its two grains.

   What fix acoustic/mindlin computes for each contact, in one call that
   both engines make (the LAMMPS fix calls it too):
     Delta = contact_point_displacement(dimension, model, n, r_i, r_j, q_i, q_j)
     U_t   = tangential_amplitude(Delta, n, U0)       = U0 |Delta - (Delta.n) n|
     s     = friction_factor(law, k_t, U_t, mu, F_n)  = clamp(1 - C_mu k_t U_t / (mu F_n), mu_min, 1)
   (acoustic_contact_network.h, acoustic_mindlin_law.h): the same
   operations in the same order, so the same bits.  A wall is grain j with
   its prescribed motion as q_j (its radius only multiplies its rotation,
   which is 0: fix acoustic/mindlin passes 0, the flat wall's).
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_CONTACT_FACTOR_H
#define ACOUSTIC_CONTACT_FACTOR_H

#include "acoustic_facade.h"

#include <string>

namespace Acoustic {

struct ContactFactorInput {
  int dimension;                      // 2 or 3
  FacadeContactModel::Value model;    // the DOFs per grain (facade_dofs_per_grain)
  double normal[3];                   // unit normal from j to i (z = 0 in 2D)
  double radius_i, radius_j;          // lever arms of the rotations (model full)
  // complex DOF values of grain i and grain j, dofs_per_grain (re, im) pairs
  // each: DOF k is (q[2k], q[2k+1]), translations first; not copied
  const double *q_i;
  const double *q_j;
  double amplitude;               // U0 >= 0, the drive amplitude the DOF values are relative to
  bool compute_factor;            // false: U_t only, factor = 1 (the law is not checked)
  double tangential_stiffness;    // k_t >= 0
  double friction_coefficient;    // mu >= 0
  double normal_force;            // F_n (F_n,crit of a cohesive model); <= 0: factor 1
  double cmu;                     // C_mu >= 0 (MindlinFrictionLaw)
  double mu_min;                  // lower bound of the factor, in [0, 1]

  ContactFactorInput() :
      dimension(3), model(FacadeContactModel::Normal), radius_i(0.0), radius_j(0.0), q_i(0), q_j(0),
      amplitude(0.0), compute_factor(true), tangential_stiffness(0.0), friction_coefficient(0.0),
      normal_force(0.0), cmu(1.0), mu_min(0.0)
  {
    normal[0] = normal[1] = normal[2] = 0.0;
  }
};

struct ContactFactorResult {
  double tangential_amplitude;    // U_t; 0 unless status is Success
  double factor;                  // s = mu* / mu; 1 unless status is Success
  FacadeStatus::Value status;     // Success, InvalidInput or InternalError
  std::string message;            // why, when status is not Success
  bool ok() const { return status == FacadeStatus::Success; }

  ContactFactorResult() : tangential_amplitude(0.0), factor(1.0), status(FacadeStatus::Success) {}
};

// U_t and s of one contact into result; false (status and message set) on
// invalid input, which is never thrown.  Reuse one result for many
// contacts: its message keeps its storage.
ACOUSTIC_FACADE_API bool contact_mindlin_factor(const ContactFactorInput &input,
                                                ContactFactorResult &result);

}    // namespace Acoustic

#endif
