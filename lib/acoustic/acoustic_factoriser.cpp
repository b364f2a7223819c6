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
   ACOUSTIC package numerics: the sparse factorisations behind one
   interface (MUMPS, UMFPACK, CHOLMOD).
------------------------------------------------------------------------- */

#include "acoustic_factoriser.h"

#include "acoustic_solver_error.h"

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>

namespace Acoustic {

namespace {

  using Complex = std::complex<double>;

  // x = A^-1 b with a factorisation of A: real factors solve for the real and the
  // imaginary part of b, leaving out a part that is zero (a drive in phase
  // everywhere has no imaginary part: one triangular solve instead of two)
  template <typename Solver>
  Eigen::VectorXcd solve_real(const Solver &solver, const Eigen::VectorXcd &b)
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

  template <typename Solver>
  Eigen::VectorXcd solve_scalar(const Solver &solver, const Eigen::VectorXcd &b, double)
  {
    return solve_real(solver, b);
  }
  template <typename Solver>
  Eigen::VectorXcd solve_scalar(const Solver &solver, const Eigen::VectorXcd &b, Complex)
  {
    return solver.solve(b);
  }

  // MUMPS LDL^T on the team's ranks
  template <typename Scalar> class MumpsFactoriser : public Factoriser<Scalar> {
   public:
    MumpsFactoriser(MumpsTeam &team, const MumpsSettings &settings) : mumps_(team, settings) {}
    std::string name() const override { return "mumps"; }
    bool analyse(const typename Factoriser<Scalar>::Matrix &a) override
    {
      mumps_.analyzePattern(a);
      return mumps_.info() == Eigen::Success;
    }
    bool factorise(const typename Factoriser<Scalar>::Matrix &a) override
    {
      mumps_.factorize(a);
      return mumps_.info() == Eigen::Success;
    }
    Eigen::VectorXcd solve(const Eigen::VectorXcd &b) const override
    {
      return solve_scalar(mumps_, b, Scalar());
    }
    std::string detail() const override { return mumps_.message(); }
    double flops() const override { return mumps_.factorisation_flops(); }

   private:
    MumpsLdlt<Scalar> mumps_;
  };

  // UMFPACK LU, without iterative refinement (the caller measures the residual)
  template <typename Scalar> class UmfpackFactoriser : public Factoriser<Scalar> {
   public:
    typedef Eigen::SparseMatrix<Scalar> Matrix;
    UmfpackFactoriser() { lu_.umfpackControl()(UMFPACK_IRSTEP) = 0; }
    std::string name() const override { return "lu"; }
    bool analyse(const Matrix &a) override
    {
      matrix_ = a;
      lu_.analyzePattern(matrix_);
      return lu_.info() == Eigen::Success;
    }
    bool factorise(const Matrix &a) override
    {
      // Eigen's UMFPACK wrapper keeps a reference to the factorised matrix
      matrix_ = a;
      lu_.factorize(matrix_);
      return lu_.info() == Eigen::Success && !lu_.singular();
    }
    Eigen::VectorXcd solve(const Eigen::VectorXcd &b) const override
    {
      return solve_scalar(lu_, b, Scalar());
    }

   private:
    // UMFPACK LU that also reports whether the matrix was found singular
    class Lu : public Eigen::UmfPackLU<Matrix> {
     public:
      bool singular() const { return this->m_fact_errorCode == UMFPACK_WARNING_singular_matrix; }
    };
    Lu lu_;
    Matrix matrix_;
  };

  // CHOLMOD simplicial LDL^T of the lower triangle, silent on zero pivots
  class CholmodFactoriser : public Factoriser<double> {
   public:
    CholmodFactoriser()
    {
      ldlt_.cholmod().print = 0;
      // one fill-reducing ordering (AMD) instead of CHOLMOD's default search over
      // AMD, METIS and NESDIS: the analysis is redone whenever contacts change
      ldlt_.cholmod().nmethods = 1;
      ldlt_.cholmod().method[0].ordering = CHOLMOD_AMD;
      ldlt_.cholmod().postorder = 1;
    }
    std::string name() const override { return "ldlt"; }
    bool analyse(const Matrix &a) override
    {
      ldlt_.analyzePattern(a);
      return ldlt_.info() == Eigen::Success;
    }
    bool factorise(const Matrix &a) override
    {
      ldlt_.factorize(a);
      return ldlt_.info() == Eigen::Success;
    }
    Eigen::VectorXcd solve(const Eigen::VectorXcd &b) const override
    {
      return solve_real(ldlt_, b);
    }

   private:
    Eigen::CholmodSimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt_;
  };

}    // namespace

template <>
std::unique_ptr<Factoriser<double>>
make_factoriser<double>(LinearSolverChoice choice, MumpsTeam &team, const MumpsSettings &settings)
{
  switch (choice) {
    case LinearSolverChoice::Ldlt:
      return std::unique_ptr<Factoriser<double>>(new CholmodFactoriser());
    case LinearSolverChoice::Lu:
      return std::unique_ptr<Factoriser<double>>(new UmfpackFactoriser<double>());
    case LinearSolverChoice::Auto:
      // without MUMPS: UMFPACK's LU, which pivots (indefinite matrices too)
      if (!mumps_available())
        return std::unique_ptr<Factoriser<double>>(new UmfpackFactoriser<double>());
      return std::unique_ptr<Factoriser<double>>(new MumpsFactoriser<double>(team, settings));
    case LinearSolverChoice::Mumps:
      return std::unique_ptr<Factoriser<double>>(new MumpsFactoriser<double>(team, settings));
    default:
      return nullptr;
  }
}

template <>
std::unique_ptr<Factoriser<Complex>>
make_factoriser<Complex>(LinearSolverChoice choice, MumpsTeam &team, const MumpsSettings &settings)
{
  switch (choice) {
    case LinearSolverChoice::Lu:
      return std::unique_ptr<Factoriser<Complex>>(new UmfpackFactoriser<Complex>());
    case LinearSolverChoice::Auto:
      // without MUMPS: UMFPACK's LU, which pivots (indefinite matrices too)
      if (!mumps_available())
        return std::unique_ptr<Factoriser<Complex>>(new UmfpackFactoriser<Complex>());
      return std::unique_ptr<Factoriser<Complex>>(new MumpsFactoriser<Complex>(team, settings));
    case LinearSolverChoice::Mumps:
      return std::unique_ptr<Factoriser<Complex>>(new MumpsFactoriser<Complex>(team, settings));
    default:
      return nullptr;    // ldlt: real symmetric matrices only
  }
}

}    // namespace Acoustic
