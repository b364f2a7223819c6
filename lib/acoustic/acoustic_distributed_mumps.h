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
   ACOUSTIC package numerics: the Helmholtz problem of a distributed
   network factorised by MUMPS from distributed assembled input.

   Every rank passes the entries of its own contacts (DistributedSystem's
   global_entries, ICNTL(18) = 3): the matrix is never gathered.  MUMPS
   orders (its own choice: the graph is whole nowhere to order it with
   METIS), factorises and solves on all the ranks; the right-hand side is
   gathered to rank 0 and the solution sent back, O(n) numbers.  The
   analysis is kept while the pattern of every rank's entries stays the
   same.  Undamped systems are factorised in real arithmetic, damped ones
   in complex.  As with the other direct solvers, a solve whose relative
   residual exceeds the tolerance returns InaccurateSolution; a singular
   matrix FactorisationFailed, with q_F = 0.  MUMPS assembles the ranks'
   contributions in the order they arrive: not bitwise reproducible.
   Every function is collective over the communicator.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_DISTRIBUTED_MUMPS_H
#define ACOUSTIC_DISTRIBUTED_MUMPS_H

#include "acoustic_distributed_system.h"
#include "acoustic_helmholtz_solver.h"
#include "acoustic_mumps_ldlt.h"

#include <mpi.h>

#include <memory>
#include <vector>

namespace Acoustic {

class DistributedMumpsSolver {
 public:
  DistributedMumpsSolver(MPI_Comm comm, const MumpsSettings &settings,
                         double residual_tolerance = 1e-6);
  ~DistributedMumpsSolver();
  DistributedMumpsSolver(const DistributedMumpsSolver &) = delete;
  DistributedMumpsSolver &operator=(const DistributedMumpsSolver &) = delete;

  // q on every local DOF, as KrylovHelmholtzSolver::solve; last_solution:
  // nullptr, or the last solution per local DOF, taken if it still solves
  // the system to 1e-2 times the tolerance (reuse)
  HelmholtzSolution solve(const DistributedHelmholtzProblem &problem, HaloExchange &halo,
                          const Eigen::VectorXcd *last_solution = nullptr);

  long num_analyses() const { return num_analyses_; }
  long num_factorisations() const { return num_factorisations_; }
  long num_reuses() const { return num_reuses_; }
  const SolverTimings &last_timings() const { return timings_; }
  double last_factorisation_flops() const { return flops_; }

 private:
  MPI_Comm comm_;
  double tolerance_;
  MumpsTeam team_;
  MumpsLdlt<double> real_;
  MumpsLdlt<std::complex<double>> complex_;
  // this rank's pattern at the last analysis of each arithmetic
  std::vector<long> real_rows_, real_cols_, complex_rows_, complex_cols_;
  long real_n_ = -1, complex_n_ = -1;
  long num_analyses_ = 0, num_factorisations_ = 0, num_reuses_ = 0;
  double flops_ = 0.0;
  SolverTimings timings_;

  template <typename Scalar>
  bool factorise(MumpsLdlt<Scalar> &mumps, long n, const std::vector<long> &rows,
                 const std::vector<long> &cols, const std::vector<std::complex<double>> &values,
                 std::vector<long> &last_rows, std::vector<long> &last_cols, long &last_n);
};

}    // namespace Acoustic

#endif
