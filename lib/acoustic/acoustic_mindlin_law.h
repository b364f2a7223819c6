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
   ACOUSTIC package numerics: contact laws used by the vibration model.

   Hertz stiffness of a contact between two grains of the same material,
   the dashpot of a damped contact, and the Mindlin friction update of
   paper 000 (Eq. 2.12):

     1/E* = 2 (1 - nu^2) / E,   1/R* = 1/r_i + 1/r_j,
     kappa = (4/3) E* sqrt(R*),  k_n = (3/2) kappa^(2/3) f_n^(1/3),
     c = 2 zeta sqrt(k m_eff),   m_eff = m_i m_j / (m_i + m_j),
     U_t = U0 |dq - (dq.n) n|    (complex modulus for complex dq),
     mu* / mu = clamp(1 - C_mu k_t U_t / (mu f_n), mu_min, 1).

   All functions validate their arguments and throw Acoustic::SolverError
   on invalid input; none returns NaN.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_MINDLIN_LAW_H
#define ACOUSTIC_MINDLIN_LAW_H

#include <Eigen/Core>

namespace Acoustic {

// E* of two grains of Young's modulus E and Poisson ratio nu: E / (2 (1 - nu^2)).
double hertz_effective_modulus(double youngs_modulus, double poisson_ratio);

// R* = 1 / (1/r_i + 1/r_j).  One radius may be infinite (a flat wall), not both.
double hertz_effective_radius(double radius_i, double radius_j);

// kappa = (4/3) E* sqrt(R*), the prefactor of the Hertz force f_n = kappa delta^(3/2).
double hertz_kappa(double youngs_modulus, double poisson_ratio, double radius_i, double radius_j);

// Tangent stiffness of the Hertz law at normal force f_n: (3/2) kappa^(2/3) f_n^(1/3).
// Returns 0 for f_n <= 0 (open contact).
double hertz_normal_stiffness(double kappa, double normal_force);

// m_i m_j / (m_i + m_j).  An infinite mass (a frozen grain or wall) gives the other mass.
double effective_mass(double mass_i, double mass_j);

// Dashpot coefficient 2 zeta sqrt(k m_eff) of a contact of stiffness k between two grains.
double dashpot_coefficient(double damping_ratio, double stiffness, double mass_i, double mass_j);

// U_t = U0 |dq - (dq.n) n| with n the real unit normal and |.| the complex modulus
// (+inf when the product exceeds the range of doubles).
double tangential_amplitude(const Eigen::Vector3cd &contact_displacement,
                            const Eigen::Vector3d &normal, double amplitude);

// Parameters of the friction update mu* / mu = clamp(1 - C_mu dF_t / (mu f_n), mu_min, 1).
struct MindlinFrictionLaw {
  double cmu = 1.0;       // C_mu >= 0
  double mu_min = 0.0;    // lower bound of mu* / mu, in [0, 1]
};

// Friction factor mu* / mu of a contact with tangential stiffness k_t, tangential
// vibration amplitude U_t, friction coefficient mu and normal force f_n.
// Returns 1 when f_n <= 0 (no load, nothing to reduce), mu == 0 (no friction),
// or k_t U_t C_mu = 0; U_t = +inf (beyond the range of doubles) gives mu_min.
double friction_factor(const MindlinFrictionLaw &law, double tangential_stiffness,
                       double tangential_amplitude, double friction_coefficient,
                       double normal_force);

}    // namespace Acoustic

#endif
