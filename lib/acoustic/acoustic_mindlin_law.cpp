/* ----------------------------------------------------------------------
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
------------------------------------------------------------------------- */

#include "acoustic_mindlin_law.h"

#include "acoustic_solver_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace Acoustic {

namespace {

  // the message is built only when a check fails: these functions run once per contact
  [[noreturn]] void fail(const std::string &message)
  {
    throw SolverError(message);
  }

  bool is_positive_mass(double m)
  {
    return m > 0.0 && !std::isnan(m);    // +inf allowed: frozen grain or wall
  }

}    // namespace

double hertz_effective_modulus(double youngs_modulus, double poisson_ratio)
{
  if (!(std::isfinite(youngs_modulus) && youngs_modulus > 0.0))
    fail("Hertz stiffness: Young's modulus must be positive and finite, got " +
         std::to_string(youngs_modulus));
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5))
    fail("Hertz stiffness: Poisson ratio must lie in (-1, 0.5), got " +
         std::to_string(poisson_ratio));
  return youngs_modulus / (2.0 * (1.0 - poisson_ratio * poisson_ratio));
}

double hertz_effective_radius(double radius_i, double radius_j)
{
  if (!(radius_i > 0.0 && radius_j > 0.0))
    fail("Hertz stiffness: grain radii must be positive, got " + std::to_string(radius_i) +
         " and " + std::to_string(radius_j));
  if (!(std::isfinite(radius_i) || std::isfinite(radius_j)))
    fail("Hertz stiffness: at most one of the two radii may be infinite (a flat wall)");
  return 1.0 / (1.0 / radius_i + 1.0 / radius_j);
}

double hertz_kappa(double youngs_modulus, double poisson_ratio, double radius_i, double radius_j)
{
  return 4.0 / 3.0 * hertz_effective_modulus(youngs_modulus, poisson_ratio) *
      std::sqrt(hertz_effective_radius(radius_i, radius_j));
}

double hertz_normal_stiffness(double kappa, double normal_force)
{
  if (!(std::isfinite(kappa) && kappa > 0.0))
    fail("Hertz stiffness: kappa must be positive and finite, got " + std::to_string(kappa));
  if (!(std::isfinite(normal_force))) fail("Hertz stiffness: the normal force is not finite");
  if (normal_force <= 0.0) return 0.0;
  return 1.5 * std::pow(kappa, 2.0 / 3.0) * std::cbrt(normal_force);
}

double effective_mass(double mass_i, double mass_j)
{
  if (!(is_positive_mass(mass_i) && is_positive_mass(mass_j)))
    fail("effective mass: grain masses must be positive, got " + std::to_string(mass_i) + " and " +
         std::to_string(mass_j));
  if (!(std::isfinite(mass_i) || std::isfinite(mass_j)))
    fail("effective mass: a contact between two infinite (frozen) masses has no dynamics");
  if (!std::isfinite(mass_i)) return mass_j;
  if (!std::isfinite(mass_j)) return mass_i;
  return mass_i * mass_j / (mass_i + mass_j);
}

double dashpot_coefficient(double damping_ratio, double stiffness, double mass_i, double mass_j)
{
  if (!(std::isfinite(damping_ratio) && damping_ratio >= 0.0))
    fail("dashpot: the damping ratio zeta must be >= 0, got " + std::to_string(damping_ratio));
  if (!(std::isfinite(stiffness) && stiffness >= 0.0))
    fail("dashpot: the contact stiffness must be >= 0 and finite, got " +
         std::to_string(stiffness));
  return 2.0 * damping_ratio * std::sqrt(stiffness * effective_mass(mass_i, mass_j));
}

double tangential_amplitude(const Eigen::Vector3cd &contact_displacement,
                            const Eigen::Vector3d &normal, double amplitude)
{
  if (!(std::isfinite(amplitude) && amplitude >= 0.0))
    fail("tangential amplitude: the vibration amplitude U0 must be >= 0, got " +
         std::to_string(amplitude));
  if (!(std::abs(normal.norm() - 1.0) < 1e-8))
    fail("tangential amplitude: the contact normal must be a unit vector");
  if (!(contact_displacement.allFinite()))
    fail("tangential amplitude: the contact displacement is not finite");
  // dq.n without complex conjugation (Eigen's dot conjugates its left operand, here the real n)
  const Eigen::Vector3cd n = normal.cast<std::complex<double>>();
  const std::complex<double> along = n.dot(contact_displacement);
  const Eigen::Vector3cd tangential = contact_displacement - along * n;
  return amplitude * tangential.norm();
}

double friction_factor(const MindlinFrictionLaw &law, double tangential_stiffness,
                       double tangential_amplitude, double friction_coefficient,
                       double normal_force)
{
  if (!(std::isfinite(law.cmu) && law.cmu >= 0.0))
    fail("friction update: C_mu must be >= 0, got " + std::to_string(law.cmu));
  if (!(law.mu_min >= 0.0 && law.mu_min <= 1.0))
    fail("friction update: mu_min must lie in [0, 1], got " + std::to_string(law.mu_min));
  if (!(std::isfinite(tangential_stiffness) && tangential_stiffness >= 0.0))
    fail("friction update: the tangential stiffness must be >= 0 and finite, got " +
         std::to_string(tangential_stiffness));
  // +inf is allowed: an amplitude beyond the range of doubles lowers the factor to mu_min
  if (!(tangential_amplitude >= 0.0))
    fail("friction update: the tangential amplitude must be >= 0, got " +
         std::to_string(tangential_amplitude));
  if (!(std::isfinite(friction_coefficient) && friction_coefficient >= 0.0))
    fail("friction update: the friction coefficient must be >= 0 and finite, got " +
         std::to_string(friction_coefficient));
  if (!(!std::isnan(normal_force))) fail("friction update: the normal force is NaN");
  if (normal_force <= 0.0 || friction_coefficient == 0.0) return 1.0;
  // no tangential spring, no vibration or C_mu = 0: no reduction (and no 0 * inf)
  if (law.cmu == 0.0 || tangential_stiffness == 0.0 || tangential_amplitude == 0.0) return 1.0;
  const double numerator = law.cmu * tangential_stiffness * tangential_amplitude;
  const double denominator = friction_coefficient * normal_force;
  double reduction = numerator / denominator;
  if (!(std::isfinite(numerator) && std::isfinite(denominator)))
    // a product beyond the range of doubles: the same ratio from logarithms,
    // finite or +inf (every factor is positive and all but U_t are finite)
    reduction = std::exp(std::log(law.cmu) + std::log(tangential_stiffness) +
                         std::log(tangential_amplitude) - std::log(friction_coefficient) -
                         std::log(normal_force));
  return std::min(1.0, std::max(law.mu_min, 1.0 - reduction));
}

}    // namespace Acoustic
