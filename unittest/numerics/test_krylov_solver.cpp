/* ----------------------------------------------------------------------
   Unit tests of the distributed Krylov Helmholtz solver: against the
   direct solvers on the gathered network (1 rank and the network split
   over the ranks of the test), determinism, initial guesses, the
   undamped case inside the band.  Run as a singleton and on 2 ranks.
------------------------------------------------------------------------- */

#include "acoustic_contact_network.h"
#include "acoustic_helmholtz_solver.h"
#include "acoustic_krylov_solver.h"
#include "acoustic_solver_error.h"

#include <gtest/gtest.h>
#include <mpi.h>

#include <Eigen/Core>

#include <cmath>
#include <random>
#include <vector>

using namespace Acoustic;
using Complex = std::complex<double>;

namespace {

// Disordered 3D network: a simple cubic lattice of n x n x nz grains with
// bonds to the 6 neighbours and to 4 of the 12 face diagonals, directions
// tilted at random, random masses, stiffnesses and radii; dashpots for the
// damping ratio zeta.  The bottom layer (z = 0) is the source.
struct TestNetwork {
  ContactNetwork network;
  std::vector<int> source_grains;
};

TestNetwork disordered_3d(int n, int nz, ContactModel model, double zeta, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  auto index = [&](int x, int y, int z) { return (z * n + y) * n + x; };
  std::vector<Grain> grains;
  for (int g = 0; g < n * n * nz; ++g) grains.push_back(Grain{0.6 + 0.8 * uniform(rng), 0.4 + 0.2 * uniform(rng)});
  std::vector<Contact> contacts;
  const int steps[5][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}};
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        for (const auto &s : steps) {
          const int x2 = x + s[0], y2 = y + s[1], z2 = z + s[2];
          if (x2 >= n || y2 >= n || z2 >= nz) continue;
          if ((s[0] + s[1] + s[2]) > 1 && uniform(rng) < 0.5) continue;
          Eigen::Vector3d normal(-s[0] + 0.2 * (uniform(rng) - 0.5), -s[1] + 0.2 * (uniform(rng) - 0.5),
                                 -s[2] + 0.2 * (uniform(rng) - 0.5));
          normal.normalize();
          const int i = index(x2, y2, z2), j = index(x, y, z);
          const double kn = 0.3 + 1.4 * uniform(rng), kt = 0.3 * kn;
          const double meff = grains[i].mass * grains[j].mass / (grains[i].mass + grains[j].mass);
          contacts.push_back(Contact{i, j, normal, kn, kt, 2.0 * zeta * std::sqrt(kn * meff),
                                     2.0 * zeta * std::sqrt(kt * meff)});
        }
  TestNetwork t{ContactNetwork(3, model, grains, contacts), {}};
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) t.source_grains.push_back(index(x, y, 0));
  return t;
}

// the source grains vibrate along z, rotations held
void drive(const ContactNetwork &net, const std::vector<int> &source_grains, std::vector<int> &dofs,
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
class SplitNetwork : public HaloExchange {
 public:
  SplitNetwork(const ContactNetwork &global, const std::vector<int> &source_grains)
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
    std::vector<Contact> contacts;
    for (Contact c : global.contacts()) {
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
    std::vector<Grain> grains;
    for (int g : global_of_) grains.push_back(global.grains()[g]);
    local_.reset(new ContactNetwork(global.dimension(), global.model(), grains, contacts));
    for (int g : source_grains)
      if (local_of[g] >= 0) local_sources_.push_back(local_of[g]);
  }

  const ContactNetwork &local() const { return *local_; }
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
  std::unique_ptr<ContactNetwork> local_;
};

DistributedHelmholtzProblem problem_of(const SplitNetwork &split, double omega)
{
  DistributedHelmholtzProblem p;
  p.network = &split.local();
  p.num_owned = split.num_owned();
  p.omega = omega;
  drive(split.local(), split.local_sources(), p.prescribed_dofs, p.prescribed_values);
  return p;
}

Eigen::VectorXcd direct_solution(const ContactNetwork &net, const std::vector<int> &sources, double omega)
{
  std::vector<int> dofs;
  Eigen::VectorXcd values;
  drive(net, sources, dofs, values);
  HelmholtzSolver solver(LinearSolverChoice::Lu);
  const HelmholtzSolution sol = solver.solve(net.stiffness_matrix(), net.damping_matrix(), net.mass_diagonal(),
                                             omega, dofs, values);
  EXPECT_TRUE(sol.ok()) << sol.message;
  return sol.q;
}

// largest difference between the split solution and the global one, relative to the largest amplitude
double difference(const SplitNetwork &split, const HelmholtzSolution &sol, const Eigen::VectorXcd &reference)
{
  const int ndof = split.local().dofs_per_grain();
  double local = 0.0, global = 0.0;
  for (int g = 0; g < split.local().num_grains(); ++g)
    for (int d = 0; d < ndof; ++d)
      local = std::max(local, std::abs(sol.q[g * ndof + d] - reference[split.global_grain(g) * ndof + d]));
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return global / reference.cwiseAbs().maxCoeff();
}

// the band top of the network: largest omega^2 = eigenvalue of M^-1 K (power iteration)
double band_top(const ContactNetwork &net)
{
  const Eigen::SparseMatrix<double> k = net.stiffness_matrix();
  const Eigen::VectorXd m = net.mass_diagonal();
  Eigen::VectorXd v = Eigen::VectorXd::Ones(net.num_dofs());
  double lambda = 0.0;
  for (int it = 0; it < 300; ++it) {
    Eigen::VectorXd w = (k * v).cwiseQuotient(m);
    lambda = w.norm() / v.norm();
    v = w / w.norm();
  }
  return std::sqrt(lambda);
}

}    // namespace

TEST(KrylovSolver, MatchesTheDirectSolverOnASplitDampedNetwork)
{
  ASSERT_TRUE(KrylovHelmholtzSolver::available());
  for (ContactModel model : {ContactModel::Normal, ContactModel::Full}) {
    const TestNetwork t = disordered_3d(6, 5, model, 0.05, 7);
    const double top = band_top(t.network);
    SplitNetwork split(t.network, t.source_grains);
    for (double fraction : {0.1, 0.3, 0.6}) {
      SCOPED_TRACE(contact_model_name(model) + " at " + std::to_string(fraction) + " of the band top");
      const double omega = fraction * top;
      const Eigen::VectorXcd reference = direct_solution(t.network, t.source_grains, omega);
      for (KrylovPreconditioner pc : {KrylovPreconditioner::None, KrylovPreconditioner::Shifted}) {
        KrylovSettings settings;
        settings.preconditioner = pc;
        settings.tolerance = 1e-10;
        KrylovHelmholtzSolver solver(MPI_COMM_WORLD, settings);
        const HelmholtzSolution sol = solver.solve(problem_of(split, omega), split);
        ASSERT_TRUE(sol.ok()) << sol.message;
        EXPECT_LE(sol.relative_residual, 1e-10);
        EXPECT_GT(sol.iterations, 0);
        EXPECT_LT(difference(split, sol, reference), 1e-8);
      }
    }
  }
}

TEST(KrylovSolver, TheSameInputGivesTheSameBits)
{
  const TestNetwork t = disordered_3d(5, 4, ContactModel::Full, 0.02, 11);
  SplitNetwork split(t.network, t.source_grains);
  const double omega = 0.3 * band_top(t.network);
  KrylovHelmholtzSolver first(MPI_COMM_WORLD, KrylovSettings());
  KrylovHelmholtzSolver second(MPI_COMM_WORLD, KrylovSettings());
  const HelmholtzSolution a = first.solve(problem_of(split, omega), split);
  const HelmholtzSolution b = second.solve(problem_of(split, omega), split);
  ASSERT_TRUE(a.ok());
  EXPECT_EQ(a.iterations, b.iterations);
  for (Eigen::Index k = 0; k < a.q.size(); ++k) EXPECT_EQ(a.q[k], b.q[k]);
}

TEST(KrylovSolver, AGuessThatSolvesTheSystemTakesNoIteration)
{
  const TestNetwork t = disordered_3d(5, 4, ContactModel::Normal, 0.05, 3);
  SplitNetwork split(t.network, t.source_grains);
  const double omega = 0.4 * band_top(t.network);
  KrylovHelmholtzSolver solver(MPI_COMM_WORLD, KrylovSettings());
  const HelmholtzSolution cold = solver.solve(problem_of(split, omega), split);
  ASSERT_TRUE(cold.ok());
  EXPECT_EQ(solver.num_reuses(), 0);
  const HelmholtzSolution warm = solver.solve(problem_of(split, omega), split, &cold.q);
  ASSERT_TRUE(warm.ok());
  EXPECT_EQ(warm.iterations, 0);
  EXPECT_EQ(solver.num_reuses(), 1);
  EXPECT_EQ(solver.last_products(), 0);
  EXPECT_EQ(warm.q, cold.q);

  // a slightly different frequency: the old solution is a start, fewer iterations
  const HelmholtzSolution near_cold = solver.solve(problem_of(split, 1.0001 * omega), split);
  const HelmholtzSolution near_warm = solver.solve(problem_of(split, 1.0001 * omega), split, &cold.q);
  ASSERT_TRUE(near_warm.ok());
  EXPECT_LT(near_warm.iterations, near_cold.iterations);
  EXPECT_LT((near_warm.q - near_cold.q).cwiseAbs().maxCoeff(), 1e-6 * near_cold.q.cwiseAbs().maxCoeff());
}

TEST(KrylovSolver, AnUndampedNetworkInsideItsBandStopsAtTheIterationLimit)
{
  const TestNetwork t = disordered_3d(6, 5, ContactModel::Normal, 0.0, 5);
  SplitNetwork split(t.network, t.source_grains);
  const double omega = 0.5 * band_top(t.network);
  KrylovSettings settings;
  settings.max_iterations = 200;
  KrylovHelmholtzSolver solver(MPI_COMM_WORLD, settings);
  const HelmholtzSolution sol = solver.solve(problem_of(split, omega), split);
  EXPECT_FALSE(sol.ok());
  EXPECT_EQ(sol.status, SolveStatus::InaccurateSolution);
  EXPECT_LE(sol.iterations, 200);
  EXPECT_TRUE(sol.q.allFinite());
  EXPECT_GT(sol.relative_residual, settings.tolerance);
  EXPECT_FALSE(sol.message.empty());
}

TEST(KrylovSolver, BelowTheBandAnUndampedNetworkConverges)
{
  const TestNetwork t = disordered_3d(6, 5, ContactModel::Full, 0.0, 5);
  SplitNetwork split(t.network, t.source_grains);
  const double omega = 0.02 * band_top(t.network);
  const Eigen::VectorXcd reference = direct_solution(t.network, t.source_grains, omega);
  KrylovHelmholtzSolver solver(MPI_COMM_WORLD, KrylovSettings());
  const HelmholtzSolution sol = solver.solve(problem_of(split, omega), split);
  ASSERT_TRUE(sol.ok()) << sol.message;
  EXPECT_LT(difference(split, sol, reference), 1e-6);
}

TEST(KrylovSolver, RejectsInvalidInputOnEveryRank)
{
  const TestNetwork t = disordered_3d(4, 3, ContactModel::Normal, 0.05, 1);
  SplitNetwork split(t.network, t.source_grains);
  KrylovHelmholtzSolver solver(MPI_COMM_WORLD, KrylovSettings());
  DistributedHelmholtzProblem p = problem_of(split, 1.0);
  p.omega = -1.0;
  EXPECT_THROW(solver.solve(p, split), SolverError);
  p = problem_of(split, 1.0);
  if (!p.prescribed_dofs.empty()) p.prescribed_dofs.push_back(p.prescribed_dofs.front());
  p.prescribed_values.conservativeResize(static_cast<Eigen::Index>(p.prescribed_dofs.size()));
  // rank 0 holds sources: the duplicate is its error, the others hear of it
  EXPECT_THROW(solver.solve(p, split), SolverError);
  KrylovSettings bad;
  bad.tolerance = 0.0;
  EXPECT_THROW(KrylovHelmholtzSolver(MPI_COMM_WORLD, bad), SolverError);
}
