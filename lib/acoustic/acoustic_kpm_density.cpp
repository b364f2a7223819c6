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
   ACOUSTIC package numerics: density of vibrational states by the kernel
   polynomial method.
------------------------------------------------------------------------- */

#include "acoustic_kpm_density.h"

#include "acoustic_solver_error.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace Acoustic {

namespace {

  const double pi = 3.14159265358979323846264;
  const int vectors_per_block =
      8;    // random vectors propagated together (sparse x dense block products)

  // Jackson kernel coefficients g_0 .. g_{M-1}.
  Eigen::VectorXd jackson_kernel(int moments)
  {
    Eigen::VectorXd g(moments);
    const double q = pi / (moments + 1);
    for (int m = 0; m < moments; ++m)
      g[m] = ((moments - m + 1) * std::cos(q * m) + std::sin(q * m) / std::tan(q)) / (moments + 1);
    return g;
  }

  // Chebyshev moments (rows) of each random vector (columns), normalised by n.
  Eigen::MatrixXd stochastic_moments(const Eigen::SparseMatrix<double> &d, double centre,
                                     double half_width, const KpmOptions &options)
  {
    const Eigen::Index n = d.rows();
    const int moments = options.moments;
    Eigen::MatrixXd mu(moments, options.random_vectors);
    std::mt19937_64 generator(options.seed);
    std::bernoulli_distribution coin(0.5);

    // D~ = (D - centre I) / half_width, row-major so that products with a row-major block of
    // vectors read contiguous memory
    Eigen::SparseMatrix<double> identity(n, n);
    identity.setIdentity();
    const Eigen::SparseMatrix<double, Eigen::RowMajor> scaled =
        (d - centre * identity) / half_width;
    // fixed block width: the inner loops of the sparse x block product are unrolled and vectorised;
    // in the last block, columns beyond the requested vectors stay 0 and are not used
    typedef Eigen::Matrix<double, Eigen::Dynamic, vectors_per_block, Eigen::RowMajor> Block;

    for (int first = 0; first < options.random_vectors; first += vectors_per_block) {
      const int nb = std::min(vectors_per_block, options.random_vectors - first);
      Block previous = Block::Zero(n, vectors_per_block), current(n, vectors_per_block),
            next(n, vectors_per_block);
      for (int c = 0; c < nb; ++c)
        for (Eigen::Index k = 0; k < n; ++k) previous(k, c) = coin(generator) ? 1.0 : -1.0;
      current.noalias() = scaled * previous;    // T_0 r = r, T_1 r = D~ r
      const Eigen::RowVectorXd mu0 = previous.colwise().squaredNorm();
      const Eigen::RowVectorXd mu1 = (previous.array() * current.array()).colwise().sum().matrix();
      mu.block(0, first, 1, nb) = mu0.head(nb);
      mu.block(1, first, 1, nb) = mu1.head(nb);    // moments >= 2
      // mu_2m = 2 <T_m r, T_m r> - mu_0,  mu_2m+1 = 2 <T_m+1 r, T_m r> - mu_1
      for (int m = 1; 2 * m < moments; ++m) {
        mu.block(2 * m, first, 1, nb) = (2.0 * current.colwise().squaredNorm() - mu0).head(nb);
        if (2 * m + 1 >= moments) break;
        next.noalias() = scaled * current;
        next = 2.0 * next - previous;
        mu.block(2 * m + 1, first, 1, nb) =
            (2.0 * (next.array() * current.array()).colwise().sum().matrix() - mu1).head(nb);
        previous.swap(current);
        current.swap(next);
      }
    }
    return mu / static_cast<double>(n);
  }

  // Fraction of eigenvalues below x (in [-1, 1]) from damped moments gmu.
  double cumulative_fraction(const Eigen::VectorXd &gmu, double x)
  {
    const double t = std::acos(std::min(1.0, std::max(-1.0, x)));
    double sum = gmu[0] * (1.0 - t / pi);
    for (Eigen::Index m = 1; m < gmu.size(); ++m) sum -= 2.0 / pi * gmu[m] * std::sin(m * t) / m;
    return sum;
  }

}    // namespace

FrequencyHistogram kpm_frequency_histogram(const DynamicalMatrix &dynamical, int nbins, double fmin,
                                           double fmax, const KpmOptions &options)
{
  check_histogram_range(nbins, fmin, fmax);
  if (options.moments < 2)
    throw SolverError("vibration modes (kpm): the number of moments must be >= 2, got " +
                      std::to_string(options.moments));
  if (options.random_vectors < 2)
    throw SolverError("vibration modes (kpm): the number of random vectors must be >= 2, got " +
                      std::to_string(options.random_vectors));
  const int n = dynamical.num_free();
  const double bound = dynamical.spectrum_upper_bound();
  if (n == 0 || bound == 0.0)    // no DOF, or no stiffness: every mode is at f = 0
    return frequency_histogram(Eigen::VectorXd::Zero(n), nbins, fmin, fmax);

  const double lower = -0.01 * bound;
  const double upper = 1.01 * bound;
  const double centre = 0.5 * (upper + lower);
  const double half_width = 0.5 * (upper - lower);
  const Eigen::MatrixXd mu = stochastic_moments(dynamical.matrix(), centre, half_width, options);
  // |mu_m| <= 1 for a spectrum inside the bounds (up to the stochastic error); growth means it is
  // not
  if (!mu.allFinite() || mu.cwiseAbs().maxCoeff() > 10.0)
    throw SolverError(
        "vibration modes (kpm): the spectrum lies outside [0, Gershgorin bound]: the stiffness "
        "matrix has a negative eigenvalue (a contact with negative stiffness?)");
  const Eigen::VectorXd kernel = jackson_kernel(options.moments);

  // fraction of eigenvalues in each bin, for each random vector
  FrequencyHistogram hist = frequency_histogram(Eigen::VectorXd(), nbins, fmin, fmax);
  const int nvec = options.random_vectors;
  Eigen::MatrixXd fractions(nbins, nvec);
  for (int r = 0; r < nvec; ++r) {
    const Eigen::VectorXd gmu = kernel.cwiseProduct(mu.col(r));
    double below = 0.0;
    for (int b = 0; b <= nbins; ++b) {
      // a range starting at f = 0 starts at the lower end of the mapped spectrum: the kernel
      // spreads the peak of the zero modes to both sides of lambda = 0
      const double omega = 2.0 * pi * (fmin + b * hist.bin_width);
      const double x = (b == 0 && fmin == 0.0) ? -1.0 : (omega * omega - centre) / half_width;
      const double cumulative = cumulative_fraction(gmu, x);
      if (b > 0) fractions(b - 1, r) = cumulative - below;
      below = cumulative;
    }
  }
  const Eigen::VectorXd mean = fractions.rowwise().mean();
  const double in_range = mean.sum();
  if (!(in_range > 0.0)) return hist;    // no state in [fmin, fmax]
  hist.counted = in_range * n;
  const double scale = 1.0 / (in_range * hist.bin_width);
  hist.density = mean * scale;
  const Eigen::MatrixXd deviations = (fractions.colwise() - mean) * scale;
  hist.density_error = (deviations.rowwise().squaredNorm() / (nvec * (nvec - 1.0))).cwiseSqrt();
  return hist;
}

}    // namespace Acoustic
