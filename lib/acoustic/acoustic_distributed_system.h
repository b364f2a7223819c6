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
   ACOUSTIC package numerics: the Helmholtz system of a network distributed
   over MPI ranks.

   Each rank holds its part of the network (see acoustic_halo_exchange.h):
   a ContactNetwork whose grains are the ones it owns (the first
   num_owned), then ghosts, then prescribed nodes, and whose contacts are
   those it counts (every contact of the whole network on exactly one
   rank).  The operator
     A = K + i omega C - omega^2 M
   is applied without assembling it anywhere: each rank multiplies by its
   local K and C (assembled by ContactNetwork, the same code as for the
   gathered network) and by the masses of the grains it owns; ghost values
   come in by a forward halo exchange, ghost products go back to their
   owners by a reverse one.  The unknowns are the free DOFs of the owned
   grains (rank by rank in rank order, grain by grain within a rank: the
   global numbering of an assembled copy); b = -(A_FP q_P) on them, from
   the prescribed values of every prescribed DOF the rank holds (owned,
   ghost or node).

   Every function is collective over the ranks of the decomposition.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_DISTRIBUTED_SYSTEM_H
#define ACOUSTIC_DISTRIBUTED_SYSTEM_H

#include "acoustic_contact_network.h"
#include "acoustic_halo_exchange.h"

#include <mpi.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>
#include <string>
#include <vector>

namespace Acoustic {

// one rank's part of the problem
struct DistributedHelmholtzProblem {
  const ContactNetwork *network = nullptr;    // local grains and this rank's contacts
  int num_owned = 0;                          // grains 0 .. num_owned - 1 are owned here
  double omega = 0.0;
  std::vector<int> prescribed_dofs;      // local DOFs, any local grain
  Eigen::VectorXcd prescribed_values;    // their amplitudes
};

class DistributedSystem {
 public:
  typedef std::complex<double> Complex;

  // Invalid input throws SolverError on the rank that found it and
  // SolverErrorElsewhere on the others.  The operator is assembled and b
  // computed here.
  DistributedSystem(const DistributedHelmholtzProblem &problem, HaloExchange &halo, MPI_Comm comm);

  MPI_Comm comm() const { return comm_; }
  int dofs_per_grain() const { return ndof_; }
  int num_dofs() const { return num_dofs_; }    // local DOFs
  int num_unknowns() const { return static_cast<int>(unknowns_.size()); }
  const std::vector<int> &unknowns() const { return unknowns_; }    // local DOF of each unknown
  long first_unknown() const { return first_; }    // global index of this rank's first
  long num_global_unknowns() const { return total_; }

  const std::vector<Complex> &right_hand_side() const { return rhs_; }
  double rhs_norm() const { return rhs_norm_; }    // ||b|| over every rank

  // y = A x on this rank's unknowns
  void apply(const Complex *x, Complex *y);
  // ||b - A x|| / ||b||; infinite if x or the residual is not finite
  double relative_residual(const std::vector<Complex> &x);
  // q on every local DOF: the unknowns' values x, the prescribed values,
  // the ghosts' from their owners
  Eigen::VectorXcd local_solution(const std::vector<Complex> &x);

  // This rank's entries of A + i shift omega^2 M (shift > 0: the shifted
  // operator of the preconditioner) in the global numbering (0-based), rows
  // of ghosts included: summed over the ranks, they are the entries of the
  // assembled matrix.  lower: only those with row >= column.
  void global_entries(double shift, bool lower, std::vector<long> &rows, std::vector<long> &cols,
                      std::vector<Complex> &values);
  // true on every rank when each owned grain has all its DOFs unknown or none
  bool blocked() const { return blocked_; }

 private:
  MPI_Comm comm_;
  HaloExchange &halo_;
  int ndof_, num_dofs_;
  double omega_;
  long first_ = 0, total_ = 0;
  bool blocked_ = false;
  Eigen::SparseMatrix<Complex> matrix_;    // local A (ghost masses left out)
  Eigen::VectorXd owned_mass_;             // per local DOF, 0 for ghosts and nodes
  std::vector<char> prescribed_;
  std::vector<int> unknowns_;
  Eigen::VectorXcd values_;    // prescribed values per local DOF
  std::vector<Complex> rhs_;
  double rhs_norm_ = 0.0;
  Eigen::VectorXcd in_, out_;

  void multiply_local(Complex *result);
};

}    // namespace Acoustic

#endif
