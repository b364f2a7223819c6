/* ----------------------------------------------------------------------
   Unit tests: Hertz stiffness, dashpots and the Mindlin friction update.
------------------------------------------------------------------------- */

#include "acoustic_mindlin_law.h"
#include "acoustic_solver_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <limits>

using namespace Acoustic;

namespace {
const double inf = std::numeric_limits<double>::infinity();
}

TEST(HertzLaw, EffectiveModulusAndRadius)
{
  EXPECT_DOUBLE_EQ(hertz_effective_modulus(2.0e9, 0.0), 1.0e9);
  EXPECT_DOUBLE_EQ(hertz_effective_modulus(1.5e9, 0.3), 1.5e9 / (2.0 * 0.91));
  EXPECT_DOUBLE_EQ(hertz_effective_radius(1.0, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(hertz_effective_radius(2.0, 3.0), 1.2);
  EXPECT_DOUBLE_EQ(hertz_effective_radius(2.0, inf), 2.0);    // sphere on a flat wall
  EXPECT_THROW(hertz_effective_radius(inf, inf), SolverError);
  EXPECT_THROW(hertz_effective_radius(-1.0, 1.0), SolverError);
  EXPECT_THROW(hertz_effective_modulus(1.0, 0.5), SolverError);
  EXPECT_THROW(hertz_effective_modulus(0.0, 0.3), SolverError);
}

TEST(HertzLaw, KappaOfEqualSpheres)
{
  // two spheres of radius R, nu = 0: E* = E/2, R* = R/2, kappa = (4/3)(E/2) sqrt(R/2)
  const double e = 7.0e10, r = 1.0e-3;
  EXPECT_NEAR(hertz_kappa(e, 0.0, r, r), 2.0 / 3.0 * e * std::sqrt(r / 2.0), 1e-12 * e);
}

TEST(HertzLaw, StiffnessIsTheDerivativeOfTheForce)
{
  // f = kappa delta^(3/2): k_n(f) must equal df/d delta, here by a central difference
  const double kappa = hertz_kappa(6.0e10, 0.22, 0.8e-3, 1.3e-3);
  const double delta = 2.0e-6, h = 1.0e-10;
  const double force = kappa * std::pow(delta, 1.5);
  const double slope = kappa * (std::pow(delta + h, 1.5) - std::pow(delta - h, 1.5)) / (2.0 * h);
  EXPECT_NEAR(hertz_normal_stiffness(kappa, force), slope, 1e-7 * slope);
  EXPECT_EQ(hertz_normal_stiffness(kappa, 0.0), 0.0);
  EXPECT_EQ(hertz_normal_stiffness(kappa, -1.0), 0.0);
}

TEST(MindlinLaw, TangentialAmplitudeUsesTheComplexModulus)
{
  const Eigen::Vector3d n(1.0, 0.0, 0.0);
  Eigen::Vector3cd dq;
  dq << std::complex<double>(5.0, -7.0), std::complex<double>(0.0, 3.0), std::complex<double>(4.0, 0.0);
  EXPECT_NEAR(tangential_amplitude(dq, n, 2.0), 2.0 * 5.0, 1e-14);    // |(0, 3i, 4)| = 5
  const Eigen::Vector3d m(0.6, 0.8, 0.0);
  const Eigen::Vector3cd along = std::complex<double>(1.0, 2.0) * m.cast<std::complex<double>>();
  EXPECT_NEAR(tangential_amplitude(along, m, 1.0), 0.0, 1e-15);
  EXPECT_THROW(tangential_amplitude(dq, Eigen::Vector3d(1.0, 1.0, 0.0), 1.0), SolverError);
}

TEST(MindlinLaw, ReproducesPaper000ClosedForm)
{
  // Paper 000: with Hertz k_n, k_t = (2/7) k_n and C_mu = 1,
  //   mu* / mu = 1 - 3 U0 kappa^(2/3) |P dq| / (7 mu f_n^(2/3)).
  const double kappa = 100.0 * hertz_kappa(7.0e10, 0.25, 1.0e-3, 1.2e-3);
  const double fn = 0.35, mu = 0.5, u0 = 1.0e-8;
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  Eigen::Vector3cd dq;
  dq << std::complex<double>(0.7, 0.2), std::complex<double>(-1.1, 0.4), std::complex<double>(0.5, -0.9);

  const double kn = hertz_normal_stiffness(kappa, fn);
  const double kt = 2.0 / 7.0 * kn;
  const MindlinFrictionLaw law;    // C_mu = 1, mu_min = 0
  const double factor = friction_factor(law, kt, tangential_amplitude(dq, n, u0), mu, fn);

  Eigen::Vector3cd p_dq = dq;    // P dq: tangential projection, written out component-wise
  std::complex<double> dq_n = 0.0;
  for (int k = 0; k < 3; ++k) dq_n += dq[k] * n[k];
  for (int k = 0; k < 3; ++k) p_dq[k] -= dq_n * n[k];
  double modulus = 0.0;
  for (int k = 0; k < 3; ++k) modulus += std::norm(p_dq[k]);
  modulus = std::sqrt(modulus);
  const double expected = 1.0 - 3.0 * u0 * std::pow(kappa, 2.0 / 3.0) * modulus / (7.0 * mu * std::pow(fn, 2.0 / 3.0));
  ASSERT_GT(expected, 0.05);
  ASSERT_LT(expected, 0.95);
  EXPECT_NEAR(factor, expected, 1e-12);
}

TEST(MindlinLaw, FactorIsClampedAndOneWithoutLoad)
{
  MindlinFrictionLaw law;
  law.cmu = 2.0;
  EXPECT_DOUBLE_EQ(friction_factor(law, 10.0, 0.01, 0.5, 2.0), 1.0 - 2.0 * 10.0 * 0.01 / (0.5 * 2.0));
  EXPECT_EQ(friction_factor(law, 10.0, 1.0, 0.5, 2.0), 0.0);    // clamped at mu_min = 0
  law.mu_min = 0.3;
  EXPECT_EQ(friction_factor(law, 10.0, 1.0, 0.5, 2.0), 0.3);
  EXPECT_EQ(friction_factor(law, 10.0, 0.0, 0.5, 2.0), 1.0);
  EXPECT_EQ(friction_factor(law, 10.0, 1.0, 0.5, 0.0), 1.0);     // f_n = 0: no load
  EXPECT_EQ(friction_factor(law, 10.0, 1.0, 0.5, -3.0), 1.0);    // f_n < 0: open contact
  EXPECT_EQ(friction_factor(law, 10.0, 1.0, 0.0, 2.0), 1.0);     // frictionless contact
  law.mu_min = 1.5;
  EXPECT_THROW(friction_factor(law, 10.0, 1.0, 0.5, 2.0), SolverError);
  law.mu_min = 0.0;
  law.cmu = -1.0;
  EXPECT_THROW(friction_factor(law, 10.0, 1.0, 0.5, 2.0), SolverError);
  EXPECT_THROW(friction_factor(MindlinFrictionLaw(), 10.0, 1.0, 0.5, std::nan("")), SolverError);
}

TEST(MindlinLaw, AmplitudesBeyondTheRangeOfDoubles)
{
  // U_t = +inf or products that overflow: the smallest factor, never NaN
  MindlinFrictionLaw law;
  law.mu_min = 0.25;
  EXPECT_EQ(friction_factor(law, 10.0, inf, 0.5, 2.0), 0.25);
  EXPECT_EQ(friction_factor(law, 1e300, 1e300, 0.5, 2.0), 0.25);
  law.cmu = 1e300;
  EXPECT_EQ(friction_factor(law, 1e10, 1e10, 0.5, 2.0), 0.25);
  // a tiny product that does not overflow is still exact
  EXPECT_DOUBLE_EQ(friction_factor(law, 1e-300, 1e-10, 0.5, 2.0), 1.0 - 1e300 * 1e-300 * 1e-10);
  // both products overflow (mu f_n too): the ratio from logarithms,
  // 1e300 * 5e299 / (1e300 * 1e300) = 0.5
  law.cmu = 1.0;
  law.mu_min = 0.0;
  EXPECT_NEAR(friction_factor(law, 1e300, 5e299, 1e300, 1e300), 0.5, 1e-12);
  // no tangential spring, or C_mu = 0: no reduction, even for an infinite amplitude
  EXPECT_EQ(friction_factor(law, 0.0, inf, 0.5, 2.0), 1.0);
  law.cmu = 0.0;
  EXPECT_EQ(friction_factor(law, 10.0, inf, 0.5, 2.0), 1.0);
  EXPECT_THROW(friction_factor(MindlinFrictionLaw(), 10.0, std::nan(""), 0.5, 2.0), SolverError);
  // U0 |P dq| overflowing is +inf, not an error
  EXPECT_EQ(tangential_amplitude(Eigen::Vector3cd(1e200, 0.0, 0.0), Eigen::Vector3d(0.0, 1.0, 0.0), 1e200),
            inf);
}

TEST(Dashpot, EffectiveMassAndCoefficient)
{
  EXPECT_DOUBLE_EQ(effective_mass(2.0, 3.0), 1.2);
  EXPECT_DOUBLE_EQ(effective_mass(2.0, inf), 2.0);    // frozen partner
  EXPECT_DOUBLE_EQ(effective_mass(inf, 5.0), 5.0);
  EXPECT_THROW(effective_mass(inf, inf), SolverError);
  EXPECT_THROW(effective_mass(0.0, 1.0), SolverError);
  EXPECT_DOUBLE_EQ(dashpot_coefficient(0.1, 50.0, 2.0, 3.0), 2.0 * 0.1 * std::sqrt(50.0 * 1.2));
  EXPECT_DOUBLE_EQ(dashpot_coefficient(0.0, 50.0, 2.0, 3.0), 0.0);
  EXPECT_THROW(dashpot_coefficient(-0.1, 50.0, 2.0, 3.0), SolverError);
}
