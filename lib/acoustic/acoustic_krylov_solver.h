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
   ACOUSTIC package numerics: the damped Helmholtz problem solved by a
   Krylov method where the network lies, in a domain decomposition.

   The system, its operator applied where the contacts are and its
   unknowns, is a DistributedSystem (acoustic_distributed_system.h).

   The Krylov method is PETSc's (KSP on a shell matrix, on the ranks'
   communicator): BiCGStab by default.  (COCG, the natural method for a
   complex symmetric A, is KSPCG with KSP_CG_SYMMETRIC in PETSc, but its
   test for an indefinite matrix stops it on these systems.)
   Preconditioner "shifted" (default): the shifted operator
     P = K + i omega C - (1 - i shift) omega^2 M,
   assembled as a PETSc matrix over the ranks and inverted approximately by
   incomplete LU on each rank's unknowns plus one layer of its neighbours'
   (additive Schwarz, PCASM with overlap 1 and ILU(1) in reverse
   Cuthill-McKee order); "none": none.
   Convergence: ||b - A x|| <= tolerance ||b||, checked at every iteration
   on the recursively updated residual and once more on the true residual
   at the end.  PETSc options with the prefix "acoustic_" (e.g. in the
   environment variable PETSC_OPTIONS) override the method and the
   preconditioner (-acoustic_ksp_type, -acoustic_pc_type, -acoustic_sub_pc_type).

   Convergence needs damping: an undamped network driven inside its band
   is indefinite and BiCGStab stalls or breaks down.  A solve that does not
   converge within max_iterations returns status InaccurateSolution and
   its residual, never NaN (free DOFs are zero if not finite).

   Deterministic: the same input on the same ranks gives the same bits
   (fixed summation order in the products and in MPI's reductions).
   Without PETSc (ACOUSTIC_HAVE_PETSC undefined) available() is false and
   the constructor throws SolverError.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_KRYLOV_SOLVER_H
#define ACOUSTIC_KRYLOV_SOLVER_H

#include "acoustic_distributed_system.h"
#include "acoustic_halo_exchange.h"
#include "acoustic_helmholtz_solver.h"

#include <mpi.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace Acoustic {

enum class KrylovPreconditioner { None, Shifted };

// "none" or "shifted"; throws SolverError listing the allowed names otherwise
KrylovPreconditioner krylov_preconditioner_from_name(const std::string &name);
std::string krylov_preconditioner_name(KrylovPreconditioner preconditioner);

struct KrylovSettings {
  std::string method = "bcgs";    // PETSc KSP type
  double tolerance = 1e-9;        // relative residual ||b - A x|| / ||b||
  int max_iterations = 5000;
  KrylovPreconditioner preconditioner = KrylovPreconditioner::Shifted;
  double shift = 0.5;    // beta of the shifted operator K + i omega C - (1 - i beta) omega^2 M
};

class KrylovHelmholtzSolver {
 public:
  // true when built with PETSc
  static bool available();

  // collective over comm
  KrylovHelmholtzSolver(MPI_Comm comm, const KrylovSettings &settings);
  ~KrylovHelmholtzSolver();
  KrylovHelmholtzSolver(const KrylovHelmholtzSolver &) = delete;
  KrylovHelmholtzSolver &operator=(const KrylovHelmholtzSolver &) = delete;

  // Collective.  Returns q on every local DOF (ghosts from their owners,
  // prescribed DOFs their values), the iterations and the true relative
  // residual.  initial_guess: nullptr (start from 0) or one value per local
  // DOF (the owned free ones are used); a guess that already satisfies the
  // tolerance is returned as it is, after one product and no preconditioner
  // (num_reuses() counts these).  Invalid input throws SolverError on the
  // rank that found it and SolverErrorElsewhere on the others.
  HelmholtzSolution solve(const DistributedHelmholtzProblem &problem, HaloExchange &halo,
                          const Eigen::VectorXcd *initial_guess = nullptr);

  const KrylovSettings &settings() const { return settings_; }
  int last_iterations() const { return iterations_; }
  // products of the operator with a vector in the last solve (one or two per
  // iteration, depending on the method)
  int last_products() const { return products_; }
  // solves answered by the initial guess (no iteration), since construction
  long num_reuses() const { return num_reuses_; }
  // local operator, right-hand side and preconditioner (factorisation;
  // analysis = 0), iterations and final residual (solve)
  const SolverTimings &last_timings() const { return timings_; }

 private:
  MPI_Comm comm_;
  KrylovSettings settings_;
  int iterations_ = 0, products_ = 0;
  long num_reuses_ = 0;
  SolverTimings timings_;
};

}    // namespace Acoustic

#endif
