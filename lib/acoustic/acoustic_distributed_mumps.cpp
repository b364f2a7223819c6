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
   ACOUSTIC package numerics: MUMPS on a distributed network.
------------------------------------------------------------------------- */

#include "acoustic_distributed_mumps.h"

#include <chrono>
#include <cmath>

namespace Acoustic {

namespace {

  using Complex = std::complex<double>;
  using Clock = std::chrono::steady_clock;

  double seconds_since(Clock::time_point start)
  {
    return std::chrono::duration<double>(Clock::now() - start).count();
  }

  template <typename Scalar> Scalar as_scalar(const Complex &v);
  template <> double as_scalar<double>(const Complex &v)
  {
    return v.real();
  }
  template <> Complex as_scalar<Complex>(const Complex &v)
  {
    return v;
  }

  // the unknowns' values of every rank on rank 0, in the global numbering
  std::vector<Complex> gather_to_host(const std::vector<Complex> &mine, long total, MPI_Comm comm)
  {
    int nprocs = 1, rank = 0;
    MPI_Comm_size(comm, &nprocs);
    MPI_Comm_rank(comm, &rank);
    int count = 2 * static_cast<int>(mine.size());
    std::vector<int> counts(nprocs), displs(nprocs, 0);
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
    for (int p = 1; p < nprocs; ++p) displs[p] = displs[p - 1] + counts[p - 1];
    std::vector<Complex> all(rank == 0 ? total : 0);
    MPI_Gatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                MPI_DOUBLE, 0, comm);
    return all;
  }

  // back from rank 0 to the owners of the unknowns
  std::vector<Complex> scatter_from_host(const std::vector<Complex> &all, int mine, MPI_Comm comm)
  {
    int nprocs = 1;
    MPI_Comm_size(comm, &nprocs);
    int count = 2 * mine;
    std::vector<int> counts(nprocs), displs(nprocs, 0);
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
    for (int p = 1; p < nprocs; ++p) displs[p] = displs[p - 1] + counts[p - 1];
    std::vector<Complex> part(mine);
    MPI_Scatterv(all.data(), counts.data(), displs.data(), MPI_DOUBLE, part.data(), count,
                 MPI_DOUBLE, 0, comm);
    return part;
  }

}    // namespace

DistributedMumpsSolver::DistributedMumpsSolver(MPI_Comm comm, const MumpsSettings &settings,
                                               double residual_tolerance) :
    comm_(comm),
    tolerance_(residual_tolerance), team_(comm), real_(team_, settings), complex_(team_, settings)
{
}

DistributedMumpsSolver::~DistributedMumpsSolver() = default;

// analyse if the pattern changed on any rank, then factorise
template <typename Scalar>
bool DistributedMumpsSolver::factorise(MumpsLdlt<Scalar> &mumps, long n,
                                       const std::vector<long> &rows, const std::vector<long> &cols,
                                       const std::vector<Complex> &values,
                                       std::vector<long> &last_rows, std::vector<long> &last_cols,
                                       long &last_n)
{
  std::vector<Scalar> entries(values.size());
  for (std::size_t k = 0; k < values.size(); ++k) entries[k] = as_scalar<Scalar>(values[k]);
  int changed = (n != last_n || rows != last_rows || cols != last_cols) ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &changed, 1, MPI_INT, MPI_MAX, comm_);
  Clock::time_point start = Clock::now();
  if (changed) {
    mumps.analyze_distributed(n, rows, cols, entries);
    timings_.analysis += seconds_since(start);
    ++num_analyses_;
    if (mumps.info() != Eigen::Success) {
      last_n = -1;
      return false;
    }
    last_rows = rows;
    last_cols = cols;
    last_n = n;
    start = Clock::now();
  }
  mumps.factorize_distributed(entries);
  ++num_factorisations_;
  timings_.factorisation += seconds_since(start);
  flops_ = mumps.factorisation_flops();
  return mumps.info() == Eigen::Success;
}

HelmholtzSolution DistributedMumpsSolver::solve(const DistributedHelmholtzProblem &problem,
                                                HaloExchange &halo,
                                                const Eigen::VectorXcd *last_solution)
{
  timings_ = SolverTimings();
  Clock::time_point start = Clock::now();
  DistributedSystem system(problem, halo, comm_);
  const int n = system.num_unknowns();
  HelmholtzSolution result;
  result.factorisation = "mumps (distributed input)";
  std::vector<Complex> x(n, Complex(0.0));
  double residual = 0.0;
  if (system.num_global_unknowns() == 0 || system.rhs_norm() == 0.0) {
    result.q = system.local_solution(x);
    return result;
  }
  // the last solution may still solve this system
  if (last_solution && last_solution->size() == system.num_dofs()) {
    for (int k = 0; k < n; ++k) x[k] = (*last_solution)[system.unknowns()[k]];
    residual = system.relative_residual(x);
    if (residual <= 1e-2 * tolerance_) {
      ++num_reuses_;
      result.factorisation += " (earlier solution)";
      result.q = system.local_solution(x);
      result.relative_residual = residual;
      return result;
    }
  }

  std::vector<long> rows, cols;
  std::vector<Complex> values;
  system.global_entries(0.0, true, rows, cols, values);
  int damped = 0;
  for (const Complex &v : values) damped = damped || v.imag() != 0.0;
  MPI_Allreduce(MPI_IN_PLACE, &damped, 1, MPI_INT, MPI_MAX, comm_);
  timings_.solve += seconds_since(start);
  const long total = system.num_global_unknowns();
  const bool factorised = damped
      ? factorise(complex_, total, rows, cols, values, complex_rows_, complex_cols_, complex_n_)
      : factorise(real_, total, rows, cols, values, real_rows_, real_cols_, real_n_);
  start = Clock::now();
  if (!factorised) {
    for (Complex &v : x) v = 0.0;
    result.status = SolveStatus::FactorisationFailed;
    result.message =
        "the Helmholtz matrix is singular: the frequency is an eigenfrequency of the network; "
        "change the frequency or add damping [" +
        (damped ? complex_.message() : real_.message()) + "]";
    result.relative_residual = 1.0;
    result.q = system.local_solution(x);
    return result;
  }
  std::vector<Complex> all = gather_to_host(system.right_hand_side(), total, comm_);
  if (damped) {
    Eigen::MatrixXcd b =
        Eigen::Map<Eigen::VectorXcd>(all.data(), static_cast<Eigen::Index>(all.size()));
    complex_.solve_distributed(b);
    for (std::size_t k = 0; k < all.size(); ++k) all[k] = b(k, 0);
  } else {
    // the real factors solve for the real and the imaginary parts
    Eigen::MatrixXd b(static_cast<Eigen::Index>(all.size()), 2);
    for (std::size_t k = 0; k < all.size(); ++k) {
      b(k, 0) = all[k].real();
      b(k, 1) = all[k].imag();
    }
    real_.solve_distributed(b);
    for (std::size_t k = 0; k < all.size(); ++k) all[k] = Complex(b(k, 0), b(k, 1));
  }
  x = scatter_from_host(all, n, comm_);
  residual = system.relative_residual(x);
  timings_.solve += seconds_since(start);
  if (!std::isfinite(residual)) {
    for (Complex &v : x) v = 0.0;
    residual = 1.0;
    result.status = SolveStatus::InaccurateSolution;
    result.message = "the Helmholtz solution is not finite: the matrix is numerically singular";
  } else if (residual > tolerance_) {
    result.status = SolveStatus::InaccurateSolution;
    result.message = "the relative residual " + std::to_string(residual) +
        " exceeds the tolerance: the frequency is close to an eigenfrequency of the network";
  }
  result.q = system.local_solution(x);
  result.relative_residual = residual;
  return result;
}

}    // namespace Acoustic
