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
   ACOUSTIC package numerics: distributed Krylov solve of the damped
   Helmholtz problem (PETSc KSP on a shell matrix).
------------------------------------------------------------------------- */

#include "acoustic_krylov_solver.h"

#include "acoustic_distributed_system.h"

#include "acoustic_solver_error.h"

#include <Eigen/SparseCore>

#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <memory>

#ifdef ACOUSTIC_HAVE_PETSC
// PETSc's operators between std::complex and integers are not needed here
#define PETSC_SKIP_CXX_COMPLEX_FIX 1
#include <petscksp.h>
#endif

namespace Acoustic {

KrylovPreconditioner krylov_preconditioner_from_name(const std::string &name)
{
  if (name == "none") return KrylovPreconditioner::None;
  if (name == "shifted") return KrylovPreconditioner::Shifted;
  throw SolverError("unknown preconditioner '" + name + "': allowed are none, shifted");
}

std::string krylov_preconditioner_name(KrylovPreconditioner preconditioner)
{
  return preconditioner == KrylovPreconditioner::None ? "none" : "shifted";
}

namespace {

  using Complex = std::complex<double>;
  using Clock = std::chrono::steady_clock;

  // a number in messages: %g, readable for 1e-9 as for 0.5
  std::string number(double value)
  {
    char text[32];
    std::snprintf(text, sizeof(text), "%g", value);
    return text;
  }

  double seconds_since(Clock::time_point start)
  {
    return std::chrono::duration<double>(Clock::now() - start).count();
  }

}    // namespace

#ifdef ACOUSTIC_HAVE_PETSC

namespace {

  static_assert(sizeof(PetscScalar) == sizeof(Complex), "PETSc must be built with complex scalars");

  // PETSc once per process, on each rank by itself (PETSC_COMM_WORLD = self:
  // no collective call at start-up, whatever the caller's communicator);
  // errors come back as codes, not as PETSc's own messages on stderr, and
  // signals stay with the host program.  PETSc is left initialised until the
  // process ends (finalising it would end it for any other user in the process).
  void initialise_petsc()
  {
    PetscBool initialised = PETSC_FALSE;
    PetscInitialized(&initialised);
    if (initialised) return;
    PETSC_COMM_WORLD = MPI_COMM_SELF;
    PetscErrorCode ierr = PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr);
    if (!ierr) ierr = PetscInitializeNoArguments();
    if (ierr)
      throw SolverError("Krylov Helmholtz solver: PETSc failed to initialise (error " +
                        std::to_string(ierr) + ")");
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  }

  void check(PetscErrorCode ierr, const char *what)
  {
    if (!ierr) return;
    const char *text = nullptr;
    PetscErrorMessage(ierr, &text, nullptr);
    throw SolverError(std::string("Krylov Helmholtz solve: PETSc failed in ") + what + ": " +
                      (text ? text : "unknown error"));
  }

  struct ShellContext {
    DistributedSystem *system = nullptr;
    double rhs_norm = 0.0;
    double tolerance = 0.0;
    int products = 0;    // of the operator with a vector
  };

  PetscErrorCode shell_multiply(Mat a, Vec x, Vec y)
  {
    ShellContext *ctx = nullptr;
    PetscCall(MatShellGetContext(a, &ctx));
    const PetscScalar *in = nullptr;
    PetscScalar *out = nullptr;
    PetscCall(VecGetArrayRead(x, &in));
    PetscCall(VecGetArrayWrite(y, &out));
    ctx->system->apply(reinterpret_cast<const Complex *>(in), reinterpret_cast<Complex *>(out));
    ++ctx->products;
    PetscCall(VecRestoreArrayWrite(y, &out));
    PetscCall(VecRestoreArrayRead(x, &in));
    return 0;
  }

  // converged when the (unpreconditioned) residual is below tolerance * ||b||,
  // whatever the initial guess
  PetscErrorCode converged_relative_to_rhs(KSP, PetscInt, PetscReal rnorm,
                                           KSPConvergedReason *reason, void *context)
  {
    const auto *ctx = static_cast<const ShellContext *>(context);
    if (!std::isfinite(rnorm))
      *reason = KSP_DIVERGED_NANORINF;
    else if (rnorm <= ctx->tolerance * ctx->rhs_norm)
      *reason = KSP_CONVERGED_RTOL;
    else
      *reason = KSP_CONVERGED_ITERATING;
    return 0;
  }

  // The shifted operator P = A + i beta omega^2 M (= K + i omega C - (1 - i beta)
  // omega^2 M) assembled as a PETSc matrix over the unknowns of every rank:
  // each rank adds the entries of its local operator, rows of ghosts
  // included (PETSc sends them to their owners); blocks of the DOFs of a
  // grain (faster incomplete factors) when every grain has all its DOFs
  // unknown or none.
  Mat assemble_shifted_operator(DistributedSystem &system, double beta)
  {
    std::vector<long> rows, cols;
    std::vector<Complex> values;
    system.global_entries(beta, false, rows, cols, values);
    const MPI_Comm comm = system.comm();
    const PetscInt n = system.num_unknowns();
    const PetscInt block = system.blocked() ? system.dofs_per_grain() : 1;
    // the entries come column by column: one call per column
    std::vector<PetscInt> petsc_rows(rows.begin(), rows.end());
    auto insert = [&](Mat m) {
      for (std::size_t k = 0; k < rows.size();) {
        std::size_t end = k;
        while (end < rows.size() && cols[end] == cols[k]) ++end;
        const PetscInt col = static_cast<PetscInt>(cols[k]);
        check(MatSetValues(m, static_cast<PetscInt>(end - k), &petsc_rows[k], 1, &col,
                           reinterpret_cast<const PetscScalar *>(&values[k]), ADD_VALUES),
              "MatSetValues");
        k = end;
      }
      check(MatAssemblyBegin(m, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
      check(MatAssemblyEnd(m, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
    };
    Mat preallocator = nullptr, p = nullptr;
    check(MatCreate(comm, &preallocator), "MatCreate");
    check(MatSetType(preallocator, MATPREALLOCATOR), "MatSetType");
    check(MatSetSizes(preallocator, n, n, PETSC_DETERMINE, PETSC_DETERMINE), "MatSetSizes");
    check(MatSetBlockSize(preallocator, block), "MatSetBlockSize");
    check(MatSetUp(preallocator), "MatSetUp");
    insert(preallocator);
    check(MatCreate(comm, &p), "MatCreate");
    check(MatSetType(p, block > 1 ? MATBAIJ : MATAIJ), "MatSetType");
    check(MatSetSizes(p, n, n, PETSC_DETERMINE, PETSC_DETERMINE), "MatSetSizes");
    check(MatSetBlockSize(p, block), "MatSetBlockSize");
    check(MatPreallocatorPreallocate(preallocator, PETSC_TRUE, p), "MatPreallocatorPreallocate");
    MatDestroy(&preallocator);
    insert(p);
    return p;
  }

  // PETSc objects of one solve, destroyed with it
  struct PetscObjects {
    Mat shell = nullptr, shifted = nullptr;
    Vec x = nullptr, b = nullptr;
    KSP ksp = nullptr;
    ~PetscObjects()
    {
      KSPDestroy(&ksp);
      VecDestroy(&b);
      VecDestroy(&x);
      MatDestroy(&shifted);
      MatDestroy(&shell);
    }
  };

}    // namespace

bool KrylovHelmholtzSolver::available()
{
  return true;
}

KrylovHelmholtzSolver::KrylovHelmholtzSolver(MPI_Comm comm, const KrylovSettings &settings) :
    comm_(comm), settings_(settings)
{
  if (!(settings.tolerance > 0.0) || !(settings.tolerance < 1.0))
    throw SolverError("Krylov Helmholtz solver: the tolerance must be in (0, 1), got " +
                      number(settings.tolerance));
  if (settings.max_iterations < 1)
    throw SolverError("Krylov Helmholtz solver: max_iterations must be >= 1, got " +
                      std::to_string(settings.max_iterations));
  initialise_petsc();
}

KrylovHelmholtzSolver::~KrylovHelmholtzSolver() = default;

namespace {

  struct KspOutcome {
    std::string reason;    // PETSc's reason for stopping
    int iterations = 0, products = 0;
    double setup_seconds = 0.0, solve_seconds = 0.0;
  };

  // KSP on the shell operator, preconditioned with the shifted operator; x
  // holds the start and the result
  KspOutcome run_ksp(DistributedSystem &system, const KrylovSettings &settings_, bool guessed,
                     std::vector<Complex> &x)
  {
    KspOutcome outcome;
    Clock::time_point start = Clock::now();
    const MPI_Comm comm_ = system.comm();
    const int n = system.num_unknowns();
    const std::vector<Complex> &rhs = system.right_hand_side();
    ShellContext ctx;
    ctx.system = &system;
    ctx.rhs_norm = system.rhs_norm();
    ctx.tolerance = settings_.tolerance;
    PetscObjects petsc;
    check(MatCreateShell(comm_, n, n, PETSC_DETERMINE, PETSC_DETERMINE, &ctx, &petsc.shell),
          "MatCreateShell");
    check(MatShellSetOperation(petsc.shell, MATOP_MULT,
                               reinterpret_cast<void (*)(void)>(shell_multiply)),
          "MatShellSetOperation");
    check(MatSetOption(petsc.shell, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
    check(VecCreateMPIWithArray(comm_, 1, n, PETSC_DECIDE,
                                reinterpret_cast<PetscScalar *>(x.data()), &petsc.x),
          "VecCreateMPIWithArray");
    check(VecCreateMPIWithArray(comm_, 1, n, PETSC_DECIDE,
                                reinterpret_cast<const PetscScalar *>(rhs.data()), &petsc.b),
          "VecCreateMPIWithArray");
    check(KSPCreate(comm_, &petsc.ksp), "KSPCreate");
    check(KSPSetOptionsPrefix(petsc.ksp, "acoustic_"), "KSPSetOptionsPrefix");
    check(KSPSetType(petsc.ksp, settings_.method.c_str()), "KSPSetType");
    check(KSPSetNormType(petsc.ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
    check(KSPSetTolerances(petsc.ksp, settings_.tolerance, 0.0, PETSC_DEFAULT,
                           settings_.max_iterations),
          "KSPSetTolerances");
    check(KSPSetConvergenceTest(petsc.ksp, converged_relative_to_rhs, &ctx, nullptr),
          "KSPSetConvergenceTest");
    check(KSPSetInitialGuessNonzero(petsc.ksp, guessed ? PETSC_TRUE : PETSC_FALSE),
          "KSPSetInitialGuessNonzero");
    PC pc = nullptr;
    check(KSPGetPC(petsc.ksp, &pc), "KSPGetPC");
    const bool shifted = settings_.preconditioner == KrylovPreconditioner::Shifted;
    if (shifted) {
      // the shifted operator, inverted approximately: incomplete LU on each
      // rank's unknowns and one layer of its neighbours' (additive Schwarz)
      petsc.shifted = assemble_shifted_operator(system, settings_.shift);
      check(KSPSetOperators(petsc.ksp, petsc.shell, petsc.shifted), "KSPSetOperators");
      check(PCSetType(pc, PCASM), "PCSetType");
      check(PCASMSetOverlap(pc, 1), "PCASMSetOverlap");
    } else {
      check(KSPSetOperators(petsc.ksp, petsc.shell, petsc.shell), "KSPSetOperators");
      check(PCSetType(pc, PCNONE), "PCSetType");
    }
    check(KSPSetFromOptions(petsc.ksp), "KSPSetFromOptions");
    check(KSPSetUp(petsc.ksp), "KSPSetUp");
    PetscBool is_asm = PETSC_FALSE;
    check(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCASM, &is_asm),
          "PetscObjectTypeCompare");
    if (shifted && is_asm) {
      // the sub-domain solves: ILU(1) in reverse Cuthill-McKee order unless the options say
      // otherwise
      KSP *sub = nullptr;
      PetscInt nsub = 0;
      check(PCASMGetSubKSP(pc, &nsub, nullptr, &sub), "PCASMGetSubKSP");
      for (PetscInt k = 0; k < nsub; ++k) {
        PC subpc = nullptr;
        check(KSPGetPC(sub[k], &subpc), "KSPGetPC");
        check(KSPSetType(sub[k], KSPPREONLY), "KSPSetType");
        check(PCSetType(subpc, PCILU), "PCSetType");
        check(PCFactorSetLevels(subpc, 1), "PCFactorSetLevels");
        // reverse Cuthill-McKee: 10 % fewer iterations than the natural order (bench/README.md)
        check(PCFactorSetMatOrderingType(subpc, MATORDERINGRCM), "PCFactorSetMatOrderingType");
        check(KSPSetFromOptions(sub[k]), "KSPSetFromOptions");
      }
      check(PCSetUpOnBlocks(pc), "PCSetUpOnBlocks");    // the incomplete factors
    }
    outcome.setup_seconds = seconds_since(start);
    start = Clock::now();
    check(KSPSolve(petsc.ksp, petsc.b, petsc.x), "KSPSolve");
    PetscInt its = 0;
    check(KSPGetIterationNumber(petsc.ksp, &its), "KSPGetIterationNumber");
    outcome.iterations = static_cast<int>(its);
    outcome.products = ctx.products;
    KSPConvergedReason reason;
    check(KSPGetConvergedReason(petsc.ksp, &reason), "KSPGetConvergedReason");
    outcome.reason = KSPConvergedReasons[reason];
    outcome.solve_seconds = seconds_since(start);
    return outcome;
  }

}    // namespace

HelmholtzSolution KrylovHelmholtzSolver::solve(const DistributedHelmholtzProblem &problem,
                                               HaloExchange &halo,
                                               const Eigen::VectorXcd *initial_guess)
{
  timings_ = SolverTimings();
  iterations_ = products_ = 0;
  int bad_guess =
      (initial_guess && problem.network && initial_guess->size() != problem.network->num_dofs())
      ? 1
      : 0;
  MPI_Allreduce(MPI_IN_PLACE, &bad_guess, 1, MPI_INT, MPI_MAX, comm_);
  if (bad_guess)
    throw SolverError("Krylov Helmholtz solve: the initial guess needs one value per local DOF");

  const Clock::time_point start = Clock::now();
  DistributedSystem system(problem, halo, comm_);
  timings_.factorisation = seconds_since(start);
  const int n = system.num_unknowns();

  HelmholtzSolution result;
  result.factorisation =
      settings_.method + " (" + krylov_preconditioner_name(settings_.preconditioner) + ")";
  std::vector<Complex> x(n, Complex(0.0));
  double residual = 0.0;
  if (system.num_global_unknowns() > 0 && system.rhs_norm() > 0.0) {
    if (initial_guess)
      for (int k = 0; k < n; ++k) x[k] = (*initial_guess)[system.unknowns()[k]];
    // a guess that already solves the system: no preconditioner, no iteration
    residual = initial_guess ? system.relative_residual(x) : 1.0;
    if (residual <= settings_.tolerance) {
      ++num_reuses_;
      result.factorisation += " (earlier solution)";
    } else {
      const KspOutcome ksp = run_ksp(system, settings_, initial_guess != nullptr, x);
      iterations_ = ksp.iterations;
      products_ = ksp.products;
      timings_.factorisation += ksp.setup_seconds;
      timings_.solve += ksp.solve_seconds;
      const Clock::time_point check_start = Clock::now();
      residual = system.relative_residual(x);
      timings_.solve += seconds_since(check_start);
      if (!std::isfinite(residual)) {
        for (Complex &v : x) v = 0.0;
        result.status = SolveStatus::InaccurateSolution;
        result.message = "the iterate is not finite (" + ksp.reason + ")";
        residual = 1.0;
      } else if (residual > settings_.tolerance) {
        result.status = SolveStatus::InaccurateSolution;
        result.message = "no convergence to the relative residual " + number(settings_.tolerance) +
            " in " + std::to_string(iterations_) + " iterations (" + ksp.reason + ")";
      }
    }
  }
  result.q = system.local_solution(x);
  result.relative_residual = residual;
  result.iterations = iterations_;
  return result;
}

#else    // no PETSc

bool KrylovHelmholtzSolver::available()
{
  return false;
}

KrylovHelmholtzSolver::KrylovHelmholtzSolver(MPI_Comm comm, const KrylovSettings &settings) :
    comm_(comm), settings_(settings)
{
  throw SolverError("the iterative solver needs PETSc with complex scalars (Debian: "
                    "libpetsc-complex-dev); this build has none: use a direct solver or rebuild");
}

KrylovHelmholtzSolver::~KrylovHelmholtzSolver() = default;

HelmholtzSolution KrylovHelmholtzSolver::solve(const DistributedHelmholtzProblem &, HaloExchange &,
                                               const Eigen::VectorXcd *)
{
  throw SolverError("the iterative solver needs PETSc");
}

#endif

}    // namespace Acoustic
