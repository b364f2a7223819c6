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
   ACOUSTIC package numerics: the Helmholtz system of a network distributed
   over MPI ranks.
------------------------------------------------------------------------- */

#include "acoustic_distributed_system.h"

#include "acoustic_solver_error.h"

#include <cmath>
#include <limits>

namespace Acoustic {

namespace {

  using Complex = std::complex<double>;

  std::string check_problem(const DistributedHelmholtzProblem &p)
  {
    if (!p.network) return "distributed Helmholtz solve: no network";
    const ContactNetwork &net = *p.network;
    if (p.num_owned < 0 || p.num_owned > net.num_grains())
      return "distributed Helmholtz solve: num_owned is outside 0.." +
          std::to_string(net.num_grains());
    if (!std::isfinite(p.omega) || p.omega < 0.0)
      return "distributed Helmholtz solve: the angular frequency must be >= 0 and finite";
    if (p.prescribed_values.size() != static_cast<Eigen::Index>(p.prescribed_dofs.size()))
      return "distributed Helmholtz solve: give one prescribed value per prescribed DOF";
    if (!p.prescribed_values.allFinite())
      return "distributed Helmholtz solve: a prescribed value is not finite";
    std::vector<char> seen(net.num_dofs(), 0);
    for (int dof : p.prescribed_dofs) {
      if (dof < 0 || dof >= net.num_dofs())
        return "distributed Helmholtz solve: prescribed DOF " + std::to_string(dof) +
            " is outside the network";
      if (seen[dof])
        return "distributed Helmholtz solve: DOF " + std::to_string(dof) + " is prescribed twice";
      seen[dof] = 1;
    }
    return "";
  }

  // every rank throws if any rank found the input invalid (a collective call
  // must not leave ranks behind)
  void agree_on_validity(MPI_Comm comm, const std::string &local_problem)
  {
    int bad = local_problem.empty() ? 0 : 1, any_bad = 0;
    MPI_Allreduce(&bad, &any_bad, 1, MPI_INT, MPI_MAX, comm);
    if (bad) throw SolverError(local_problem);
    if (any_bad) throw SolverErrorElsewhere();
  }

}    // namespace

DistributedSystem::DistributedSystem(const DistributedHelmholtzProblem &p, HaloExchange &halo,
                                     MPI_Comm comm) :
    comm_(comm),
    halo_(halo), ndof_(0), num_dofs_(0), omega_(p.omega)
{
  agree_on_validity(comm, check_problem(p));
  const ContactNetwork &net = *p.network;
  ndof_ = net.dofs_per_grain();
  num_dofs_ = net.num_dofs();

  // K + i omega C on every local DOF, - omega^2 m on the owned ones: a
  // ghost's mass is counted by its owner
  Eigen::SparseMatrix<Complex> a = net.stiffness_matrix().cast<Complex>();
  if (net.has_damping() && omega_ > 0.0)
    a += Complex(0.0, omega_) * net.damping_matrix().cast<Complex>();
  const Eigen::VectorXd mass = net.mass_diagonal();
  Eigen::VectorXcd diagonal = Eigen::VectorXcd::Zero(num_dofs_);
  owned_mass_ = Eigen::VectorXd::Zero(num_dofs_);
  for (int k = 0; k < p.num_owned * ndof_; ++k) {
    diagonal[k] = -omega_ * omega_ * mass[k];
    owned_mass_[k] = mass[k];
  }
  a += Eigen::SparseMatrix<Complex>(diagonal.asDiagonal());
  matrix_ = std::move(a);
  matrix_.makeCompressed();

  prescribed_.assign(num_dofs_, 0);
  values_ = Eigen::VectorXcd::Zero(num_dofs_);
  for (std::size_t k = 0; k < p.prescribed_dofs.size(); ++k) {
    prescribed_[p.prescribed_dofs[k]] = 1;
    values_[p.prescribed_dofs[k]] = p.prescribed_values[k];
  }
  for (int dof = 0; dof < p.num_owned * ndof_; ++dof)
    if (!prescribed_[dof]) unknowns_.push_back(dof);
  in_.resize(num_dofs_);
  out_.resize(num_dofs_);

  // the global numbering: this rank's unknowns after those of the lower ranks
  long mine = num_unknowns();
  MPI_Exscan(&mine, &first_, 1, MPI_LONG, MPI_SUM, comm);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0) first_ = 0;
  MPI_Allreduce(&mine, &total_, 1, MPI_LONG, MPI_SUM, comm);
  int blocked = 1;
  for (std::size_t k = 0; k < unknowns_.size(); k += ndof_)
    if (k + ndof_ - 1 >= unknowns_.size() || unknowns_[k] % ndof_ != 0 ||
        unknowns_[k + ndof_ - 1] != unknowns_[k] + ndof_ - 1)
      blocked = 0;
  MPI_Allreduce(MPI_IN_PLACE, &blocked, 1, MPI_INT, MPI_MIN, comm);
  blocked_ = blocked != 0;

  // b = -A_FP q_P: the prescribed values (ghosts' from their owners) through A
  in_.setZero();
  for (int dof = 0; dof < num_dofs_; ++dof)
    if (prescribed_[dof]) in_[dof] = values_[dof];
  rhs_.resize(unknowns_.size());
  multiply_local(rhs_.data());
  double norm = 0.0;
  for (Complex &v : rhs_) {
    v = -v;
    norm += std::norm(v);
  }
  MPI_Allreduce(MPI_IN_PLACE, &norm, 1, MPI_DOUBLE, MPI_SUM, comm);
  rhs_norm_ = std::sqrt(norm);
  if (!std::isfinite(rhs_norm_))
    throw SolverError("distributed Helmholtz solve: the right-hand side is not finite");
}

void DistributedSystem::apply(const Complex *x, Complex *y)
{
  in_.setZero();
  for (std::size_t k = 0; k < unknowns_.size(); ++k) in_[unknowns_[k]] = x[k];
  multiply_local(y);
}

// out = A in on the unknowns, in_ holding the owned values: ghosts from their
// owners, local products, ghost rows back to their owners
void DistributedSystem::multiply_local(Complex *result)
{
  halo_.forward(in_.data(), ndof_);
  out_.noalias() = matrix_ * in_;
  halo_.reverse(out_.data(), ndof_);
  for (std::size_t k = 0; k < unknowns_.size(); ++k) result[k] = out_[unknowns_[k]];
}

double DistributedSystem::relative_residual(const std::vector<Complex> &x)
{
  std::vector<Complex> ax(x.size());
  apply(x.data(), ax.data());
  double local[2] = {0.0, 0.0}, global[2];
  for (std::size_t k = 0; k < x.size(); ++k) {
    local[0] += std::norm(rhs_[k] - ax[k]);
    if (!std::isfinite(x[k].real()) || !std::isfinite(x[k].imag())) local[1] = 1.0;
  }
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, comm_);
  const double residual = std::sqrt(global[0]) / rhs_norm_;
  return (global[1] > 0.0 || !std::isfinite(residual)) ? std::numeric_limits<double>::infinity()
                                                       : residual;
}

Eigen::VectorXcd DistributedSystem::local_solution(const std::vector<Complex> &x)
{
  Eigen::VectorXcd q = values_;
  for (std::size_t k = 0; k < unknowns_.size(); ++k) q[unknowns_[k]] = x[k];
  halo_.forward(q.data(), ndof_);
  return q;
}

void DistributedSystem::global_entries(double shift, bool lower, std::vector<long> &rows,
                                       std::vector<long> &cols, std::vector<Complex> &values)
{
  // the global index of each local DOF (ghosts from their owners), -1 if prescribed
  Eigen::VectorXcd index = Eigen::VectorXcd::Constant(num_dofs_, Complex(-1.0));
  for (std::size_t k = 0; k < unknowns_.size(); ++k)
    index[unknowns_[k]] = Complex(static_cast<double>(first_ + k));
  halo_.forward(index.data(), ndof_);
  std::vector<long> global(num_dofs_);
  for (int k = 0; k < num_dofs_; ++k)
    global[k] = prescribed_[k] ? -1 : std::lround(index[k].real());

  rows.clear();
  cols.clear();
  values.clear();
  rows.reserve(matrix_.nonZeros());
  cols.reserve(matrix_.nonZeros());
  values.reserve(matrix_.nonZeros());
  for (int col = 0; col < matrix_.outerSize(); ++col) {
    const long gcol = global[col];
    if (gcol < 0) continue;
    for (Eigen::SparseMatrix<Complex>::InnerIterator it(matrix_, col); it; ++it) {
      const long grow = global[it.row()];
      if (grow < 0 || (lower && grow < gcol)) continue;
      Complex value = it.value();
      if (it.row() == col && owned_mass_[col] > 0.0)
        value += Complex(0.0, shift * omega_ * omega_ * owned_mass_[col]);
      rows.push_back(grow);
      cols.push_back(gcol);
      values.push_back(value);
    }
  }
}

}    // namespace Acoustic
