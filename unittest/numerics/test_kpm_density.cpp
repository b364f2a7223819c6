/* ----------------------------------------------------------------------
   Unit tests: density of states by the kernel polynomial method.
------------------------------------------------------------------------- */

#include "acoustic_contact_network.h"
#include "acoustic_dynamical_matrix.h"
#include "acoustic_kpm_density.h"
#include "acoustic_solver_error.h"
#include "acoustic_vibration_modes.h"
#include "network_builders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace Acoustic;

namespace {
const double pi = 3.14159265358979323846;
}

TEST(KpmDensity, ExactForDiagonalMatrices)
{
  // For diagonal D every +-1 vector gives the exact trace, so KPM equals the Jackson-broadened
  // exact spectrum; with bins much wider than the broadening, the exact histogram.
  Eigen::VectorXd f(6);
  f << 1.5, 2.5, 2.5, 2.7, 7.5, 12.0;    // 12 lies outside [0, 10]
  Eigen::SparseMatrix<double> k(6, 6);
  Eigen::VectorXd mass(6);
  for (int i = 0; i < 6; ++i) {
    mass[i] = 1.0 + i;
    k.insert(i, i) = mass[i] * std::pow(2.0 * pi * f[i], 2);
  }
  const DynamicalMatrix dynamical(k, mass, {}, 1);
  KpmOptions options;
  options.moments = 3000;
  options.random_vectors = 3;
  const FrequencyHistogram kpm = kpm_frequency_histogram(dynamical, 10, 0.0, 10.0, options);
  const FrequencyHistogram exact = frequency_histogram(f, 10, 0.0, 10.0);
  EXPECT_LT((kpm.density - exact.density).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_NEAR(kpm.counted, 5.0, 1e-5);
  EXPECT_LT(kpm.density_error.maxCoeff(), 1e-10);
}

TEST(KpmDensity, MatchesDenseOnDisorderedNetwork)
{
  // 30 x 30 triangular patch, bottom row fixed, random stiffness, masses and contact directions
  std::vector<int> bottom;
  const ContactNetwork network = AcousticTest::disordered_network(30, 30, 11u, bottom);
  const DynamicalMatrix dynamical(network.stiffness_matrix(), network.mass_diagonal(), bottom, 2);
  ASSERT_GT(dynamical.num_free(), 1000);

  const VibrationModes modes = dense_vibration_modes(dynamical, false);
  ASSERT_EQ(modes.zero_modes, 0);
  const double fmax = modes.frequencies.maxCoeff() * 1.0001;
  const int nbins = 16;
  const FrequencyHistogram exact = frequency_histogram(modes.frequencies, nbins, 0.0, fmax);
  KpmOptions options;
  options.moments = 400;
  options.random_vectors = 64;
  const FrequencyHistogram kpm = kpm_frequency_histogram(dynamical, nbins, 0.0, fmax, options);

  EXPECT_NEAR(kpm.density.sum() * kpm.bin_width, 1.0, 1e-12);
  EXPECT_NEAR(kpm.counted, dynamical.num_free(), 0.01 * dynamical.num_free());
  const double l1 = (kpm.density - exact.density).cwiseAbs().sum() * kpm.bin_width;
  EXPECT_LE(l1, 0.03);
  // the error estimate is of the size of the actual deviation
  const double estimated = kpm.density_error.sum() * kpm.bin_width;
  EXPECT_GT(estimated, 0.0);
  EXPECT_LT(estimated, 0.05);
  RecordProperty("L1", std::to_string(l1));
  std::printf("KPM vs dense on %d DOFs: L1 = %.4f, summed error estimate = %.4f\n", dynamical.num_free(), l1,
              estimated);
}

TEST(KpmDensity, RejectsInvalidOptions)
{
  Eigen::SparseMatrix<double> k(2, 2);
  k.insert(0, 0) = 1.0;
  k.insert(1, 1) = 2.0;
  const DynamicalMatrix dynamical(k, Eigen::VectorXd::Ones(2), {}, 1);
  KpmOptions options;
  options.moments = 1;
  EXPECT_THROW(kpm_frequency_histogram(dynamical, 4, 0.0, 1.0, options), SolverError);
  options = KpmOptions();
  options.random_vectors = 1;
  EXPECT_THROW(kpm_frequency_histogram(dynamical, 4, 0.0, 1.0, options), SolverError);
  EXPECT_THROW(kpm_frequency_histogram(dynamical, 4, 1.0, 1.0), SolverError);

  // a negative eigenvalue below the Gershgorin-based lower bound -0.01 B: no NaN, an error
  Eigen::SparseMatrix<double> unstable(2, 2);
  unstable.insert(0, 0) = 1.0;
  unstable.insert(0, 1) = 2.0;
  unstable.insert(1, 0) = 2.0;
  unstable.insert(1, 1) = 1.0;    // eigenvalues 3 and -1, bound B = 3
  options = KpmOptions();
  options.moments = 200;
  EXPECT_THROW(kpm_frequency_histogram(DynamicalMatrix(unstable, Eigen::VectorXd::Ones(2), {}, 1), 4, 0.0, 1.0,
                                       options),
               SolverError);
}
