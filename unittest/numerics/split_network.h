/* ----------------------------------------------------------------------
   Test helpers: a network split over the ranks of MPI_COMM_WORLD, with a
   halo exchange by MPI reductions, for the distributed solvers.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_TEST_SPLIT_NETWORK_H
#define ACOUSTIC_TEST_SPLIT_NETWORK_H

#include "acoustic_contact_network.h"
#include "acoustic_distributed_system.h"
#include "acoustic_halo_exchange.h"
#include "acoustic_helmholtz_solver.h"

#include <gtest/gtest.h>
#include <mpi.h>

#include <Eigen/Core>

#include <algorithm>
#include <complex>
#include <memory>
#include <vector>

namespace AcousticTest {

using Complex = std::complex<double>;

// the source grains vibrate along z, rotations held
inline void drive(const Acoustic::ContactNetwork &net, const std::vector<int> &source_grains, std::vector<int> &dofs,
           Eigen::VectorXcd &values)
{
  dofs.clear();
  std::vector<Complex> v;
  for (int g : source_grains)
    for (int d = 0; d < net.dofs_per_grain(); ++d) {
      dofs.push_back(net.dof(g, d));
      v.push_back(d == 2 ? 1.0 : 0.0);
    }
  values = Eigen::Map<Eigen::VectorXcd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

// The network split over the ranks of MPI_COMM_WORLD: grain g is owned by
// rank g * nprocs / num_grains, a contact is counted by the owner of its
// grain i.  The halo exchange sums global vectors over the ranks.
class SplitNetwork : public Acoustic::HaloExchange {
 public:
  SplitNetwork(const Acoustic::ContactNetwork &global, const std::vector<int> &source_grains)
  {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &nprocs_);
    num_global_ = global.num_grains();
    auto owner = [&](int g) { return static_cast<int>(static_cast<long>(g) * nprocs_ / num_global_); };
    std::vector<int> local_of(num_global_, -1);
    for (int g = 0; g < num_global_; ++g)
      if (owner(g) == rank_) {
        local_of[g] = static_cast<int>(global_of_.size());
        global_of_.push_back(g);
      }
    num_owned_ = static_cast<int>(global_of_.size());
    std::vector<Acoustic::Contact> contacts;
    for (Acoustic::Contact c : global.contacts()) {
      if (owner(c.i) != rank_) continue;
      for (int *g : {&c.i, &c.j}) {
        if (local_of[*g] < 0) {
          local_of[*g] = static_cast<int>(global_of_.size());
          global_of_.push_back(*g);
        }
        *g = local_of[*g];
      }
      contacts.push_back(c);
    }
    std::vector<Acoustic::Grain> grains;
    for (int g : global_of_) grains.push_back(global.grains()[g]);
    local_.reset(new Acoustic::ContactNetwork(global.dimension(), global.model(), grains, contacts));
    for (int g : source_grains)
      if (local_of[g] >= 0) local_sources_.push_back(local_of[g]);
  }

  const Acoustic::ContactNetwork &local() const { return *local_; }
  int num_owned() const { return num_owned_; }
  const std::vector<int> &local_sources() const { return local_sources_; }
  int global_grain(int local) const { return global_of_[local]; }

  void forward(Complex *values, int width) override
  {
    std::vector<Complex> all(static_cast<std::size_t>(num_global_) * width, 0.0);
    for (int g = 0; g < num_owned_; ++g)
      for (int k = 0; k < width; ++k) all[global_of_[g] * width + k] = values[g * width + k];
    MPI_Allreduce(MPI_IN_PLACE, all.data(), static_cast<int>(all.size()), MPI_C_DOUBLE_COMPLEX, MPI_SUM,
                  MPI_COMM_WORLD);
    for (std::size_t g = num_owned_; g < global_of_.size(); ++g)
      for (int k = 0; k < width; ++k) values[g * width + k] = all[global_of_[g] * width + k];
  }
  void reverse(Complex *values, int width) override
  {
    std::vector<Complex> all(static_cast<std::size_t>(num_global_) * width, 0.0);
    for (std::size_t g = num_owned_; g < global_of_.size(); ++g)
      for (int k = 0; k < width; ++k) all[global_of_[g] * width + k] = values[g * width + k];
    MPI_Allreduce(MPI_IN_PLACE, all.data(), static_cast<int>(all.size()), MPI_C_DOUBLE_COMPLEX, MPI_SUM,
                  MPI_COMM_WORLD);
    for (int g = 0; g < num_owned_; ++g)
      for (int k = 0; k < width; ++k) values[g * width + k] += all[global_of_[g] * width + k];
  }

 private:
  int rank_ = 0, nprocs_ = 1, num_global_ = 0, num_owned_ = 0;
  std::vector<int> global_of_;
  std::vector<int> local_sources_;
  std::unique_ptr<Acoustic::ContactNetwork> local_;
};

inline Acoustic::DistributedHelmholtzProblem problem_of(const SplitNetwork &split, double omega)
{
  Acoustic::DistributedHelmholtzProblem p;
  p.network = &split.local();
  p.num_owned = split.num_owned();
  p.omega = omega;
  drive(split.local(), split.local_sources(), p.prescribed_dofs, p.prescribed_values);
  return p;
}

inline Eigen::VectorXcd direct_solution(const Acoustic::ContactNetwork &net, const std::vector<int> &sources, double omega)
{
  std::vector<int> dofs;
  Eigen::VectorXcd values;
  drive(net, sources, dofs, values);
  Acoustic::HelmholtzSolver solver(Acoustic::LinearSolverChoice::Lu);
  const Acoustic::HelmholtzSolution sol = solver.solve(net.stiffness_matrix(), net.damping_matrix(), net.mass_diagonal(),
                                             omega, dofs, values);
  EXPECT_TRUE(sol.ok()) << sol.message;
  return sol.q;
}

// largest difference between the split solution and the global one, relative to the largest amplitude
inline double difference(const SplitNetwork &split, const Acoustic::HelmholtzSolution &sol, const Eigen::VectorXcd &reference)
{
  const int ndof = split.local().dofs_per_grain();
  double local = 0.0, global = 0.0;
  for (int g = 0; g < split.local().num_grains(); ++g)
    for (int d = 0; d < ndof; ++d)
      local = std::max(local, std::abs(sol.q[g * ndof + d] - reference[split.global_grain(g) * ndof + d]));
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return global / reference.cwiseAbs().maxCoeff();
}

}    // namespace AcousticTest

#endif
