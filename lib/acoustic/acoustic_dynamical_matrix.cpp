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
   ACOUSTIC package numerics: mass-weighted stiffness of the free DOFs.
------------------------------------------------------------------------- */

#include "acoustic_dynamical_matrix.h"

#include "acoustic_solver_error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace Acoustic {

DynamicalMatrix::DynamicalMatrix(const Eigen::SparseMatrix<double> &stiffness,
                                 const Eigen::VectorXd &mass, const std::vector<int> &fixed_dofs,
                                 int dofs_per_grain) :
    num_dofs_(static_cast<int>(stiffness.rows())),
    dofs_per_grain_(dofs_per_grain), num_active_grains_(0), upper_bound_(0.0)
{
  if (stiffness.cols() != stiffness.rows())
    throw SolverError("vibration modes: the stiffness matrix is not square");
  if (mass.size() != num_dofs_)
    throw SolverError("vibration modes: the mass vector must have one entry per DOF");
  if (!(mass.array() > 0.0).all() || !mass.allFinite())
    throw SolverError("vibration modes: every mass must be positive and finite");
  if (dofs_per_grain < 1 || num_dofs_ % dofs_per_grain != 0)
    throw SolverError(
        "vibration modes: the number of DOFs is not a multiple of the DOFs per grain");

  std::vector<int> free_index(num_dofs_, 0);
  for (int dof : fixed_dofs) {
    if (dof < 0 || dof >= num_dofs_)
      throw SolverError("vibration modes: fixed DOF " + std::to_string(dof) + " is outside 0.." +
                        std::to_string(num_dofs_ - 1));
    free_index[dof] = -1;
  }
  for (int dof = 0; dof < num_dofs_; ++dof) {
    if (free_index[dof] < 0) continue;
    free_index[dof] = static_cast<int>(free_dofs_.size());
    free_dofs_.push_back(dof);
  }
  const int nfree = num_free();

  inv_sqrt_mass_.resize(nfree);
  for (int k = 0; k < nfree; ++k) inv_sqrt_mass_[k] = 1.0 / std::sqrt(mass[free_dofs_[k]]);

  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(stiffness.nonZeros());
  for (int col = 0; col < stiffness.outerSize(); ++col) {
    const int fc = free_index[col];
    if (fc < 0) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(stiffness, col); it; ++it) {
      const int fr = free_index[it.row()];
      if (fr >= 0)
        triplets.emplace_back(fr, fc, it.value() * inv_sqrt_mass_[fr] * inv_sqrt_mass_[fc]);
    }
  }
  matrix_.resize(nfree, nfree);
  matrix_.setFromTriplets(triplets.begin(), triplets.end());
  matrix_.makeCompressed();
  if (!Eigen::Map<const Eigen::VectorXd>(matrix_.valuePtr(), matrix_.nonZeros()).allFinite())
    throw SolverError("vibration modes: the stiffness matrix holds NaN or Inf");

  for (int col = 0; col < nfree; ++col) {
    double row_sum = 0.0;    // D is symmetric: column sums are row sums
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix_, col); it; ++it)
      row_sum += std::abs(it.value());
    upper_bound_ = std::max(upper_bound_, row_sum);
  }

  int last_grain = -1;
  for (int dof : free_dofs_) {
    if (dof / dofs_per_grain_ != last_grain) ++num_active_grains_;
    last_grain = dof / dofs_per_grain_;
  }
}

std::vector<int> DynamicalMatrix::decoupled_free_dofs() const
{
  std::vector<int> decoupled;
  for (int col = 0; col < matrix_.outerSize(); ++col) {
    bool zero = true;
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix_, col); it; ++it)
      if (it.value() != 0.0) zero = false;
    if (zero) decoupled.push_back(col);
  }
  return decoupled;
}

Eigen::VectorXd DynamicalMatrix::to_dof_space(const Eigen::VectorXd &y) const
{
  if (y.size() != num_free())
    throw SolverError("vibration modes: a mode vector must have one entry per free DOF");
  Eigen::VectorXd v = Eigen::VectorXd::Zero(num_dofs_);
  for (int k = 0; k < num_free(); ++k) v[free_dofs_[k]] = y[k] * inv_sqrt_mass_[k];
  return v;
}

double DynamicalMatrix::participation_ratio(const Eigen::VectorXd &y) const
{
  if (y.size() != num_free())
    throw SolverError("vibration modes: a mode vector must have one entry per free DOF");
  double sum = 0.0;
  double sum_squares = 0.0;
  double grain_weight = 0.0;
  int last_grain = -1;
  for (int k = 0; k < num_free(); ++k) {
    const int grain = free_dofs_[k] / dofs_per_grain_;
    if (grain != last_grain) {
      sum_squares += grain_weight * grain_weight;
      grain_weight = 0.0;
      last_grain = grain;
    }
    grain_weight += y[k] * y[k];
    sum += y[k] * y[k];
  }
  sum_squares += grain_weight * grain_weight;
  if (sum_squares == 0.0) return 0.0;
  return sum * sum / (num_active_grains_ * sum_squares);
}

}    // namespace Acoustic
