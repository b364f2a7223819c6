/* ----------------------------------------------------------------------
   ACOUSTIC package numerics: distributed Krylov solve of the damped
   Helmholtz problem (PETSc KSP on a shell matrix).
------------------------------------------------------------------------- */

#include "acoustic_krylov_solver.h"

#include "acoustic_solver_error.h"

#include <Eigen/SparseCore>

#include <chrono>
#include <cmath>
#include <complex>
#include <limits>
#include <cstdio>
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

// every rank throws if any rank found the input invalid (a collective
// solve must not leave ranks behind)
void agree_on_validity(MPI_Comm comm, const std::string &local_problem)
{
  int bad = local_problem.empty() ? 0 : 1, any_bad = 0;
  MPI_Allreduce(&bad, &any_bad, 1, MPI_INT, MPI_MAX, comm);
  if (bad) throw SolverError(local_problem);
  if (any_bad) throw SolverErrorElsewhere();
}

std::string check_problem(const DistributedHelmholtzProblem &p)
{
  if (!p.network) return "Krylov Helmholtz solve: no network";
  const ContactNetwork &net = *p.network;
  if (p.num_owned < 0 || p.num_owned > net.num_grains())
    return "Krylov Helmholtz solve: num_owned is outside 0.." + std::to_string(net.num_grains());
  if (!std::isfinite(p.omega) || p.omega < 0.0)
    return "Krylov Helmholtz solve: the angular frequency must be >= 0 and finite";
  if (p.prescribed_values.size() != static_cast<Eigen::Index>(p.prescribed_dofs.size()))
    return "Krylov Helmholtz solve: give one prescribed value per prescribed DOF";
  if (!p.prescribed_values.allFinite()) return "Krylov Helmholtz solve: a prescribed value is not finite";
  std::vector<char> seen(net.num_dofs(), 0);
  for (int dof : p.prescribed_dofs) {
    if (dof < 0 || dof >= net.num_dofs())
      return "Krylov Helmholtz solve: prescribed DOF " + std::to_string(dof) + " is outside the network";
    if (seen[dof]) return "Krylov Helmholtz solve: DOF " + std::to_string(dof) + " is prescribed twice";
    seen[dof] = 1;
  }
  return "";
}

// The local operator and the map between the solver's unknowns (the free
// DOFs of the owned grains, in DOF order) and the local DOFs.
class LocalOperator {
 public:
  LocalOperator(const DistributedHelmholtzProblem &p, HaloExchange &halo) :
      halo_(halo), ndof_(p.network->dofs_per_grain()), num_dofs_(p.network->num_dofs())
  {
    const ContactNetwork &net = *p.network;
    const double omega = p.omega;
    // K + i omega C on every local DOF, - omega^2 m on the owned ones: a
    // ghost's mass is counted by its owner
    Eigen::SparseMatrix<Complex> a = net.stiffness_matrix().cast<Complex>();
    if (net.has_damping() && omega > 0.0) a += Complex(0.0, omega) * net.damping_matrix().cast<Complex>();
    const Eigen::VectorXd mass = net.mass_diagonal();
    Eigen::VectorXcd diagonal = Eigen::VectorXcd::Zero(num_dofs_);
    owned_mass_ = Eigen::VectorXd::Zero(num_dofs_);
    for (int k = 0; k < p.num_owned * ndof_; ++k) {
      diagonal[k] = -omega * omega * mass[k];
      owned_mass_[k] = mass[k];
    }
    a += Eigen::SparseMatrix<Complex>(diagonal.asDiagonal());
    matrix_ = std::move(a);
    matrix_.makeCompressed();

    prescribed_.assign(num_dofs_, 0);
    for (int dof : p.prescribed_dofs) prescribed_[dof] = 1;
    for (int dof = 0; dof < p.num_owned * ndof_; ++dof)
      if (!prescribed_[dof]) unknowns_.push_back(dof);
    in_.resize(num_dofs_);
    out_.resize(num_dofs_);
  }

  int num_unknowns() const { return static_cast<int>(unknowns_.size()); }
  int num_dofs() const { return num_dofs_; }
  const Eigen::VectorXd &owned_mass() const { return owned_mass_; }
  const std::vector<int> &unknowns() const { return unknowns_; }
  const std::vector<char> &prescribed() const { return prescribed_; }
  const Eigen::SparseMatrix<Complex> &matrix() const { return matrix_; }
  HaloExchange &halo() { return halo_; }
  int dofs_per_grain() const { return ndof_; }

  // y = A_FF x on the unknowns of this rank (collective)
  void apply(const Complex *x, Complex *y)
  {
    in_.setZero();
    for (std::size_t k = 0; k < unknowns_.size(); ++k) in_[unknowns_[k]] = x[k];
    multiply_local(y);
  }

  // b = -A_FP q_P on the unknowns of this rank (collective); every prescribed
  // DOF the rank holds has its value in `values` (local DOFs)
  void right_hand_side(const Eigen::VectorXcd &values, Complex *b)
  {
    in_.setZero();
    for (int dof = 0; dof < num_dofs_; ++dof)
      if (prescribed_[dof]) in_[dof] = values[dof];
    multiply_local(b);
    for (std::size_t k = 0; k < unknowns_.size(); ++k) b[k] = -b[k];
  }

 private:
  // out = A in on the unknowns, in_ holding the owned values: ghosts from
  // their owners, local products, ghost rows back to their owners
  void multiply_local(Complex *result)
  {
    halo_.forward(in_.data(), ndof_);
    out_.noalias() = matrix_ * in_;
    halo_.reverse(out_.data(), ndof_);
    for (std::size_t k = 0; k < unknowns_.size(); ++k) result[k] = out_[unknowns_[k]];
  }

  HaloExchange &halo_;
  int ndof_, num_dofs_;
  Eigen::SparseMatrix<Complex> matrix_;
  Eigen::VectorXd owned_mass_;
  std::vector<char> prescribed_;
  std::vector<int> unknowns_;
  Eigen::VectorXcd in_, out_;
};

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
  if (ierr) throw SolverError("Krylov Helmholtz solver: PETSc failed to initialise (error " + std::to_string(ierr) + ")");
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
}

void check(PetscErrorCode ierr, const char *what)
{
  if (!ierr) return;
  const char *text = nullptr;
  PetscErrorMessage(ierr, &text, nullptr);
  throw SolverError(std::string("Krylov Helmholtz solve: PETSc failed in ") + what + ": " + (text ? text : "unknown error"));
}

struct ShellContext {
  LocalOperator *op = nullptr;
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
  ctx->op->apply(reinterpret_cast<const Complex *>(in), reinterpret_cast<Complex *>(out));
  ++ctx->products;
  PetscCall(VecRestoreArrayWrite(y, &out));
  PetscCall(VecRestoreArrayRead(x, &in));
  return 0;
}

// converged when the (unpreconditioned) residual is below tolerance * ||b||,
// whatever the initial guess
PetscErrorCode converged_relative_to_rhs(KSP, PetscInt, PetscReal rnorm, KSPConvergedReason *reason, void *context)
{
  const auto *ctx = static_cast<const ShellContext *>(context);
  if (!std::isfinite(rnorm)) *reason = KSP_DIVERGED_NANORINF;
  else if (rnorm <= ctx->tolerance * ctx->rhs_norm) *reason = KSP_CONVERGED_RTOL;
  else *reason = KSP_CONVERGED_ITERATING;
  return 0;
}

// The shifted operator P = A + i beta omega^2 M (= K + i omega C - (1 - i beta)
// omega^2 M) assembled as a PETSc matrix over the unknowns of every rank:
// each rank adds the entries of its local operator, rows of ghosts
// included (PETSc sends them to their owners).
Mat assemble_shifted_operator(LocalOperator &op, MPI_Comm comm, double omega, double beta)
{
  const int n = op.num_unknowns();
  int first = 0;
  MPI_Exscan(&n, &first, 1, MPI_INT, MPI_SUM, comm);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0) first = 0;
  // the global index of each local DOF (ghosts from their owners), -1 if prescribed
  Eigen::VectorXcd index = Eigen::VectorXcd::Constant(op.num_dofs(), Complex(-1.0));
  for (int k = 0; k < n; ++k) index[op.unknowns()[k]] = Complex(first + k);
  op.halo().forward(index.data(), op.dofs_per_grain());
  std::vector<PetscInt> global(op.num_dofs());
  for (int k = 0; k < op.num_dofs(); ++k)
    global[k] = op.prescribed()[k] ? -1 : static_cast<PetscInt>(std::lround(index[k].real()));

  Eigen::SparseMatrix<Complex> shifted = op.matrix();
  for (int k = 0; k < op.num_dofs(); ++k)
    if (op.owned_mass()[k] > 0.0) shifted.coeffRef(k, k) += Complex(0.0, beta * omega * omega * op.owned_mass()[k]);

  auto insert = [&](Mat m) {
    std::vector<PetscInt> rows;
    std::vector<PetscScalar> values;
    for (int col = 0; col < shifted.outerSize(); ++col) {
      const PetscInt gcol = global[col];
      if (gcol < 0) continue;
      rows.clear();
      values.clear();
      for (Eigen::SparseMatrix<Complex>::InnerIterator it(shifted, col); it; ++it) {
        if (global[it.row()] < 0) continue;
        rows.push_back(global[it.row()]);
        values.push_back(it.value());
      }
      check(MatSetValues(m, static_cast<PetscInt>(rows.size()), rows.data(), 1, &gcol, values.data(), ADD_VALUES),
            "MatSetValues");
    }
    check(MatAssemblyBegin(m, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    check(MatAssemblyEnd(m, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  };
  // blocks of the DOFs of a grain (faster incomplete factors) when every
  // grain has all its DOFs free or none
  const int ndof = op.dofs_per_grain();
  int blocked = 1;
  for (std::size_t k = 0; k < op.unknowns().size(); k += ndof)
    if (k + ndof - 1 >= op.unknowns().size() || op.unknowns()[k + ndof - 1] != op.unknowns()[k] + ndof - 1 ||
        op.unknowns()[k] % ndof != 0)
      blocked = 0;
  MPI_Allreduce(MPI_IN_PLACE, &blocked, 1, MPI_INT, MPI_MIN, comm);
  const PetscInt block = blocked ? ndof : 1;

  Mat preallocator = nullptr, p = nullptr;
  check(MatCreate(comm, &preallocator), "MatCreate");
  check(MatSetType(preallocator, MATPREALLOCATOR), "MatSetType");
  check(MatSetSizes(preallocator, n, n, PETSC_DETERMINE, PETSC_DETERMINE), "MatSetSizes");
  check(MatSetBlockSize(preallocator, block), "MatSetBlockSize");
  check(MatSetUp(preallocator), "MatSetUp");
  insert(preallocator);
  check(MatCreate(comm, &p), "MatCreate");
  check(MatSetType(p, blocked ? MATBAIJ : MATAIJ), "MatSetType");
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
    throw SolverError("Krylov Helmholtz solver: the tolerance must be in (0, 1), got " + number(settings.tolerance));
  if (settings.max_iterations < 1)
    throw SolverError("Krylov Helmholtz solver: max_iterations must be >= 1, got " +
                      std::to_string(settings.max_iterations));
  initialise_petsc();
}

KrylovHelmholtzSolver::~KrylovHelmholtzSolver() = default;

namespace {

// ||b - A x|| / ||b|| over every rank; infinite if x or the residual is not finite
double relative_residual(LocalOperator &op, const std::vector<Complex> &x, const std::vector<Complex> &b,
                         double b_norm, MPI_Comm comm)
{
  std::vector<Complex> ax(x.size());
  op.apply(x.data(), ax.data());
  double local[2] = {0.0, 0.0}, global[2];
  for (std::size_t k = 0; k < x.size(); ++k) {
    local[0] += std::norm(b[k] - ax[k]);
    if (!std::isfinite(x[k].real()) || !std::isfinite(x[k].imag())) local[1] = 1.0;
  }
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, comm);
  const double residual = std::sqrt(global[0]) / b_norm;
  return (global[1] > 0.0 || !std::isfinite(residual)) ? std::numeric_limits<double>::infinity() : residual;
}

struct KspOutcome {
  std::string reason;    // PETSc's reason for stopping
  int iterations = 0, products = 0;
  double setup_seconds = 0.0, solve_seconds = 0.0;
};

// KSP on the shell operator, preconditioned with the shifted operator; x
// holds the start and the result
KspOutcome run_ksp(LocalOperator &op, const KrylovSettings &settings_, MPI_Comm comm_, double omega,
                   const std::vector<Complex> &rhs, double rhs_norm, bool guessed, std::vector<Complex> &x)
{
  KspOutcome outcome;
  Clock::time_point start = Clock::now();
  const int n = op.num_unknowns();
  ShellContext ctx;
  ctx.op = &op;
  ctx.rhs_norm = rhs_norm;
  ctx.tolerance = settings_.tolerance;
  PetscObjects petsc;
  check(MatCreateShell(comm_, n, n, PETSC_DETERMINE, PETSC_DETERMINE, &ctx, &petsc.shell), "MatCreateShell");
  check(MatShellSetOperation(petsc.shell, MATOP_MULT, reinterpret_cast<void (*)(void)>(shell_multiply)),
        "MatShellSetOperation");
  check(MatSetOption(petsc.shell, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  check(VecCreateMPIWithArray(comm_, 1, n, PETSC_DECIDE, reinterpret_cast<PetscScalar *>(x.data()), &petsc.x),
        "VecCreateMPIWithArray");
  check(VecCreateMPIWithArray(comm_, 1, n, PETSC_DECIDE, reinterpret_cast<const PetscScalar *>(rhs.data()),
                              &petsc.b),
        "VecCreateMPIWithArray");
  check(KSPCreate(comm_, &petsc.ksp), "KSPCreate");
  check(KSPSetOptionsPrefix(petsc.ksp, "acoustic_"), "KSPSetOptionsPrefix");
  check(KSPSetType(petsc.ksp, settings_.method.c_str()), "KSPSetType");
  check(KSPSetNormType(petsc.ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  check(KSPSetTolerances(petsc.ksp, settings_.tolerance, 0.0, PETSC_DEFAULT, settings_.max_iterations),
        "KSPSetTolerances");
  check(KSPSetConvergenceTest(petsc.ksp, converged_relative_to_rhs, &ctx, nullptr), "KSPSetConvergenceTest");
  check(KSPSetInitialGuessNonzero(petsc.ksp, guessed ? PETSC_TRUE : PETSC_FALSE), "KSPSetInitialGuessNonzero");
  PC pc = nullptr;
  check(KSPGetPC(petsc.ksp, &pc), "KSPGetPC");
  const bool shifted = settings_.preconditioner == KrylovPreconditioner::Shifted;
  if (shifted) {
    // the shifted operator, inverted approximately: incomplete LU on each
    // rank's unknowns and one layer of its neighbours' (additive Schwarz)
    petsc.shifted = assemble_shifted_operator(op, comm_, omega, settings_.shift);
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
  check(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCASM, &is_asm), "PetscObjectTypeCompare");
  if (shifted && is_asm) {
    // the sub-domain solves: ILU(1) unless the options say otherwise
    KSP *sub = nullptr;
    PetscInt nsub = 0;
    check(PCASMGetSubKSP(pc, &nsub, nullptr, &sub), "PCASMGetSubKSP");
    for (PetscInt k = 0; k < nsub; ++k) {
      PC subpc = nullptr;
      check(KSPGetPC(sub[k], &subpc), "KSPGetPC");
      check(KSPSetType(sub[k], KSPPREONLY), "KSPSetType");
      check(PCSetType(subpc, PCILU), "PCSetType");
      check(PCFactorSetLevels(subpc, 1), "PCFactorSetLevels");
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

HelmholtzSolution KrylovHelmholtzSolver::solve(const DistributedHelmholtzProblem &problem, HaloExchange &halo,
                                               const Eigen::VectorXcd *initial_guess)
{
  timings_ = SolverTimings();
  iterations_ = products_ = 0;
  std::string problem_text = check_problem(problem);
  if (problem_text.empty() && initial_guess && initial_guess->size() != problem.network->num_dofs())
    problem_text = "Krylov Helmholtz solve: the initial guess needs one value per local DOF";
  agree_on_validity(comm_, problem_text);

  const Clock::time_point start = Clock::now();
  const ContactNetwork &net = *problem.network;
  LocalOperator op(problem, halo);
  Eigen::VectorXcd values = Eigen::VectorXcd::Zero(net.num_dofs());
  for (std::size_t k = 0; k < problem.prescribed_dofs.size(); ++k)
    values[problem.prescribed_dofs[k]] = problem.prescribed_values[k];
  const int n = op.num_unknowns();
  std::vector<Complex> rhs(n);
  op.right_hand_side(values, rhs.data());
  double local[2] = {0.0, static_cast<double>(n)}, global[2];
  for (const Complex &v : rhs) local[0] += std::norm(v);
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, comm_);
  const double rhs_norm = std::sqrt(global[0]);
  if (!std::isfinite(rhs_norm)) throw SolverError("Krylov Helmholtz solve: the right-hand side is not finite");
  timings_.factorisation = seconds_since(start);

  HelmholtzSolution result;
  result.factorisation = settings_.method + " (" + krylov_preconditioner_name(settings_.preconditioner) + ")";
  std::vector<Complex> x(n, Complex(0.0));
  double residual = 0.0;
  if (global[1] > 0.0 && rhs_norm > 0.0) {
    if (initial_guess)
      for (int k = 0; k < n; ++k) x[k] = (*initial_guess)[op.unknowns()[k]];
    // a guess that already solves the system: no preconditioner, no iteration
    residual = initial_guess ? relative_residual(op, x, rhs, rhs_norm, comm_) : 1.0;
    if (residual <= settings_.tolerance) {
      ++num_reuses_;
      result.factorisation += " (earlier solution)";
    } else {
      const KspOutcome ksp = run_ksp(op, settings_, comm_, problem.omega, rhs, rhs_norm, initial_guess != nullptr, x);
      iterations_ = ksp.iterations;
      products_ = ksp.products;
      timings_.factorisation += ksp.setup_seconds;
      timings_.solve += ksp.solve_seconds;
      const std::string &reason = ksp.reason;
      const Clock::time_point check_start = Clock::now();
      residual = relative_residual(op, x, rhs, rhs_norm, comm_);
      timings_.solve += seconds_since(check_start);
      if (!std::isfinite(residual)) {
        for (Complex &v : x) v = 0.0;
        result.status = SolveStatus::InaccurateSolution;
        result.message = "the iterate is not finite (" + reason + ")";
        residual = 1.0;
      } else if (residual > settings_.tolerance) {
        result.status = SolveStatus::InaccurateSolution;
        result.message = "no convergence to the relative residual " + number(settings_.tolerance) + " in " +
            std::to_string(iterations_) + " iterations (" + reason + ")";
      }
    }
  }

  // q on every local DOF: the owned unknowns, the prescribed values, the ghosts from their owners
  result.q = values;
  for (int k = 0; k < n; ++k) result.q[op.unknowns()[k]] = x[k];
  halo.forward(result.q.data(), op.dofs_per_grain());
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
