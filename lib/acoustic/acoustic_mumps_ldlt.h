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
   ACOUSTIC package numerics: sparse symmetric LDL^T factorisation with
   MUMPS, on one or several MPI ranks.

   MumpsLdlt<Scalar> wraps one MUMPS instance with sym = 2: multifrontal
   LDL^T with 1x1 and 2x2 pivots (BLAS-3 on dense fronts), for real
   symmetric indefinite matrices (Scalar = double, K - w^2 M above the
   lowest eigenfrequency) and complex symmetric ones (Scalar =
   std::complex<double>, K + i w C - w^2 M).  The interface is that of
   Eigen's sparse solvers (analyzePattern / factorize / solve / info), so
   the Helmholtz solver treats it like the SuiteSparse ones.

   Several ranks: MUMPS factorises on every rank of the team's
   communicator, with the matrix and the right-hand sides on the host
   (rank 0 of the team).  The host drives: each of its calls first sends
   the MUMPS job to the other ranks (MumpsTeam::order), which run it in
   MumpsTeam::serve until the host calls MumpsTeam::release.  On one rank
   (MPI_COMM_SELF) nothing is sent.  MPI must be initialised.

   A team's instances are created lazily by the host's first analysis and
   destroyed (collectively) by the destructors, which every rank of the
   team must call in the same order.

   MumpsSettings: the fill-reducing ordering (auto: MUMPS's own choice,
   ICNTL(7) = 7, which takes PORD's nested dissection on contact networks;
   metis: METIS_NodeND on the graph of the matrix, given to MUMPS as its
   pivot order, ICNTL(7) = 1, when the package is built with METIS), and
   the block low-rank factorisation (ICNTL(35) = 2: BLR factors, used in
   the solve too; CNTL(7): the dropping tolerance of the low-rank
   compression, relative to the norm of the matrix).
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_MUMPS_LDLT_H
#define ACOUSTIC_MUMPS_LDLT_H

#include <mpi.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>
#include <memory>
#include <string>
#include <vector>

namespace Acoustic {

class MumpsInstance;

enum class MumpsOrdering { Auto, Metis };
// "auto" or "metis"; throws SolverError listing the allowed names otherwise
MumpsOrdering mumps_ordering_from_name(const std::string &name);
std::string mumps_ordering_name(MumpsOrdering ordering);
// true when the package is built with METIS
bool metis_available();
// whether the package was built with MUMPS (without it MumpsLdlt's
// constructor throws a SolverError that says so)
bool mumps_available();

struct MumpsSettings {
  MumpsOrdering ordering = MumpsOrdering::Auto;
  bool low_rank = false;                // block low-rank factorisation
  double low_rank_tolerance = 1e-10;    // CNTL(7)
};

// The ranks that factorise together, and the channel on which the host
// sends them the jobs of its instances.
class MumpsTeam {
 public:
  // collective over comm (duplicated: the team's messages stay apart)
  explicit MumpsTeam(MPI_Comm comm);
  ~MumpsTeam();
  MumpsTeam(const MumpsTeam &) = delete;
  MumpsTeam &operator=(const MumpsTeam &) = delete;

  bool host() const { return rank_ == 0; }
  int size() const { return size_; }
  MPI_Comm comm() const { return comm_; }

  // other ranks: run the jobs the host orders until it calls release()
  void serve();
  // host: let the other ranks return from serve()
  void release();

 private:
  friend class MumpsInstance;
  int attach(MumpsInstance *instance);    // its number in the orders
  void detach(int number);
  void order(int number, int job);    // host: workers run `job` of instance `number`

  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
  std::vector<MumpsInstance *> instances_;
};

template <typename Scalar> class MumpsLdlt {
 public:
  typedef Eigen::SparseMatrix<Scalar> MatrixType;
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Dense;

  // throws SolverError for settings this build cannot honour (metis without METIS)
  explicit MumpsLdlt(MumpsTeam &team, const MumpsSettings &settings = MumpsSettings());
  ~MumpsLdlt();
  MumpsLdlt(const MumpsLdlt &) = delete;
  MumpsLdlt &operator=(const MumpsLdlt &) = delete;

  // Host only.  a: symmetric, both triangles stored (the lower one is read).
  // analyzePattern: fill-reducing ordering (MUMPS's choice) and symbolic factorisation;
  // factorize: numeric factorisation of a matrix with the analysed pattern.
  void analyzePattern(const MatrixType &a);
  void factorize(const MatrixType &a);
  void compute(const MatrixType &a)
  {
    analyzePattern(a);
    if (info() == Eigen::Success) factorize(a);
  }
  // Success, NumericalIssue (singular matrix) or InvalidInput (other MUMPS errors)
  Eigen::ComputationInfo info() const { return info_; }
  // MUMPS's explanation of the last failure
  const std::string &message() const { return message_; }

  // solution of A x = b with the last factorisation (b: one column per right-hand side)
  template <typename Rhs> Dense solve(const Eigen::MatrixBase<Rhs> &b) const
  {
    Dense x = b;
    solve_in_place(x);
    return x;
  }
  void solve_in_place(Dense &x) const;

  // Distributed assembled input (ICNTL(18) = 3), called by every rank of the
  // team together (no host orders): each rank gives its own entries of the
  // lower triangle (0-based global rows and columns; entries given twice are
  // summed) of an n x n matrix; the ordering is MUMPS's own (the graph is
  // nowhere whole to order it with METIS).  The right-hand side and the
  // solution are dense on the host (centralised): solve_distributed's x is
  // read and written on the host only.  info() and message() as above, on
  // every rank.
  void analyze_distributed(long n, const std::vector<long> &rows, const std::vector<long> &cols,
                           const std::vector<Scalar> &values);
  void factorize_distributed(const std::vector<Scalar> &values);
  void solve_distributed(Dense &x) const;

  // size of the last factors (entries of L)
  long factor_entries() const;
  // floating-point operations of the last factorisation done on this rank
  // (any rank of the team: shows how the work was shared)
  double local_factorisation_flops() const;
  // floating-point operations of the last factorisation on all ranks (host),
  // as done: with the low-rank blocks when low_rank is on
  double factorisation_flops() const;

 private:
  MumpsSettings settings_;
  std::unique_ptr<MumpsInstance> instance_;
  Eigen::ComputationInfo info_ = Eigen::Success;
  std::string message_;
  std::vector<int> rows_, cols_;    // lower triangle, 1-based
  std::vector<Scalar> values_;
  std::vector<int> pivot_order_;    // ordering metis: position of each variable, 1-based

  void factorise(bool everyone);
  void take_status(bool factorisation);
};

extern template class MumpsLdlt<double>;
extern template class MumpsLdlt<std::complex<double>>;

}    // namespace Acoustic

#endif
