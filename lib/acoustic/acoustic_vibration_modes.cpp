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
   ACOUSTIC package numerics: eigenmodes K v = omega^2 M v of a network.
------------------------------------------------------------------------- */

#include "acoustic_vibration_modes.h"

#include "acoustic_solver_error.h"

#include <Eigen/CholmodSupport>
#include <Eigen/Eigenvalues>
#ifdef ACOUSTIC_HAVE_SPECTRA
#include <Spectra/SymEigsShiftSolver.h>
#endif

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace Acoustic {

namespace {

  const double two_pi = 6.283185307179586476925287;
  const int max_dense_dofs = 20000;
  const double lanczos_shift_fraction = 1e-6;    // shift = -fraction * spectrum bound
  const double lanczos_tolerance = 1e-12;        // Spectra's relative convergence tolerance
  const int lanczos_max_restarts = 1000;
  const int lanczos_min_size = 40;    // smaller reduced problems are solved dense
  const char lanczos_missing[] =
      "vibration modes: method lanczos needs an ACOUSTIC package built with "
      "Spectra (Debian: libspectra-dev; CMake: ACOUSTIC_WITH_SPECTRA=on); "
      "use method dense or kpm";

  double frequency_of(double eigenvalue)
  {
    return std::sqrt(std::max(eigenvalue, 0.0)) / two_pi;
  }

  void check_semi_definite(double lowest_eigenvalue, double zero_threshold)
  {
    if (lowest_eigenvalue < -zero_threshold)
      throw SolverError("vibration modes: the stiffness matrix has a negative eigenvalue " +
                        std::to_string(lowest_eigenvalue) +
                        " (a contact with negative stiffness?); the network is not stable");
  }

#ifdef ACOUSTIC_HAVE_SPECTRA
  // y -> (D - sigma I)^(-1) y for Spectra, by a sparse Cholesky factorisation
  // (D - sigma I is positive definite for sigma < 0 and D positive semi-definite).
  class ShiftInvertOperator {
   public:
    using Scalar = double;
    explicit ShiftInvertOperator(const Eigen::SparseMatrix<double> &d) : d_(d)
    {
      llt_.cholmod().print = 0;
    }
    Eigen::Index rows() const { return d_.rows(); }
    Eigen::Index cols() const { return d_.cols(); }
    void set_shift(double sigma)
    {
      Eigen::SparseMatrix<double> identity(d_.rows(), d_.cols());
      identity.setIdentity();
      const Eigen::SparseMatrix<double> shifted = d_ - sigma * identity;
      llt_.compute(shifted);
      if (llt_.info() != Eigen::Success)
        throw SolverError(
            "vibration modes (lanczos): the shifted stiffness matrix is not positive definite: "
            "the network has a negative eigenvalue (a contact with negative stiffness?)");
    }
    void perform_op(const double *x_in, double *y_out) const
    {
      Eigen::Map<const Eigen::VectorXd> x(x_in, d_.rows());
      Eigen::Map<Eigen::VectorXd> y(y_out, d_.rows());
      y = llt_.solve(x);
    }

   private:
    const Eigen::SparseMatrix<double> &d_;
    Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> llt_;
  };

#endif

  // Submatrix of d on the given (ascending) indices.
  Eigen::SparseMatrix<double> principal_submatrix(const Eigen::SparseMatrix<double> &d,
                                                  const std::vector<int> &keep)
  {
    std::vector<int> index(d.rows(), -1);
    for (std::size_t k = 0; k < keep.size(); ++k) index[keep[k]] = static_cast<int>(k);
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(d.nonZeros());
    for (int col = 0; col < d.outerSize(); ++col) {
      if (index[col] < 0) continue;
      for (Eigen::SparseMatrix<double>::InnerIterator it(d, col); it; ++it)
        if (index[it.row()] >= 0) triplets.emplace_back(index[it.row()], index[col], it.value());
    }
    Eigen::SparseMatrix<double> sub(keep.size(), keep.size());
    sub.setFromTriplets(triplets.begin(), triplets.end());
    sub.makeCompressed();
    return sub;
  }

  // Lowest `count` eigenpairs of the symmetric positive semi-definite d, ascending.
  void lowest_eigenpairs(const Eigen::SparseMatrix<double> &d, int count, double shift,
                         Eigen::VectorXd &values, Eigen::MatrixXd &vectors)
  {
    const int n = static_cast<int>(d.rows());
    if (n <= lanczos_min_size || count >= n - 1) {
      const Eigen::MatrixXd dense_d(d);
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> dense(dense_d);
      values = dense.eigenvalues().head(count);
      vectors = dense.eigenvectors().leftCols(count);
      return;
    }
#ifndef ACOUSTIC_HAVE_SPECTRA
    (void) shift;
    throw SolverError(lanczos_missing);
#else
    ShiftInvertOperator op(d);
    const int ncv = std::min(n, std::max(2 * count + 1, count + 20));
    Spectra::SymEigsShiftSolver<ShiftInvertOperator> eigs(op, count, ncv, shift);
    eigs.init();
    eigs.compute(Spectra::SortRule::LargestMagn, lanczos_max_restarts, lanczos_tolerance,
                 Spectra::SortRule::SmallestAlge);
    if (eigs.info() != Spectra::CompInfo::Successful)
      throw SolverError("vibration modes (lanczos): the Lanczos iteration did not converge for " +
                        std::to_string(count) + " modes of " + std::to_string(n) +
                        " DOFs; ask for fewer modes or use method dense");
    values = eigs.eigenvalues();
    vectors = eigs.eigenvectors();
#endif
  }

}    // namespace

bool lanczos_available()
{
#ifdef ACOUSTIC_HAVE_SPECTRA
  return true;
#else
  return false;
#endif
}

ModeMethod mode_method_from_name(const std::string &name)
{
  if (name == "dense") return ModeMethod::Dense;
  if (name == "lanczos") {
    if (!lanczos_available()) throw SolverError(lanczos_missing);
    return ModeMethod::Lanczos;
  }
  if (name == "kpm") return ModeMethod::Kpm;
  throw SolverError("unknown vibration mode method '" + name +
                    "': allowed methods are dense, lanczos, kpm");
}

std::string mode_method_name(ModeMethod method)
{
  switch (method) {
    case ModeMethod::Lanczos:
      return "lanczos";
    case ModeMethod::Kpm:
      return "kpm";
    default:
      return "dense";
  }
}

VibrationModes dense_vibration_modes(const DynamicalMatrix &dynamical, bool with_shapes,
                                     double zero_tolerance)
{
  const int n = dynamical.num_free();
  if (n > max_dense_dofs)
    throw SolverError("vibration modes (dense): " + std::to_string(n) +
                      " free DOFs is too many for a dense "
                      "eigensolver (limit " +
                      std::to_string(max_dense_dofs) + "); use method lanczos or kpm");
  VibrationModes modes;
  if (n == 0) return modes;
  const double zero_threshold = zero_tolerance * dynamical.spectrum_upper_bound();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(Eigen::MatrixXd(dynamical.matrix()),
                                                        with_shapes ? Eigen::ComputeEigenvectors
                                                                    : Eigen::EigenvaluesOnly);
  if (solver.info() != Eigen::Success)
    throw SolverError("vibration modes (dense): the dense eigensolver did not converge");
  modes.eigenvalues = solver.eigenvalues();
  check_semi_definite(modes.eigenvalues[0], zero_threshold);
  modes.frequencies = modes.eigenvalues.unaryExpr(&frequency_of);
  for (int k = 0; k < n; ++k)
    if (std::abs(modes.eigenvalues[k]) <= zero_threshold) ++modes.zero_modes;
  if (with_shapes) {
    modes.shapes.resize(dynamical.num_dofs(), n);
    modes.participation_ratios.resize(n);
    for (int k = 0; k < n; ++k) {
      modes.shapes.col(k) = dynamical.to_dof_space(solver.eigenvectors().col(k));
      modes.participation_ratios[k] = dynamical.participation_ratio(solver.eigenvectors().col(k));
    }
  }
  return modes;
}

VibrationModes lanczos_vibration_modes(const DynamicalMatrix &dynamical, int num_modes,
                                       double zero_tolerance)
{
  if (num_modes < 1)
    throw SolverError("vibration modes (lanczos): the number of modes must be >= 1, got " +
                      std::to_string(num_modes));
  VibrationModes modes;
  const double bound = dynamical.spectrum_upper_bound();
  const double zero_threshold = zero_tolerance * bound;

  // DOFs without any stiffness are exact, decoupled zero modes: count them and drop them.
  const std::vector<int> decoupled = dynamical.decoupled_free_dofs();
  std::vector<char> is_decoupled(dynamical.num_free(), 0);
  for (int k : decoupled) is_decoupled[k] = 1;
  std::vector<int> coupled;
  for (int k = 0; k < dynamical.num_free(); ++k)
    if (!is_decoupled[k]) coupled.push_back(k);
  modes.zero_modes = static_cast<int>(decoupled.size());
  const int n = static_cast<int>(coupled.size());
  if (n == 0) return modes;
  const Eigen::SparseMatrix<double> d = principal_submatrix(dynamical.matrix(), coupled);

  // Ask for more modes until num_modes non-zero ones are found (zero modes come first).
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  int requested = std::min(num_modes, n);
  int zeros = 0;
  while (true) {
    lowest_eigenpairs(d, requested, -lanczos_shift_fraction * bound, values, vectors);
    check_semi_definite(values[0], zero_threshold);
    zeros = 0;
    while (zeros < requested && values[zeros] <= zero_threshold) ++zeros;
    if (requested - zeros >= num_modes || requested == n) break;
    requested = (zeros == requested) ? std::min(n, 2 * requested) : std::min(n, num_modes + zeros);
  }
  modes.zero_modes += zeros;

  const int found = std::min(num_modes, requested - zeros);
  modes.eigenvalues = values.segment(zeros, found);
  modes.frequencies = modes.eigenvalues.unaryExpr(&frequency_of);
  modes.shapes.resize(dynamical.num_dofs(), found);
  modes.participation_ratios.resize(found);
  Eigen::VectorXd y(dynamical.num_free());
  for (int k = 0; k < found; ++k) {
    y.setZero();
    for (int r = 0; r < n; ++r) y[coupled[r]] = vectors(r, zeros + k);
    y.normalize();
    modes.shapes.col(k) = dynamical.to_dof_space(y);
    modes.participation_ratios[k] = dynamical.participation_ratio(y);
  }
  return modes;
}

}    // namespace Acoustic
