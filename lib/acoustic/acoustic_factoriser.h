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
   ACOUSTIC package numerics: one interface for the sparse factorisations
   of the Helmholtz solver.

   A Factoriser<Scalar> factorises a sparse symmetric matrix the way
   Eigen's sparse solvers do: analyse (symbolic analysis, fill-reducing
   ordering) for a sparsity pattern, factorise (numeric factorisation of a
   matrix of that pattern), solve with the last factors.  Scalar is double
   (undamped: K - omega^2 M) or std::complex<double> (damped); a real
   factorisation solves a complex right-hand side by its real and imaginary
   parts.  Implementations:
     mumps  MUMPS LDL^T with 2x2 pivots (MumpsLdlt), on a team of ranks
     lu     UMFPACK LU with partial pivoting, on the calling rank
     ldlt   CHOLMOD simplicial LDL^T without pivoting, real only
   make_factoriser() builds the one a LinearSolverChoice names (auto is
   mumps, or lu in a build without MUMPS), or returns nullptr where there is none (ldlt, complex).
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_FACTORISER_H
#define ACOUSTIC_FACTORISER_H

#include "acoustic_helmholtz_solver.h"
#include "acoustic_mumps_ldlt.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>
#include <memory>
#include <string>

namespace Acoustic {

template <typename Scalar> class Factoriser {
 public:
  typedef Eigen::SparseMatrix<Scalar> Matrix;
  virtual ~Factoriser() = default;
  // "mumps", "lu" or "ldlt"
  virtual std::string name() const = 0;
  // symbolic analysis of the pattern of a (both triangles stored); false if it failed
  virtual bool analyse(const Matrix &a) = 0;
  // numeric factorisation of a, whose pattern was analysed; false if a is
  // (numerically) singular or the library failed
  virtual bool factorise(const Matrix &a) = 0;
  // x = A^-1 b with the last factors
  virtual Eigen::VectorXcd solve(const Eigen::VectorXcd &b) const = 0;
  // the library's explanation of the last failure ("" if it gives none)
  virtual std::string detail() const { return ""; }
  // floating-point operations of the last factorisation, if the library tells (else 0)
  virtual double flops() const { return 0.0; }
};

template <typename Scalar>
std::unique_ptr<Factoriser<Scalar>> make_factoriser(LinearSolverChoice choice, MumpsTeam &team,
                                                    const MumpsSettings &settings);

}    // namespace Acoustic

#endif
