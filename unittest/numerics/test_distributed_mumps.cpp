/* ----------------------------------------------------------------------
   Unit tests of MUMPS on a distributed network (distributed assembled
   input): against the direct solve of the gathered network, undamped and
   damped, the analysis kept while the pattern stays, the last solution
   reused.  Run as a singleton and on 2 ranks.
------------------------------------------------------------------------- */

#include "acoustic_distributed_mumps.h"
#include "network_builders.h"
#include "split_network.h"

#include <gtest/gtest.h>
#include <mpi.h>

using namespace Acoustic;
using AcousticTest::SplitNetwork;

TEST(DistributedMumps, MatchesTheGatheredSolve)
{
  for (double zeta : {0.0, 0.05}) {
    for (ContactModel model : {ContactModel::Normal, ContactModel::Full}) {
      SCOPED_TRACE(contact_model_name(model) + " damping " + std::to_string(zeta));
      const AcousticTest::TestNetwork t = AcousticTest::disordered_3d(6, 5, model, zeta, 7);
      SplitNetwork split(t.network, t.source_grains);
      const double omega = 0.7;
      const Eigen::VectorXcd reference = AcousticTest::direct_solution(t.network, t.source_grains, omega);
      DistributedMumpsSolver solver(MPI_COMM_WORLD, MumpsSettings());
      const HelmholtzSolution sol = solver.solve(AcousticTest::problem_of(split, omega), split);
      ASSERT_TRUE(sol.ok()) << sol.message;
      EXPECT_LT(sol.relative_residual, 1e-10);
      EXPECT_LT(AcousticTest::difference(split, sol, reference), 1e-9);
      EXPECT_EQ(solver.num_analyses(), 1);
      EXPECT_GT(solver.last_factorisation_flops(), 0.0);

      // the same pattern at another frequency: factorised, not analysed again
      const HelmholtzSolution again = solver.solve(AcousticTest::problem_of(split, 1.1 * omega), split);
      ASSERT_TRUE(again.ok()) << again.message;
      EXPECT_EQ(solver.num_analyses(), 1);
      EXPECT_EQ(solver.num_factorisations(), 2);
      const Eigen::VectorXcd other = AcousticTest::direct_solution(t.network, t.source_grains, 1.1 * omega);
      EXPECT_LT(AcousticTest::difference(split, again, other), 1e-9);

      // the last solution of the same system: taken as it is
      const HelmholtzSolution reused = solver.solve(AcousticTest::problem_of(split, 1.1 * omega), split, &again.q);
      ASSERT_TRUE(reused.ok());
      EXPECT_EQ(solver.num_reuses(), 1);
      EXPECT_EQ(solver.num_factorisations(), 2);
      EXPECT_EQ(reused.q, again.q);
    }
  }
}
