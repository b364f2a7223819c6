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
   ACOUSTIC package numerics: steady harmonic response (Helmholtz problem).

   Given K, C (may be empty or zero) and the diagonal of M, the angular
   frequency omega, and prescribed DOFs P with (complex) amplitudes q_P,
   solve for the free DOFs F
     (K_FF + i omega C_FF - omega^2 M_FF) q_F = -(K_FP + i omega C_FP) q_P.

   Factorisations ("solver" keyword of fix acoustic/mindlin):
     mumps sparse LDL^T with 1x1 and 2x2 pivots (MUMPS, multifrontal on
           BLAS), real symmetric or complex symmetric: the matrices above
           are symmetric and indefinite above the lowest eigenfrequency.
           Runs on every rank of the solver's communicator.
     lu    sparse LU with partial pivoting (UMFPACK), real or complex, on
           the host rank.
     ldlt  sparse LDL^T of the real symmetric matrix (CHOLMOD simplicial, no
           pivoting), on the host rank; undamped problems only.
     auto  mumps (fix acoustic/mindlin gives it MPI_COMM_SELF on rank 0:
           bitwise reproducible; solver mumps gets the whole world).
   The solver object keeps the symbolic analysis (fill-reducing ordering) of
   each factorisation and only refactorises numerically while the sparsity
   pattern of the free-free matrix stays the same; a new pattern is analysed
   again.  Counters and timings let the caller check this.

   Several ranks: construct the solver on every rank of the communicator
   (collective).  The host (rank 0) calls solve() with the matrices; the
   other ranks call serve() meanwhile, which returns when the host calls
   release_workers() after its solves.  With MPI_COMM_SELF (the default)
   serve() and release_workers() do nothing.  MPI must be initialised.

   Numerical failures do not throw: the returned status says what happened,
   relative_residual = ||A q_F - b|| / ||b|| is always reported, and the
   returned q never holds NaN or Inf (free DOFs are zero when the
   factorisation failed or the solution was not finite).  Invalid input
   (sizes, indices, negative omega, ldlt on a damped problem) throws
   SolverError.  omega = 0 with a part of the network not held by the
   prescribed DOFs is singular and returns FactorisationFailed.
   If b = 0 the solution is q_F = 0 with residual 0, without factorising.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_HELMHOLTZ_SOLVER_H
#define ACOUSTIC_HELMHOLTZ_SOLVER_H

#include <mpi.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>
#include <vector>

namespace Acoustic {

template <typename Scalar> class Factoriser;
class SparsityPattern;
struct MumpsSettings;

// Iterative: KrylovHelmholtzSolver on the distributed network (acoustic_krylov_solver.h);
// HelmholtzSolver takes the others
enum class LinearSolverChoice { Auto, Ldlt, Lu, Mumps, Iterative };

// "auto", "ldlt", "lu", "mumps" or "iterative"; throws SolverError listing the allowed names
// otherwise.
LinearSolverChoice linear_solver_from_name(const std::string &name);
std::string linear_solver_name(LinearSolverChoice choice);
// "auto, ldlt, lu, mumps, iterative": for help and error messages.
std::string linear_solver_names();

enum class SolveStatus {
  Success,                // residual below the tolerance
  FactorisationFailed,    // the matrix is (numerically) singular: q_F set to 0
  InaccurateSolution      // solved, but residual above the tolerance (or not finite: q_F set to 0)
};
std::string solve_status_name(SolveStatus status);

struct HelmholtzSolution {
  Eigen::VectorXcd q;    // every DOF, prescribed ones included
  SolveStatus status = SolveStatus::Success;
  double relative_residual = 0.0;    // ||A q_F - b|| / ||b||, of the factorisation used
  std::string factorisation;         // "ldlt", "lu", "mumps" or "none" (b = 0 or no free DOF), with
                                     // " (earlier factors, BiCGSTAB)" when they were reused
  std::string message;               // explanation when status != Success
  int iterations = 0;                // of an iterative solver (0 for the direct ones)
  bool ok() const { return status == SolveStatus::Success; }
};

// Wall time, in seconds, spent in the last call to solve().
struct SolverTimings {
  double analysis = 0.0;         // symbolic analysis (ordering)
  double factorisation = 0.0;    // numeric factorisation
  double solve = 0.0;            // assembly of A and b, triangular solves, residual
};

class HelmholtzSolver {
 public:
  // collective over comm; mumps: the ordering and low-rank settings of MUMPS
  explicit HelmholtzSolver(LinearSolverChoice choice = LinearSolverChoice::Auto,
                           double residual_tolerance = 1e-6, MPI_Comm comm = MPI_COMM_SELF);
  HelmholtzSolver(LinearSolverChoice choice, double residual_tolerance, MPI_Comm comm,
                  const MumpsSettings &mumps);
  ~HelmholtzSolver();
  HelmholtzSolver(const HelmholtzSolver &) = delete;
  HelmholtzSolver &operator=(const HelmholtzSolver &) = delete;

  // stiffness, damping: num_dofs x num_dofs (damping may also be 0 x 0);
  // mass: diagonal of M, positive; prescribed_dofs: distinct indices;
  // prescribed_values: their amplitudes, same length.
  HelmholtzSolution solve(const Eigen::SparseMatrix<double> &stiffness,
                          const Eigen::SparseMatrix<double> &damping, const Eigen::VectorXd &mass,
                          double omega, const std::vector<int> &prescribed_dofs,
                          const Eigen::VectorXcd &prescribed_values);

  // Ranks other than the host: take part in the host's factorisations and
  // solves until it calls release_workers().
  void serve();
  void release_workers();
  bool host() const;

  // Reuse of earlier work (off by default).  When the free DOFs are those of
  // the last successful solve:
  // - its solution is taken as it is if it solves the new system to
  //   1e-2 * residual_tolerance (the same network, or the same up to
  //   round-off): one product A x, no factorisation;
  // - otherwise, if at most changed_fraction of the columns (and no more than
  //   100) changed pattern (few contacts opened or closed), BiCGSTAB
  //   preconditioned with that solve's factorisation starts from its solution;
  //   the matrix is factorised if it does not converge within max_iterations,
  //   or has not brought the residual below 1e-2 after one iteration.  After a
  //   failed attempt the next 4 solves factorise directly, after consecutive
  //   failures 8, 16, ... 64 (the network changes too fast for the earlier
  //   factors); a success resets this.
  void set_reuse_factorisation(bool reuse, int max_iterations = 10, double changed_fraction = 0.01)
  {
    reuse_ = reuse;
    reuse_iterations_ = max_iterations;
    reuse_fraction_ = changed_fraction;
  }
  bool reuse_factorisation() const { return reuse_; }
  // solves answered without a factorisation, since construction: by the
  // earlier solution, or by BiCGSTAB with earlier factors
  long num_reuses() const { return num_reuses_; }

  LinearSolverChoice choice() const { return choice_; }
  double residual_tolerance() const { return residual_tolerance_; }
  // Totals since construction: symbolic analyses and numeric factorisations.
  long num_analyses() const { return num_analyses_; }
  long num_factorisations() const { return num_factorisations_; }
  const SolverTimings &last_timings() const { return timings_; }
  // floating-point operations of the last numeric factorisation (MUMPS's
  // RINFOG(3), on every rank of the team; 0 for the other factorisations)
  double last_factorisation_flops() const;

 private:
  struct Factorisations;    // the factorisers (MUMPS, UMFPACK, CHOLMOD), kept out of this header

  LinearSolverChoice choice_;
  double residual_tolerance_;
  long num_analyses_ = 0;
  long num_factorisations_ = 0;
  long num_reuses_ = 0;
  bool reuse_ = false;
  int reuse_iterations_ = 10;
  double reuse_fraction_ = 0.01;
  SolverTimings timings_;
  std::unique_ptr<Factorisations> factors_;
  struct ReusePolicy;    // what an earlier solve may answer
  std::unique_ptr<ReusePolicy> policy_;

  template <typename Scalar>
  HelmholtzSolution solve_system(Factoriser<Scalar> &factoriser, SparsityPattern &pattern,
                                 const Eigen::SparseMatrix<Scalar> &a, const Eigen::VectorXcd &rhs,
                                 const std::vector<int> &free_dofs, int kind);
};

}    // namespace Acoustic

#endif
