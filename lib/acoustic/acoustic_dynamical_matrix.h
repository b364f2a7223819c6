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
   ACOUSTIC package numerics: mass-weighted stiffness of the free DOFs.

   The vibration modes solve K v = omega^2 M v on the free DOFs (those not in
   the fixed set).  M is diagonal and positive, so with y = M^(1/2) v this
   is the standard symmetric problem D y = lambda y with
     D = M_FF^(-1/2) K_FF M_FF^(-1/2),   lambda = omega^2.
   The DOFs must be stored grain by grain (dofs_per_grain consecutive DOFs
   per grain, as in ContactNetwork), which defines the per-grain weights of
   the participation ratio.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_DYNAMICAL_MATRIX_H
#define ACOUSTIC_DYNAMICAL_MATRIX_H

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace Acoustic {

class DynamicalMatrix {
 public:
  // stiffness: symmetric, num_dofs x num_dofs; mass: positive diagonal of M;
  // fixed_dofs: DOFs held at zero (duplicates allowed).  Throws SolverError.
  DynamicalMatrix(const Eigen::SparseMatrix<double> &stiffness, const Eigen::VectorXd &mass,
                  const std::vector<int> &fixed_dofs, int dofs_per_grain);

  // D (num_free x num_free), full symmetric storage.
  const Eigen::SparseMatrix<double> &matrix() const { return matrix_; }
  int num_free() const { return static_cast<int>(free_dofs_.size()); }
  int num_dofs() const { return num_dofs_; }
  int dofs_per_grain() const { return dofs_per_grain_; }
  // DOF index of each free DOF, ascending.
  const std::vector<int> &free_dofs() const { return free_dofs_; }

  // Upper bound of the spectrum of D (Gershgorin: max_i sum_j |D_ij|);
  // the scale of the zero-mode tolerance.
  double spectrum_upper_bound() const { return upper_bound_; }

  // Free DOFs (indices into 0..num_free-1) whose row of D is zero: each is
  // an exact zero mode decoupled from the rest (e.g. a rattler's DOFs).
  std::vector<int> decoupled_free_dofs() const;

  // Mode vector in DOF space, v = M^(-1/2) y on the free DOFs, 0 on fixed
  // DOFs; a unit y gives a mass-normalised v (v^T M v = 1).
  Eigen::VectorXd to_dof_space(const Eigen::VectorXd &y) const;

  // Participation ratio of a mode y (unit or not):
  //   PR = (sum_g w_g)^2 / (N sum_g w_g^2),  w_g = sum of y_k^2 over grain g's free DOFs,
  // i.e. w_g is the grain's share of the mode's kinetic energy (m v^2 summed
  // over its DOFs) and N the number of grains with at least one free DOF.
  // PR = 1 when every grain moves with the same energy, ~1/N for one grain.
  double participation_ratio(const Eigen::VectorXd &y) const;

 private:
  int num_dofs_;
  int dofs_per_grain_;
  int num_active_grains_;
  std::vector<int> free_dofs_;
  Eigen::VectorXd inv_sqrt_mass_;    // of the free DOFs
  Eigen::SparseMatrix<double> matrix_;
  double upper_bound_;
};

}    // namespace Acoustic

#endif
