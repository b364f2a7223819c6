/* ----------------------------------------------------------------------
   ACOUSTIC package numerics: steady harmonic response (Helmholtz problem).
------------------------------------------------------------------------- */

#include "acoustic_helmholtz_solver.h"

#include "acoustic_mumps_ldlt.h"
#include "acoustic_solver_error.h"

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/UmfPackSupport>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>

namespace Acoustic {

namespace {

// a number in error messages: %g, readable for 1e200 as for 0.5
std::string number(double value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
}

using Complex = std::complex<double>;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// UMFPACK LU that also reports whether the matrix was found singular.
template <typename Matrix> class UmfpackLU : public Eigen::UmfPackLU<Matrix> {
 public:
  // no iterative refinement in UMFPACK's solve: the caller measures the residual
  UmfpackLU() { this->umfpackControl()(UMFPACK_IRSTEP) = 0; }
  bool singular() const { return this->m_fact_errorCode == UMFPACK_WARNING_singular_matrix; }
};

// Real symmetric LDL^T (CHOLMOD simplicial, lower triangle), silent on zero pivots.
class CholmodLDLT : public Eigen::CholmodSimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> {
 public:
  CholmodLDLT()
  {
    this->cholmod().print = 0;
    // one fill-reducing ordering (AMD) instead of CHOLMOD's default search over
    // AMD, METIS and NESDIS: the analysis is redone whenever contacts change
    this->cholmod().nmethods = 1;
    this->cholmod().method[0].ordering = CHOLMOD_AMD;
    this->cholmod().postorder = 1;
  }
};

// Sparsity pattern of the last matrix a factorisation object was analysed for.
class SparsityPattern {
 public:
  template <typename Scalar> bool matches(const Eigen::SparseMatrix<Scalar> &a) const
  {
    if (!valid_ || a.rows() != rows_ || a.nonZeros() != static_cast<Eigen::Index>(inner_.size()))
      return false;
    return std::equal(outer_.begin(), outer_.end(), a.outerIndexPtr()) &&
        std::equal(inner_.begin(), inner_.end(), a.innerIndexPtr());
  }
  // number of columns of a whose row indices differ from the stored pattern
  // (all of them if the sizes differ): how many DOFs gained or lost a contact
  template <typename Scalar> Eigen::Index changed_columns(const Eigen::SparseMatrix<Scalar> &a) const
  {
    if (!valid_ || a.rows() != rows_) return a.cols();
    Eigen::Index changed = 0;
    for (Eigen::Index col = 0; col < a.outerSize(); ++col) {
      const auto *begin = a.innerIndexPtr() + a.outerIndexPtr()[col];
      const auto *end = a.innerIndexPtr() + a.outerIndexPtr()[col + 1];
      const auto old_begin = inner_.begin() + outer_[col];
      const auto old_end = inner_.begin() + outer_[col + 1];
      if ((end - begin) != (old_end - old_begin) || !std::equal(begin, end, old_begin)) ++changed;
    }
    return changed;
  }
  template <typename Scalar> void store(const Eigen::SparseMatrix<Scalar> &a)
  {
    rows_ = a.rows();
    outer_.assign(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1);
    inner_.assign(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros());
    valid_ = true;
  }

 private:
  bool valid_ = false;
  Eigen::Index rows_ = 0;
  std::vector<int> outer_;
  std::vector<int> inner_;
};

// Which DOFs are free and where the prescribed values are.
struct DofPartition {
  std::vector<int> free_index;          // DOF -> index among the free DOFs, -1 if prescribed
  std::vector<int> prescribed_index;    // DOF -> index into the prescribed values, -1 if free
  std::vector<int> free_dofs;
};

DofPartition partition_dofs(int num_dofs, const std::vector<int> &prescribed_dofs)
{
  DofPartition part;
  part.free_index.assign(num_dofs, 0);
  part.prescribed_index.assign(num_dofs, -1);
  for (std::size_t k = 0; k < prescribed_dofs.size(); ++k) {
    const int dof = prescribed_dofs[k];
    if (dof < 0 || dof >= num_dofs)
      throw SolverError("Helmholtz solve: prescribed DOF " + std::to_string(dof) + " is outside 0.." +
                        std::to_string(num_dofs - 1));
    if (part.prescribed_index[dof] >= 0)
      throw SolverError("Helmholtz solve: DOF " + std::to_string(dof) + " is prescribed twice");
    part.prescribed_index[dof] = static_cast<int>(k);
    part.free_index[dof] = -1;
  }
  for (int dof = 0; dof < num_dofs; ++dof) {
    if (part.free_index[dof] < 0) continue;
    part.free_index[dof] = static_cast<int>(part.free_dofs.size());
    part.free_dofs.push_back(dof);
  }
  return part;
}

// Moves the free-prescribed part of column col of coeff * S to the right-hand side.
template <typename Scalar>
void move_to_rhs(const Eigen::SparseMatrix<double> &s, int col, Scalar coeff, const DofPartition &part,
                 const Complex &value, Eigen::VectorXcd &rhs)
{
  for (Eigen::SparseMatrix<double>::InnerIterator it(s, col); it; ++it) {
    const int free_row = part.free_index[it.row()];
    if (free_row >= 0) rhs[free_row] -= Complex(coeff * it.value()) * value;
  }
}

// A_FF = K_FF + damping_coeff C_FF - omega^2 M_FF (pattern independent of omega and of
// the values) and b of the Helmholtz problem; damping_coeff = i omega when damping is
// given.  Built column by column in compressed storage: the free DOFs keep their
// order, so column j of A_FF merges the free rows of the columns of K and C (sorted)
// with the diagonal mass term, in one pass over K and C.
template <typename Scalar>
void assemble_free_system(const Eigen::SparseMatrix<double> &stiffness, const Eigen::SparseMatrix<double> *damping,
                          Scalar damping_coeff, const Eigen::VectorXd &mass, double omega, const DofPartition &part,
                          const Eigen::VectorXcd &values, Eigen::SparseMatrix<Scalar> &a, Eigen::VectorXcd &rhs)
{
  typedef Eigen::SparseMatrix<double>::InnerIterator Iterator;
  const int nfree = static_cast<int>(part.free_dofs.size());
  const int n = static_cast<int>(stiffness.cols());
  rhs.setZero(nfree);
  std::vector<int> outer(nfree + 1, 0), inner;
  std::vector<Scalar> entries;
  const std::size_t capacity = stiffness.nonZeros() + (damping ? damping->nonZeros() : 0) + nfree;
  inner.reserve(capacity);
  entries.reserve(capacity);
  const int end = std::numeric_limits<int>::max();
  for (int col = 0; col < n; ++col) {
    const int free_col = part.free_index[col];
    if (free_col < 0) {
      const Complex value = values[part.prescribed_index[col]];
      move_to_rhs<Scalar>(stiffness, col, Scalar(1.0), part, value, rhs);
      if (damping) move_to_rhs<Scalar>(*damping, col, damping_coeff, part, value, rhs);
      continue;
    }
    outer[free_col] = static_cast<int>(inner.size());
    Iterator k(stiffness, col);
    Iterator c = damping ? Iterator(*damping, col) : Iterator(stiffness, col);
    bool c_valid = damping != nullptr && static_cast<bool>(c);
    bool diagonal_pending = true;
    for (;;) {
      const int row_k = k ? static_cast<int>(k.row()) : end;
      const int row_c = c_valid ? static_cast<int>(c.row()) : end;
      const int row_d = diagonal_pending ? col : end;
      const int row = std::min(row_k, std::min(row_c, row_d));
      if (row == end) break;
      Scalar sum(0.0);
      if (row_k == row) {
        sum += Scalar(k.value());
        ++k;
      }
      if (row_c == row) {
        sum += damping_coeff * c.value();
        ++c;
        c_valid = static_cast<bool>(c);
      }
      if (row_d == row) {
        sum += Scalar(-omega * omega * mass[col]);
        diagonal_pending = false;
      }
      const int free_row = part.free_index[row];
      if (free_row < 0) continue;
      inner.push_back(free_row);
      entries.push_back(sum);
    }
  }
  outer[nfree] = static_cast<int>(inner.size());
  a = Eigen::Map<const Eigen::SparseMatrix<Scalar>>(nfree, nfree, static_cast<Eigen::Index>(inner.size()),
                                                    outer.data(), inner.data(), entries.data());
}

// Right-hand side in the scalar type of the factorisation: [Re b, Im b] for real matrices.
Eigen::MatrixXd as_columns(const Eigen::VectorXcd &b, double)
{
  Eigen::MatrixXd m(b.size(), 2);
  m.col(0) = b.real();
  m.col(1) = b.imag();
  return m;
}
Eigen::MatrixXcd as_columns(const Eigen::VectorXcd &b, Complex)
{
  return b;
}
Eigen::VectorXcd from_columns(const Eigen::MatrixXd &x)
{
  return x.col(0).cast<Complex>() + Complex(0.0, 1.0) * x.col(1).cast<Complex>();
}
Eigen::VectorXcd from_columns(const Eigen::MatrixXcd &x)
{
  return x.col(0);
}

// x = A^-1 b with a factorisation of A: real factors solve for the real and the
// imaginary part of b, leaving out a part that is zero (a drive in phase
// everywhere has no imaginary part: one triangular solve instead of two)
template <typename Solver> Eigen::VectorXcd solve_with(const Solver &solver, const Eigen::VectorXcd &b, double)
{
  const bool re = b.real().squaredNorm() > 0.0, im = b.imag().squaredNorm() > 0.0;
  Eigen::MatrixXd columns(b.size(), int(re) + int(im));
  if (re) columns.col(0) = b.real();
  if (im) columns.col(columns.cols() - 1) = b.imag();
  Eigen::VectorXcd x = Eigen::VectorXcd::Zero(b.size());
  if (columns.cols() == 0) return x;
  const Eigen::MatrixXd solved = solver.solve(columns);
  if (re) x.real() = solved.col(0);
  if (im) x.imag() = solved.col(solved.cols() - 1);
  return x;
}
template <typename Solver> Eigen::VectorXcd solve_with(const Solver &solver, const Eigen::VectorXcd &b, Complex)
{
  return solver.solve(b);
}

Eigen::VectorXcd multiply(const Eigen::SparseMatrix<double> &a, const Eigen::VectorXcd &x)
{
  const Eigen::VectorXd re = a * x.real();
  const Eigen::VectorXd im = a * x.imag();
  return re.cast<Complex>() + Complex(0.0, 1.0) * im.cast<Complex>();
}
Eigen::VectorXcd multiply(const Eigen::SparseMatrix<Complex> &a, const Eigen::VectorXcd &x)
{
  return a * x;
}

// ||A x - b|| / ||b||, infinite when not finite
template <typename Scalar>
double relative_residual(const Eigen::SparseMatrix<Scalar> &a, const Eigen::VectorXcd &x, const Eigen::VectorXcd &b)
{
  const double residual = (multiply(a, x) - b).norm() / b.norm();
  return std::isfinite(residual) ? residual : std::numeric_limits<double>::infinity();
}

template <typename Solver> bool numerically_singular(const Solver &solver)
{
  return solver.info() != Eigen::Success;
}
template <typename Matrix> bool numerically_singular(const UmfpackLU<Matrix> &solver)
{
  return solver.info() != Eigen::Success || solver.singular();
}

// why a factorisation failed, when the library says more than info()
template <typename Solver> std::string failure_detail(const Solver &)
{
  return "";
}
template <typename Scalar> std::string failure_detail(const MumpsLdlt<Scalar> &solver)
{
  return solver.message();
}

struct Attempt {
  bool factorised = false;
  std::string detail;    // the library's explanation of a failure
  Eigen::VectorXcd x;
  double residual = 0.0;
};

}    // namespace

struct HelmholtzSolver::Factorisations {
  explicit Factorisations(MPI_Comm comm) : team(comm), mumps_real(team), mumps_complex(team) {}
  MumpsTeam team;
  MumpsLdlt<double> mumps_real;
  SparsityPattern mumps_real_pattern;
  MumpsLdlt<Complex> mumps_complex;
  SparsityPattern mumps_complex_pattern;
  CholmodLDLT ldlt;
  SparsityPattern ldlt_pattern;
  UmfpackLU<Eigen::SparseMatrix<double>> lu_real;
  SparsityPattern lu_real_pattern;
  UmfpackLU<Eigen::SparseMatrix<Complex>> lu_complex;
  SparsityPattern lu_complex_pattern;
  // Eigen's UMFPACK wrapper keeps a reference to the factorised matrix (its
  // solves refine with it): the matrices live here as long as their factors
  Eigen::SparseMatrix<double> lu_real_matrix;
  Eigen::SparseMatrix<Complex> lu_complex_matrix;

  // the factorisation of the last successful solve, its free DOFs and solution
  enum Kind { NONE, LDLT, LU_REAL, LU_COMPLEX, MUMPS_REAL, MUMPS_COMPLEX };
  Kind last = NONE;
  std::vector<int> last_free_dofs;
  Eigen::VectorXcd last_x;
};

namespace {

// Analyse (if the pattern changed), factorise, solve and measure the residual.
template <typename Solver, typename Scalar>
Attempt factorise_and_solve(Solver &solver, SparsityPattern &pattern, const Eigen::SparseMatrix<Scalar> &a,
                            const Eigen::VectorXcd &rhs, long &num_analyses, long &num_factorisations,
                            SolverTimings &timings)
{
  Attempt attempt;
  Clock::time_point start = Clock::now();
  if (!pattern.matches(a)) {
    solver.analyzePattern(a);
    if (solver.info() != Eigen::Success) {
      pattern = SparsityPattern();    // analyse again next time
      timings.analysis += seconds_since(start);
      attempt.detail = failure_detail(solver);
      return attempt;
    }
    pattern.store(a);
    ++num_analyses;
    timings.analysis += seconds_since(start);
    start = Clock::now();
  }
  solver.factorize(a);
  ++num_factorisations;
  timings.factorisation += seconds_since(start);
  if (numerically_singular(solver)) {
    attempt.detail = failure_detail(solver);
    return attempt;
  }
  attempt.factorised = true;

  start = Clock::now();
  attempt.x = solve_with(solver, rhs, Scalar());
  attempt.residual = relative_residual(a, attempt.x, rhs);
  timings.solve += seconds_since(start);
  return attempt;
}

// A factorisation of an earlier matrix used as the preconditioner of BiCGSTAB
// (the interface Eigen's iterative solvers expect of a preconditioner).
template <typename Scalar, typename Factor> class EarlierFactorisation {
 public:
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, 1> Vector;
  EarlierFactorisation() = default;
  template <typename MatrixType> explicit EarlierFactorisation(const MatrixType &) {}
  template <typename MatrixType> EarlierFactorisation &analyzePattern(const MatrixType &) { return *this; }
  template <typename MatrixType> EarlierFactorisation &factorize(const MatrixType &) { return *this; }
  template <typename MatrixType> EarlierFactorisation &compute(const MatrixType &) { return *this; }
  template <typename Rhs> Vector solve(const Rhs &b) const
  {
    const Vector rhs = b;
    return factor->solve(rhs);
  }
  Eigen::ComputationInfo info() const { return Eigen::Success; }
  const Factor *factor = nullptr;
};

// Solve a x = rhs by BiCGSTAB preconditioned with the factorisation of an
// earlier matrix, from the earlier solution; a small change of the network
// converges in a few iterations, each costing two triangular solves.
template <typename Factor, typename Scalar>
Attempt iterate_with_earlier_factors(const Factor &factor, const Eigen::SparseMatrix<Scalar> &a,
                                     const Eigen::VectorXcd &rhs, const Eigen::VectorXcd &guess,
                                     int max_iterations, double tolerance, SolverTimings &timings)
{
  Attempt attempt;
  const Clock::time_point start = Clock::now();
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Dense;
  Eigen::BiCGSTAB<Eigen::SparseMatrix<Scalar>, EarlierFactorisation<Scalar, Factor>> bicgstab;
  bicgstab.preconditioner().factor = &factor;
  bicgstab.setTolerance(tolerance);
  bicgstab.compute(a);
  const Dense b = as_columns(rhs, Scalar());
  const Dense x0 = as_columns(guess, Scalar());
  Dense x(b.rows(), b.cols());
  bool converged = true;
  for (Eigen::Index col = 0; col < b.cols(); ++col) {
    if (b.col(col).squaredNorm() == 0.0) {
      x.col(col).setZero();
      continue;
    }
    // one iteration first: a network that changed too much for the earlier
    // factors shows it at once, and is better factorised than iterated on
    const int first = std::min(1, max_iterations);
    bicgstab.setMaxIterations(first);
    x.col(col) = bicgstab.solveWithGuess(b.col(col), x0.col(col));
    if (bicgstab.info() != Eigen::Success && max_iterations > first && bicgstab.error() <= 1e-2) {
      bicgstab.setMaxIterations(max_iterations - first);
      const Dense guess = x.col(col);
      x.col(col) = bicgstab.solveWithGuess(b.col(col), guess);
    }
    converged = converged && bicgstab.info() == Eigen::Success;
    if (!converged) break;
  }
  if (converged) {
    attempt.factorised = true;
    attempt.x = from_columns(x);
    attempt.residual = relative_residual(a, attempt.x, rhs);
  }
  timings.solve += seconds_since(start);
  return attempt;
}

}    // namespace

LinearSolverChoice linear_solver_from_name(const std::string &name)
{
  if (name == "auto") return LinearSolverChoice::Auto;
  if (name == "ldlt") return LinearSolverChoice::Ldlt;
  if (name == "lu") return LinearSolverChoice::Lu;
  if (name == "mumps") return LinearSolverChoice::Mumps;
  if (name == "iterative") return LinearSolverChoice::Iterative;
  throw SolverError("unknown linear solver '" + name + "': allowed solvers are " + linear_solver_names());
}

std::string linear_solver_name(LinearSolverChoice choice)
{
  switch (choice) {
    case LinearSolverChoice::Ldlt:
      return "ldlt";
    case LinearSolverChoice::Lu:
      return "lu";
    case LinearSolverChoice::Mumps:
      return "mumps";
    case LinearSolverChoice::Iterative:
      return "iterative";
    default:
      return "auto";
  }
}

std::string linear_solver_names()
{
  return "auto, ldlt, lu, mumps, iterative";
}

std::string solve_status_name(SolveStatus status)
{
  switch (status) {
    case SolveStatus::FactorisationFailed:
      return "factorisation failed";
    case SolveStatus::InaccurateSolution:
      return "inaccurate solution";
    default:
      return "success";
  }
}

HelmholtzSolver::HelmholtzSolver(LinearSolverChoice choice, double residual_tolerance, MPI_Comm comm) :
    choice_(choice), residual_tolerance_(residual_tolerance), factors_(new Factorisations(comm))
{
  if (choice == LinearSolverChoice::Iterative)
    throw SolverError("Helmholtz solver: the iterative solver works on the distributed network; "
                      "use KrylovHelmholtzSolver");
  if (!(residual_tolerance > 0.0) || !std::isfinite(residual_tolerance))
    throw SolverError("Helmholtz solver: the residual tolerance must be positive, got " +
                      std::to_string(residual_tolerance));
}

HelmholtzSolver::~HelmholtzSolver() = default;

void HelmholtzSolver::serve()
{
  factors_->team.serve();
}

void HelmholtzSolver::release_workers()
{
  factors_->team.release();
}

bool HelmholtzSolver::host() const
{
  return factors_->team.host();
}

HelmholtzSolution HelmholtzSolver::solve(const Eigen::SparseMatrix<double> &stiffness,
                                         const Eigen::SparseMatrix<double> &damping, const Eigen::VectorXd &mass,
                                         double omega, const std::vector<int> &prescribed_dofs,
                                         const Eigen::VectorXcd &prescribed_values)
{
  timings_ = SolverTimings();
  const Clock::time_point start = Clock::now();
  if (!host()) throw SolverError("Helmholtz solve: called on a rank other than the host; call serve() there");

  const Eigen::Index n = stiffness.rows();
  if (stiffness.cols() != n) throw SolverError("Helmholtz solve: the stiffness matrix is not square");
  if (damping.size() != 0 && (damping.rows() != n || damping.cols() != n))
    throw SolverError("Helmholtz solve: the damping matrix must be empty or have the size of the stiffness matrix");
  if (mass.size() != n) throw SolverError("Helmholtz solve: the mass vector must have one entry per DOF");
  if (!(mass.array() > 0.0).all() || !mass.allFinite())
    throw SolverError("Helmholtz solve: every mass must be positive and finite");
  if (!std::isfinite(omega) || omega < 0.0)
    throw SolverError("Helmholtz solve: the angular frequency must be >= 0 and finite, got " + std::to_string(omega));
  if (n > 0 && !std::isfinite(omega * omega * mass.maxCoeff()))
    throw SolverError("Helmholtz solve: the frequency is out of range for this network: omega^2 m "
                      "exceeds the range of doubles (omega = " + number(omega) +
                      ", largest mass " + number(mass.maxCoeff()) +
                      "); give the frequency in 1/time units of the input script");
  if (damping.size() != 0 && damping.nonZeros() > 0 &&
      !std::isfinite(omega * damping.coeffs().cwiseAbs().maxCoeff()))
    throw SolverError("Helmholtz solve: the frequency is out of range for this network: omega c "
                      "exceeds the range of doubles for the largest dashpot c; lower the frequency "
                      "or the damping ratio");
  if (prescribed_values.size() != static_cast<Eigen::Index>(prescribed_dofs.size()))
    throw SolverError("Helmholtz solve: give one prescribed value per prescribed DOF");
  if (!prescribed_values.allFinite()) throw SolverError("Helmholtz solve: a prescribed value is not finite");

  bool damped = false;
  if (omega > 0.0 && damping.size() != 0)
    for (Eigen::Index k = 0; k < damping.nonZeros(); ++k)
      if (damping.valuePtr()[k] != 0.0) damped = true;
  if (damped && choice_ == LinearSolverChoice::Ldlt)
    throw SolverError("Helmholtz solve: solver ldlt needs an undamped problem (the damped matrix is complex "
                      "symmetric); use solver auto or lu, or damping 0");

  const DofPartition part = partition_dofs(static_cast<int>(n), prescribed_dofs);
  const int nfree = static_cast<int>(part.free_dofs.size());

  HelmholtzSolution result;
  result.q = Eigen::VectorXcd::Zero(n);
  for (std::size_t k = 0; k < prescribed_dofs.size(); ++k) result.q[prescribed_dofs[k]] = prescribed_values[k];
  result.factorisation = "none";

  Eigen::VectorXcd rhs;
  Attempt attempt;
  bool rhs_zero = false;
  Factorisations &f = *factors_;
  // an earlier factorisation can precondition this solve if the free DOFs are the
  // same and few of them changed contacts: BiCGSTAB then needs about as many
  // iterations as there are changed columns
  bool can_reuse = reuse_ && f.last != Factorisations::NONE && f.last_free_dofs == part.free_dofs;
  // after an attempt that did not converge, factorise directly for a few solves
  if (reuse_backoff_ > 0) {
    --reuse_backoff_;
    can_reuse = false;
  }
  auto few_changes = [&](Eigen::Index changed) {
    const Eigen::Index limit = std::min<Eigen::Index>(100, static_cast<Eigen::Index>(reuse_fraction_ * nfree));
    return changed <= std::max<Eigen::Index>(4, limit);
  };
  const double reuse_tolerance = 1e-2 * residual_tolerance_;
  Factorisations::Kind used = Factorisations::NONE;
  bool iterated = false, tried_reuse = false, previous_solution = false;
  // the last solution may still solve this system to the reuse tolerance (the
  // same network, or the same up to round-off, e.g. at the setup of a run that
  // starts at the step of the last update): one product A x, no factorisation,
  // whatever the back-off
  auto previous_solution_applies = [&]() {
    return reuse_ && f.last != Factorisations::NONE && f.last_free_dofs == part.free_dofs;
  };
  auto take_previous_solution = [&](double residual) {
    if (!(residual <= reuse_tolerance)) return false;
    previous_solution = true;
    used = f.last;
    attempt.factorised = true;
    attempt.x = f.last_x;
    attempt.residual = residual;
    return true;
  };
  if (damped) {
    Eigen::SparseMatrix<Complex> a;
    assemble_free_system<Complex>(stiffness, &damping, Complex(0.0, omega), mass, omega, part, prescribed_values, a, rhs);
    timings_.solve += seconds_since(start);
    rhs_zero = rhs.squaredNorm() == 0.0;
    if (nfree > 0 && !rhs_zero) {
      if (previous_solution_applies() && take_previous_solution(relative_residual(a, f.last_x, rhs))) {
      } else if (can_reuse && f.last == Factorisations::LU_COMPLEX &&
          few_changes(f.lu_complex_pattern.changed_columns(a))) {
        tried_reuse = true;
        attempt = iterate_with_earlier_factors(f.lu_complex, a, rhs, f.last_x, reuse_iterations_,
                                               reuse_tolerance, timings_);
        if (attempt.factorised && attempt.residual <= residual_tolerance_) used = f.last;
      } else if (can_reuse && f.last == Factorisations::MUMPS_COMPLEX &&
                 few_changes(f.mumps_complex_pattern.changed_columns(a))) {
        tried_reuse = true;
        attempt = iterate_with_earlier_factors(f.mumps_complex, a, rhs, f.last_x, reuse_iterations_,
                                               reuse_tolerance, timings_);
        if (attempt.factorised && attempt.residual <= residual_tolerance_) used = f.last;
      }
      iterated = (used != Factorisations::NONE);
      if (!iterated && choice_ == LinearSolverChoice::Lu) {
        used = Factorisations::LU_COMPLEX;
        f.lu_complex_matrix = a;
        attempt = factorise_and_solve(f.lu_complex, f.lu_complex_pattern, f.lu_complex_matrix, rhs,
                                      num_analyses_, num_factorisations_, timings_);
      } else if (!iterated) {
        used = Factorisations::MUMPS_COMPLEX;
        attempt = factorise_and_solve(f.mumps_complex, f.mumps_complex_pattern, a, rhs, num_analyses_,
                                      num_factorisations_, timings_);
      } else {
        ++num_reuses_;
      }
    }
  } else {
    Eigen::SparseMatrix<double> a;
    assemble_free_system<double>(stiffness, nullptr, 0.0, mass, omega, part, prescribed_values, a, rhs);
    timings_.solve += seconds_since(start);
    rhs_zero = rhs.squaredNorm() == 0.0;
    if (nfree > 0 && !rhs_zero) {
      const Eigen::Index changed = !can_reuse                        ? nfree
          : (f.last == Factorisations::LDLT)      ? f.ldlt_pattern.changed_columns(a)
          : (f.last == Factorisations::MUMPS_REAL) ? f.mumps_real_pattern.changed_columns(a)
                                                  : f.lu_real_pattern.changed_columns(a);
      if (previous_solution_applies() && take_previous_solution(relative_residual(a, f.last_x, rhs))) {
      } else if (can_reuse &&
                 (f.last == Factorisations::LDLT || f.last == Factorisations::LU_REAL ||
                  f.last == Factorisations::MUMPS_REAL) &&
                 few_changes(changed)) {
        tried_reuse = true;
        if (f.last == Factorisations::LDLT)
          attempt = iterate_with_earlier_factors(f.ldlt, a, rhs, f.last_x, reuse_iterations_,
                                                 reuse_tolerance, timings_);
        else if (f.last == Factorisations::MUMPS_REAL)
          attempt = iterate_with_earlier_factors(f.mumps_real, a, rhs, f.last_x, reuse_iterations_,
                                                 reuse_tolerance, timings_);
        else
          attempt = iterate_with_earlier_factors(f.lu_real, a, rhs, f.last_x, reuse_iterations_,
                                                 reuse_tolerance, timings_);
        if (attempt.factorised && attempt.residual <= residual_tolerance_) used = f.last;
      }
      iterated = (used != Factorisations::NONE);
      if (iterated) {
        ++num_reuses_;
      } else {
        if (choice_ == LinearSolverChoice::Ldlt) {
          used = Factorisations::LDLT;
          attempt = factorise_and_solve(f.ldlt, f.ldlt_pattern, a, rhs, num_analyses_, num_factorisations_,
                                        timings_);
        } else if (choice_ == LinearSolverChoice::Mumps || choice_ == LinearSolverChoice::Auto) {
          used = Factorisations::MUMPS_REAL;
          attempt = factorise_and_solve(f.mumps_real, f.mumps_real_pattern, a, rhs, num_analyses_,
                                        num_factorisations_, timings_);
        } else {
          used = Factorisations::LU_REAL;
          f.lu_real_matrix = a;
          attempt = factorise_and_solve(f.lu_real, f.lu_real_pattern, f.lu_real_matrix, rhs,
                                        num_analyses_, num_factorisations_, timings_);
        }
      }
    }
  }
  if (nfree == 0 || rhs_zero) return result;
  switch (used) {
    case Factorisations::LDLT:
      result.factorisation = "ldlt";
      break;
    case Factorisations::LU_REAL:
    case Factorisations::LU_COMPLEX:
      result.factorisation = "lu";
      break;
    case Factorisations::MUMPS_REAL:
    case Factorisations::MUMPS_COMPLEX:
      result.factorisation = "mumps";
      break;
    default:
      break;
  }
  if (previous_solution)
    result.factorisation += " (earlier solution)";
  else if (iterated)
    result.factorisation += " (earlier factors, BiCGSTAB)";
  // after a failed attempt factorise directly for the next 4, 8, 16 ... 64 solves
  if (tried_reuse && !iterated) {
    reuse_failures_ = std::min(reuse_failures_ + 1, 5);
    reuse_backoff_ = 2 << reuse_failures_;
  } else if (iterated && !previous_solution) {
    reuse_failures_ = 0;
  }
  // remember a good factorisation and its solution for the next solve
  if (attempt.factorised && attempt.x.allFinite() && attempt.residual <= residual_tolerance_) {
    f.last = used;
    f.last_free_dofs = part.free_dofs;
    f.last_x = attempt.x;
  } else {
    f.last = Factorisations::NONE;
  }

  const std::string where = " (omega = " + std::to_string(omega) + ", " + std::to_string(nfree) +
      " free DOFs, factorisation " + result.factorisation + ")";
  if (!attempt.factorised) {
    result.status = SolveStatus::FactorisationFailed;
    result.relative_residual = 1.0;    // residual of the returned q_F = 0
    result.message = "the Helmholtz matrix is singular" + where +
        ": the frequency is an eigenfrequency of the network, or (at omega = 0) part of the network "
        "is not held by the source; change the frequency, add damping, or fix the floating grains";
    if (!attempt.detail.empty()) result.message += " [" + attempt.detail + "]";
    return result;
  }
  result.relative_residual = attempt.residual;
  if (!std::isfinite(attempt.residual) || !attempt.x.allFinite()) {
    result.status = SolveStatus::InaccurateSolution;
    result.relative_residual = 1.0;
    result.message = "the Helmholtz solution is not finite" + where +
        ": the matrix is numerically singular; change the frequency or add damping";
    return result;
  }
  for (int k = 0; k < nfree; ++k) result.q[part.free_dofs[k]] = attempt.x[k];
  if (attempt.residual > residual_tolerance_) {
    result.status = SolveStatus::InaccurateSolution;
    result.message = "the relative residual " + std::to_string(attempt.residual) + " exceeds the tolerance " +
        std::to_string(residual_tolerance_) + where +
        ": the frequency is close to an eigenfrequency of the network; try another solver, another "
        "frequency, or some damping";
  }
  return result;
}

}    // namespace Acoustic
