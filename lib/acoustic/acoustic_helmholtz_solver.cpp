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
   ACOUSTIC package numerics: steady harmonic response (Helmholtz problem).
------------------------------------------------------------------------- */

#include "acoustic_helmholtz_solver.h"

#include "acoustic_factoriser.h"
#include "acoustic_mumps_ldlt.h"
#include "acoustic_solver_error.h"

#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>

namespace Acoustic {

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
  template <typename Scalar>
  Eigen::Index changed_columns(const Eigen::SparseMatrix<Scalar> &a) const
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
        throw SolverError("Helmholtz solve: prescribed DOF " + std::to_string(dof) +
                          " is outside 0.." + std::to_string(num_dofs - 1));
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
  void move_to_rhs(const Eigen::SparseMatrix<double> &s, int col, Scalar coeff,
                   const DofPartition &part, const Complex &value, Eigen::VectorXcd &rhs)
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
  void assemble_free_system(const Eigen::SparseMatrix<double> &stiffness,
                            const Eigen::SparseMatrix<double> *damping, Scalar damping_coeff,
                            const Eigen::VectorXd &mass, double omega, const DofPartition &part,
                            const Eigen::VectorXcd &values, Eigen::SparseMatrix<Scalar> &a,
                            Eigen::VectorXcd &rhs)
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
    a = Eigen::Map<const Eigen::SparseMatrix<Scalar>>(nfree, nfree,
                                                      static_cast<Eigen::Index>(inner.size()),
                                                      outer.data(), inner.data(), entries.data());
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
  double relative_residual(const Eigen::SparseMatrix<Scalar> &a, const Eigen::VectorXcd &x,
                           const Eigen::VectorXcd &b)
  {
    const double residual = (multiply(a, x) - b).norm() / b.norm();
    return std::isfinite(residual) ? residual : std::numeric_limits<double>::infinity();
  }

  // the scalar type's part of a complex vector (real part for double)
  template <typename Scalar>
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> to_scalar(const Eigen::VectorXcd &x);
  template <> Eigen::VectorXd to_scalar<double>(const Eigen::VectorXcd &x)
  {
    return x.real();
  }
  template <> Eigen::VectorXcd to_scalar<Complex>(const Eigen::VectorXcd &x)
  {
    return x;
  }

  // the columns a real system solves for a complex right-hand side: [Re b, Im b];
  // one column for a complex system
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

  // The outcome of one way of answering a solve.
  struct Attempt {
    bool solved = false;    // x holds a solution (its residual may still be too large)
    std::string detail;     // the library's explanation of a failed factorisation
    Eigen::VectorXcd x;
    double residual = 0.0;
  };

  // Analyse (if the pattern changed), factorise, solve and measure the residual.
  template <typename Scalar>
  Attempt factorise_and_solve(Factoriser<Scalar> &factoriser, SparsityPattern &pattern,
                              const Eigen::SparseMatrix<Scalar> &a, const Eigen::VectorXcd &rhs,
                              long &num_analyses, long &num_factorisations, double &flops,
                              SolverTimings &timings)
  {
    Attempt attempt;
    Clock::time_point start = Clock::now();
    if (!pattern.matches(a)) {
      const bool analysed = factoriser.analyse(a);
      timings.analysis += seconds_since(start);
      if (!analysed) {
        pattern = SparsityPattern();    // analyse again next time
        attempt.detail = factoriser.detail();
        return attempt;
      }
      pattern.store(a);
      ++num_analyses;
      start = Clock::now();
    }
    const bool factorised = factoriser.factorise(a);
    ++num_factorisations;
    flops = factoriser.flops();
    timings.factorisation += seconds_since(start);
    if (!factorised) {
      attempt.detail = factoriser.detail();
      return attempt;
    }
    start = Clock::now();
    attempt.solved = true;
    attempt.x = factoriser.solve(rhs);
    attempt.residual = relative_residual(a, attempt.x, rhs);
    timings.solve += seconds_since(start);
    return attempt;
  }

  // The factors of an earlier matrix as the preconditioner of BiCGSTAB (the
  // interface Eigen's iterative solvers expect of a preconditioner).
  template <typename Scalar> class EarlierFactors {
   public:
    typedef Eigen::Matrix<Scalar, Eigen::Dynamic, 1> Vector;
    EarlierFactors() = default;
    template <typename MatrixType> explicit EarlierFactors(const MatrixType &) {}
    template <typename MatrixType> EarlierFactors &analyzePattern(const MatrixType &)
    {
      return *this;
    }
    template <typename MatrixType> EarlierFactors &factorize(const MatrixType &) { return *this; }
    template <typename MatrixType> EarlierFactors &compute(const MatrixType &) { return *this; }
    template <typename Rhs> Vector solve(const Rhs &b) const
    {
      const Eigen::VectorXcd rhs = Vector(b).template cast<Complex>();
      return to_scalar<Scalar>(factors->solve(rhs));
    }
    Eigen::ComputationInfo info() const { return Eigen::Success; }
    const Factoriser<Scalar> *factors = nullptr;
  };

  // Solve a x = rhs by BiCGSTAB preconditioned with the factors of an earlier
  // matrix, from the earlier solution; a small change of the network converges
  // in a few iterations, each costing two triangular solves.
  template <typename Scalar>
  Attempt iterate_with_earlier_factors(const Factoriser<Scalar> &factors,
                                       const Eigen::SparseMatrix<Scalar> &a,
                                       const Eigen::VectorXcd &rhs, const Eigen::VectorXcd &guess,
                                       int max_iterations, double tolerance, SolverTimings &timings)
  {
    Attempt attempt;
    const Clock::time_point start = Clock::now();
    typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Dense;
    Eigen::BiCGSTAB<Eigen::SparseMatrix<Scalar>, EarlierFactors<Scalar>> bicgstab;
    bicgstab.preconditioner().factors = &factors;
    bicgstab.setTolerance(tolerance);
    bicgstab.compute(a);
    const Dense b = as_columns(rhs, Scalar());
    const Dense x0 = as_columns(guess, Scalar());
    Dense x(b.rows(), b.cols());
    bool converged = true;
    for (Eigen::Index col = 0; col < b.cols() && converged; ++col) {
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
        const Dense start_guess = x.col(col);
        x.col(col) = bicgstab.solveWithGuess(b.col(col), start_guess);
      }
      converged = bicgstab.info() == Eigen::Success;
    }
    if (converged) {
      attempt.solved = true;
      attempt.x = from_columns(x);
      attempt.residual = relative_residual(a, attempt.x, rhs);
    }
    timings.solve += seconds_since(start);
    return attempt;
  }

  // The input of a solve, checked; throws SolverError with what is wrong.
  void check_input(LinearSolverChoice choice_, const Eigen::SparseMatrix<double> &stiffness,
                   const Eigen::SparseMatrix<double> &damping, const Eigen::VectorXd &mass,
                   double omega, const std::vector<int> &prescribed_dofs,
                   const Eigen::VectorXcd &prescribed_values, bool &damped)
  {

    const Eigen::Index n = stiffness.rows();
    if (stiffness.cols() != n)
      throw SolverError("Helmholtz solve: the stiffness matrix is not square");
    if (damping.size() != 0 && (damping.rows() != n || damping.cols() != n))
      throw SolverError("Helmholtz solve: the damping matrix must be empty or have the size of the "
                        "stiffness matrix");
    if (mass.size() != n)
      throw SolverError("Helmholtz solve: the mass vector must have one entry per DOF");
    if (!(mass.array() > 0.0).all() || !mass.allFinite())
      throw SolverError("Helmholtz solve: every mass must be positive and finite");
    if (!std::isfinite(omega) || omega < 0.0)
      throw SolverError("Helmholtz solve: the angular frequency must be >= 0 and finite, got " +
                        std::to_string(omega));
    if (n > 0 && !std::isfinite(omega * omega * mass.maxCoeff()))
      throw SolverError(
          "Helmholtz solve: the frequency is out of range for this network: omega^2 m "
          "exceeds the range of doubles (omega = " +
          number(omega) + ", largest mass " + number(mass.maxCoeff()) +
          "); give the frequency in 1/time units of the input script");
    if (damping.size() != 0 && damping.nonZeros() > 0 &&
        !std::isfinite(omega * damping.coeffs().cwiseAbs().maxCoeff()))
      throw SolverError(
          "Helmholtz solve: the frequency is out of range for this network: omega c "
          "exceeds the range of doubles for the largest dashpot c; lower the frequency "
          "or the damping ratio");
    if (prescribed_values.size() != static_cast<Eigen::Index>(prescribed_dofs.size()))
      throw SolverError("Helmholtz solve: give one prescribed value per prescribed DOF");
    if (!prescribed_values.allFinite())
      throw SolverError("Helmholtz solve: a prescribed value is not finite");

    damped = false;
    if (omega > 0.0 && damping.size() != 0)
      for (Eigen::Index k = 0; k < damping.nonZeros(); ++k)
        if (damping.valuePtr()[k] != 0.0) damped = true;
    if (damped && choice_ == LinearSolverChoice::Ldlt)
      throw SolverError(
          "Helmholtz solve: solver ldlt needs an undamped problem (the damped matrix is complex "
          "symmetric); use solver auto or lu, or damping 0");
  }

}    // namespace

// How an earlier solve may answer this one (reuse on), for the real and the
// complex systems alike: by its solution, if it still solves the new system;
// else by BiCGSTAB preconditioned with its factors, if few columns changed
// pattern; else the matrix is factorised.  A failed attempt with earlier
// factors makes the next 4, then 8, 16 ... 64 solves factorise directly.
struct HelmholtzSolver::ReusePolicy {
  enum Kind { NONE, REAL, COMPLEX };
  Kind last = NONE;    // the system of the last successful solve
  std::vector<int> last_free_dofs;
  Eigen::VectorXcd last_x;
  int backoff = 0;
  int failures = 0;

  bool previous_applies(bool reuse, Kind kind, const std::vector<int> &free_dofs) const
  {
    return reuse && last == kind && last_free_dofs == free_dofs;
  }
  // may earlier factors precondition this solve?  (consumes one back-off step)
  bool earlier_factors_apply(bool reuse, Kind kind, const std::vector<int> &free_dofs,
                             Eigen::Index changed, Eigen::Index nfree, double changed_fraction)
  {
    if (!previous_applies(reuse, kind, free_dofs)) return false;
    if (backoff > 0) {
      --backoff;
      return false;
    }
    const Eigen::Index limit =
        std::min<Eigen::Index>(100, static_cast<Eigen::Index>(changed_fraction * nfree));
    return changed <= std::max<Eigen::Index>(4, limit);
  }
  void attempt_with_earlier_factors(bool succeeded)
  {
    if (succeeded) {
      failures = 0;
      return;
    }
    failures = std::min(failures + 1, 5);
    backoff = 2 << failures;
  }
  void remember(bool good, Kind kind, const std::vector<int> &free_dofs, const Eigen::VectorXcd &x)
  {
    if (!good) {
      last = NONE;
      return;
    }
    last = kind;
    last_free_dofs = free_dofs;
    last_x = x;
  }
};

struct HelmholtzSolver::Factorisations {
  Factorisations(LinearSolverChoice choice, MPI_Comm comm, const MumpsSettings &settings) :
      team(comm), real(make_factoriser<double>(choice, team, settings)),
      complex(make_factoriser<Complex>(choice, team, settings))
  {
  }
  MumpsTeam team;
  std::unique_ptr<Factoriser<double>> real;
  SparsityPattern real_pattern;
  std::unique_ptr<Factoriser<Complex>> complex;    // none for ldlt
  SparsityPattern complex_pattern;
  double last_flops = 0.0;
};

LinearSolverChoice linear_solver_from_name(const std::string &name)
{
  if (name == "auto") return LinearSolverChoice::Auto;
  if (name == "ldlt") return LinearSolverChoice::Ldlt;
  if (name == "lu") return LinearSolverChoice::Lu;
  if (name == "mumps") return LinearSolverChoice::Mumps;
  if (name == "iterative") return LinearSolverChoice::Iterative;
  throw SolverError("unknown linear solver '" + name + "': allowed solvers are " +
                    linear_solver_names());
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

HelmholtzSolver::HelmholtzSolver(LinearSolverChoice choice, double residual_tolerance,
                                 MPI_Comm comm) :
    HelmholtzSolver(choice, residual_tolerance, comm, MumpsSettings())
{
}

HelmholtzSolver::HelmholtzSolver(LinearSolverChoice choice, double residual_tolerance,
                                 MPI_Comm comm, const MumpsSettings &mumps) :
    choice_(choice),
    residual_tolerance_(residual_tolerance)
{
  if (choice == LinearSolverChoice::Iterative)
    throw SolverError("Helmholtz solver: the iterative solver works on the distributed network; "
                      "use KrylovHelmholtzSolver");
  if (!(residual_tolerance > 0.0) || !std::isfinite(residual_tolerance))
    throw SolverError("Helmholtz solver: the residual tolerance must be positive, got " +
                      std::to_string(residual_tolerance));
  factors_.reset(new Factorisations(choice, comm, mumps));
  policy_.reset(new ReusePolicy());
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

double HelmholtzSolver::last_factorisation_flops() const
{
  return factors_->last_flops;
}

// One free-free system, real or complex: the earlier solution, the earlier
// factors with BiCGSTAB, or a factorisation, as the reuse policy allows.
template <typename Scalar>
HelmholtzSolution
HelmholtzSolver::solve_system(Factoriser<Scalar> &factoriser, SparsityPattern &pattern,
                              const Eigen::SparseMatrix<Scalar> &a, const Eigen::VectorXcd &rhs,
                              const std::vector<int> &free_dofs, int kind)
{
  ReusePolicy &policy = *policy_;
  const ReusePolicy::Kind system = static_cast<ReusePolicy::Kind>(kind);
  const Eigen::Index nfree = static_cast<Eigen::Index>(free_dofs.size());
  const double reuse_tolerance = 1e-2 * residual_tolerance_;
  HelmholtzSolution result;
  result.factorisation = factoriser.name();
  Attempt attempt;
  bool answered = false;

  // the last solution may still solve this system (the same network, or the
  // same up to round-off): one product A x, whatever the back-off
  if (policy.previous_applies(reuse_, system, free_dofs)) {
    const double residual = relative_residual(a, policy.last_x, rhs);
    if (residual <= reuse_tolerance) {
      attempt.solved = true;
      attempt.x = policy.last_x;
      attempt.residual = residual;
      answered = true;
      ++num_reuses_;
      result.factorisation += " (earlier solution)";
    }
  }
  if (!answered &&
      policy.earlier_factors_apply(reuse_, system, free_dofs, pattern.changed_columns(a), nfree,
                                   reuse_fraction_)) {
    attempt = iterate_with_earlier_factors(factoriser, a, rhs, policy.last_x, reuse_iterations_,
                                           reuse_tolerance, timings_);
    answered = attempt.solved && attempt.residual <= residual_tolerance_;
    policy.attempt_with_earlier_factors(answered);
    if (answered) {
      ++num_reuses_;
      result.factorisation += " (earlier factors, BiCGSTAB)";
    }
  }
  if (!answered)
    attempt = factorise_and_solve(factoriser, pattern, a, rhs, num_analyses_, num_factorisations_,
                                  factors_->last_flops, timings_);
  policy.remember(attempt.solved && attempt.x.allFinite() &&
                      attempt.residual <= residual_tolerance_,
                  system, free_dofs, attempt.x);

  const std::string where =
      " (" + std::to_string(nfree) + " free DOFs, factorisation " + result.factorisation + ")";
  if (!attempt.solved) {
    result.status = SolveStatus::FactorisationFailed;
    result.relative_residual = 1.0;    // residual of the returned q_F = 0
    result.message = "the Helmholtz matrix is singular" + where +
        ": the frequency is an eigenfrequency of the network, or (at omega = 0) part of the "
        "network "
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
  result.q = attempt.x;    // the free DOFs; the caller places them
  if (attempt.residual > residual_tolerance_) {
    result.status = SolveStatus::InaccurateSolution;
    result.message = "the relative residual " + std::to_string(attempt.residual) +
        " exceeds the tolerance " + std::to_string(residual_tolerance_) + where +
        ": the frequency is close to an eigenfrequency of the network; try another solver, another "
        "frequency, or some damping";
  }
  return result;
}

HelmholtzSolution HelmholtzSolver::solve(const Eigen::SparseMatrix<double> &stiffness,
                                         const Eigen::SparseMatrix<double> &damping,
                                         const Eigen::VectorXd &mass, double omega,
                                         const std::vector<int> &prescribed_dofs,
                                         const Eigen::VectorXcd &prescribed_values)
{
  timings_ = SolverTimings();
  const Clock::time_point start = Clock::now();
  if (!host())
    throw SolverError("Helmholtz solve: called on a rank other than the host; call serve() there");
  bool damped = false;
  check_input(choice_, stiffness, damping, mass, omega, prescribed_dofs, prescribed_values, damped);
  const Eigen::Index n = stiffness.rows();
  const DofPartition part = partition_dofs(static_cast<int>(n), prescribed_dofs);
  const int nfree = static_cast<int>(part.free_dofs.size());

  HelmholtzSolution result;
  Eigen::VectorXcd rhs;
  if (damped) {
    Eigen::SparseMatrix<Complex> a;
    assemble_free_system<Complex>(stiffness, &damping, Complex(0.0, omega), mass, omega, part,
                                  prescribed_values, a, rhs);
    timings_.solve += seconds_since(start);
    if (nfree > 0 && rhs.squaredNorm() > 0.0)
      result = solve_system(*factors_->complex, factors_->complex_pattern, a, rhs, part.free_dofs,
                            ReusePolicy::COMPLEX);
  } else {
    Eigen::SparseMatrix<double> a;
    assemble_free_system<double>(stiffness, nullptr, 0.0, mass, omega, part, prescribed_values, a,
                                 rhs);
    timings_.solve += seconds_since(start);
    if (nfree > 0 && rhs.squaredNorm() > 0.0)
      result = solve_system(*factors_->real, factors_->real_pattern, a, rhs, part.free_dofs,
                            ReusePolicy::REAL);
  }
  if (nfree == 0 || rhs.squaredNorm() == 0.0) result.factorisation = "none";    // q_F = 0

  // every DOF: the prescribed values and the free ones solved (0 if the solve failed)
  const Eigen::VectorXcd free_values = result.q;
  result.q = Eigen::VectorXcd::Zero(n);
  for (std::size_t k = 0; k < prescribed_dofs.size(); ++k)
    result.q[prescribed_dofs[k]] = prescribed_values[k];
  if (free_values.size() == nfree)
    for (int k = 0; k < nfree; ++k) result.q[part.free_dofs[k]] = free_values[k];
  return result;
}

}    // namespace Acoustic
