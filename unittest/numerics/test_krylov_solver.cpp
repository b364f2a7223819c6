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
#include "network_builders.h"
#include "split_network.h"

#include <gtest/gtest.h>
#include <mpi.h>

#include <Eigen/Core>

#include <cmath>
#include <random>
#include <vector>

using namespace Acoustic;
using AcousticTest::disordered_3d;
using AcousticTest::TestNetwork;
using AcousticTest::SplitNetwork;
using AcousticTest::problem_of;
using AcousticTest::direct_solution;
using AcousticTest::difference;
using Complex = std::complex<double>;

namespace {

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
