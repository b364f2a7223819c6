/* ----------------------------------------------------------------------
   Unit tests: the MUMPS LDL^T factorisation and the Helmholtz solver on it,
   on one rank and (under mpirun -np 2) on a team of two ranks.
------------------------------------------------------------------------- */

#include "acoustic_contact_network.h"
#include "acoustic_factoriser.h"
#include "acoustic_helmholtz_solver.h"
#include "acoustic_mumps_ldlt.h"
#include "acoustic_solver_error.h"
#include "network_builders.h"

#include <gtest/gtest.h>
#include <mpi.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <complex>
#include <random>
#include <vector>

using namespace Acoustic;
using Complex = std::complex<double>;

// a build without MUMPS (ACOUSTIC_WITH_MUMPS off) has nothing of it to test
#define SKIP_WITHOUT_MUMPS() \
  if (!mumps_available()) GTEST_SKIP() << "the package is built without MUMPS"

namespace {

// k + i w c in the scalar type of the matrix (real matrices: undamped only)
double entry(double k, double, double)
{
  return k;
}
Complex entry(double k, double omega_c, Complex)
{
  return Complex(k, omega_c);
}

// A = K_FF + i w C_FF - w^2 M_FF of a disordered 2D network with its bottom row
// fixed (dashpots c = damping * k when damping > 0), as a sparse symmetric matrix
template <typename Scalar> Eigen::SparseMatrix<Scalar> helmholtz_matrix(int nx, int ny, double omega, double damping)
{
  std::vector<int> fixed;
  const ContactNetwork network = AcousticTest::disordered_network(nx, ny, 11u, fixed);
  const Eigen::SparseMatrix<double> k = network.stiffness_matrix();
  const int n = static_cast<int>(k.rows()) - static_cast<int>(fixed.size());
  const int offset = static_cast<int>(fixed.size());    // the fixed DOFs are the first ones
  std::vector<Eigen::Triplet<Scalar>> triplets;
  for (int col = 0; col < k.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(k, col); it; ++it)
      if (it.row() >= offset && col >= offset) {
        triplets.emplace_back(static_cast<int>(it.row()) - offset, col - offset,
                              entry(it.value(), omega * damping * it.value(), Scalar()));
      }
  const Eigen::VectorXd mass = network.mass_diagonal();
  for (int d = 0; d < n; ++d) triplets.emplace_back(d, d, Scalar(-omega * omega * mass[d + offset]));
  Eigen::SparseMatrix<Scalar> a(n, n);
  a.setFromTriplets(triplets.begin(), triplets.end());
  a.makeCompressed();
  return a;
}

template <typename Scalar> Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> random_rhs(int n, int columns)
{
  std::mt19937 rng(3u);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> b(n, columns);
  for (int c = 0; c < columns; ++c)
    for (int r = 0; r < n; ++r) b(r, c) = Scalar(uniform(rng));
  return b;
}

bool is_host()
{
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank == 0;
}

}    // namespace

// each rank on its own (MPI_COMM_SELF): against a dense solve
TEST(MumpsLdlt, RealIndefiniteMatchesDenseSolve)
{
  SKIP_WITHOUT_MUMPS();
  MumpsTeam team(MPI_COMM_SELF);
  MumpsLdlt<double> ldlt(team);
  // 12 x 8 grains, bottom row fixed: 176 DOFs; w^2 inside the spectrum (indefinite)
  const Eigen::SparseMatrix<double> a = helmholtz_matrix<double>(12, 8, 1.1, 0.0);
  const Eigen::MatrixXd dense = Eigen::MatrixXd(a);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(dense);
  ASSERT_LT(eig.eigenvalues().minCoeff(), 0.0);
  ASSERT_GT(eig.eigenvalues().maxCoeff(), 0.0);
  ldlt.compute(a);
  ASSERT_EQ(ldlt.info(), Eigen::Success) << ldlt.message();
  const Eigen::MatrixXd b = random_rhs<double>(static_cast<int>(a.rows()), 3);
  const Eigen::MatrixXd x = ldlt.solve(b);
  const Eigen::MatrixXd expected = dense.partialPivLu().solve(b);
  EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
  // fill-in: the factor holds more than the lower triangle of A
  EXPECT_GT(ldlt.factor_entries(), (a.nonZeros() + a.rows()) / 2);

  // new values on the same pattern: numeric factorisation only
  const Eigen::SparseMatrix<double> a2 = helmholtz_matrix<double>(12, 8, 0.7, 0.0);
  ldlt.factorize(a2);
  ASSERT_EQ(ldlt.info(), Eigen::Success) << ldlt.message();
  const Eigen::MatrixXd x2 = ldlt.solve(b);
  const Eigen::MatrixXd expected2 = Eigen::MatrixXd(a2).partialPivLu().solve(b);
  EXPECT_LT((x2 - expected2).norm(), 1e-10 * expected2.norm());

  // another pattern without analysis: refused, and solves give NaN, not stale numbers
  const Eigen::SparseMatrix<double> other = helmholtz_matrix<double>(10, 8, 0.7, 0.0);
  ldlt.factorize(other);
  EXPECT_EQ(ldlt.info(), Eigen::InvalidInput);
  EXPECT_FALSE(ldlt.message().empty());
  const Eigen::MatrixXd stale = ldlt.solve(Eigen::MatrixXd::Ones(a.rows(), 1));
  EXPECT_FALSE(stale.allFinite());
}

TEST(MumpsLdlt, ComplexSymmetricMatchesDenseSolve)
{
  SKIP_WITHOUT_MUMPS();
  MumpsTeam team(MPI_COMM_SELF);
  MumpsLdlt<Complex> ldlt(team);
  const Eigen::SparseMatrix<Complex> a = helmholtz_matrix<Complex>(10, 6, 1.3, 0.05);
  const Eigen::MatrixXcd dense = Eigen::MatrixXcd(a);
  ASSERT_LT((dense - dense.transpose()).norm(), 1e-14 * dense.norm());    // symmetric, not Hermitian
  ASSERT_GT(dense.imag().norm(), 0.0);
  ldlt.compute(a);
  ASSERT_EQ(ldlt.info(), Eigen::Success) << ldlt.message();
  const Eigen::MatrixXcd b = random_rhs<Complex>(static_cast<int>(a.rows()), 2);
  const Eigen::MatrixXcd x = ldlt.solve(b);
  const Eigen::MatrixXcd expected = dense.partialPivLu().solve(b);
  EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
}

TEST(MumpsLdlt, ReportsASingularMatrix)
{
  SKIP_WITHOUT_MUMPS();
  MumpsTeam team(MPI_COMM_SELF);
  MumpsLdlt<double> ldlt(team);
  // [[1 1 0], [1 1 0], [0 0 2]]: rank 2
  std::vector<Eigen::Triplet<double>> t = {{0, 0, 1.0}, {1, 0, 1.0}, {0, 1, 1.0}, {1, 1, 1.0}, {2, 2, 2.0}};
  Eigen::SparseMatrix<double> a(3, 3);
  a.setFromTriplets(t.begin(), t.end());
  ldlt.compute(a);
  EXPECT_EQ(ldlt.info(), Eigen::NumericalIssue);
  EXPECT_NE(ldlt.message().find("singular"), std::string::npos) << ldlt.message();
}

// METIS's nested dissection as MUMPS's pivot order: the same solution, and
// the ordering is really used (other factors than MUMPS's own choice)
TEST(MumpsLdlt, MetisOrderingGivesTheSameSolution)
{
  SKIP_WITHOUT_MUMPS();
  ASSERT_TRUE(metis_available());
  const Eigen::SparseMatrix<Complex> a = helmholtz_matrix<Complex>(30, 20, 1.1, 0.05);
  const Eigen::MatrixXcd b = random_rhs<Complex>(static_cast<int>(a.rows()), 1);
  MumpsTeam team(MPI_COMM_SELF);
  MumpsLdlt<Complex> own(team);
  MumpsSettings settings;
  settings.ordering = MumpsOrdering::Metis;
  MumpsLdlt<Complex> metis(team, settings);
  own.compute(a);
  metis.compute(a);
  ASSERT_EQ(own.info(), Eigen::Success) << own.message();
  ASSERT_EQ(metis.info(), Eigen::Success) << metis.message();
  const Eigen::MatrixXcd x_own = own.solve(b), x_metis = metis.solve(b);
  EXPECT_LT((x_own - x_metis).norm(), 1e-10 * x_own.norm());
  EXPECT_NE(own.factor_entries(), metis.factor_entries());
  EXPECT_GT(metis.factorisation_flops(), 0.0);
  EXPECT_EQ(mumps_ordering_from_name("metis"), MumpsOrdering::Metis);
  EXPECT_THROW(mumps_ordering_from_name("scotch"), SolverError);
}

// METIS in 3D: the same solution, fewer operations than MUMPS's own choice
// of ordering; block low-rank factors of a 3D network (2D fronts are too
// small to compress): the solution within a few orders of the compression
// tolerance, and other operation counts than full rank (the setting is used;
// on these networks the blocks hardly compress, see the doc page)
TEST(MumpsLdlt, LowRankAndMetisFactorsOfA3DNetwork)
{
  SKIP_WITHOUT_MUMPS();
  const AcousticTest::TestNetwork t = AcousticTest::disordered_3d(18, 18, ContactModel::Normal, 0.05, 9u);
  const ContactNetwork &net = t.network;
  std::vector<int> dofs;
  std::vector<Complex> v;
  for (int g : t.source_grains)
    for (int d = 0; d < 3; ++d) {
      dofs.push_back(net.dof(g, d));
      v.push_back(d == 2 ? 1.0 : 0.0);
    }
  const Eigen::VectorXcd values = Eigen::Map<Eigen::VectorXcd>(v.data(), static_cast<Eigen::Index>(v.size()));
  auto solve = [&](const MumpsSettings &settings, double &flops) {
    HelmholtzSolver solver(LinearSolverChoice::Auto, 1e-6, MPI_COMM_SELF, settings);
    const HelmholtzSolution sol =
        solver.solve(net.stiffness_matrix(), net.damping_matrix(), net.mass_diagonal(), 0.8, dofs, values);
    EXPECT_EQ(sol.status, SolveStatus::Success) << sol.message;
    flops = solver.last_factorisation_flops();
    return sol.q;
  };
  double full_flops = 0.0, metis_flops = 0.0;
  const Eigen::VectorXcd full = solve(MumpsSettings(), full_flops);
  MumpsSettings metis;
  metis.ordering = MumpsOrdering::Metis;
  const Eigen::VectorXcd by_metis = solve(metis, metis_flops);
  EXPECT_LT((by_metis - full).norm(), 1e-10 * full.norm());
  std::printf("3D, %d DOFs: flops %.3g (MUMPS's ordering), %.3g (METIS)\n", net.num_dofs(), full_flops, metis_flops);
  EXPECT_LT(metis_flops, full_flops);
  for (double tolerance : {1e-10, 1e-6}) {
    MumpsSettings blr = metis;
    blr.low_rank = true;
    blr.low_rank_tolerance = tolerance;
    double flops = 0.0;
    const Eigen::VectorXcd q = solve(blr, flops);
    const double error = (q - full).norm() / full.norm();
    std::printf("BLR tolerance %g: relative error %.3g, flops %.3g\n", tolerance, error, flops);
    EXPECT_LT(error, 1e3 * tolerance);
    EXPECT_NE(flops, metis_flops);
  }
  MumpsTeam team(MPI_COMM_SELF);
  MumpsSettings bad;
  bad.low_rank = true;
  bad.low_rank_tolerance = 0.0;
  EXPECT_THROW(MumpsLdlt<Complex>(team, bad), SolverError);
}

// MUMPS and UMFPACK are independent implementations: same response of a
// disordered network driven inside its band, with and without damping
TEST(MumpsLdlt, HelmholtzSolverAgreesWithUmfpack)
{
  SKIP_WITHOUT_MUMPS();
  std::vector<int> fixed;
  const ContactNetwork network = AcousticTest::disordered_network(30, 20, 5u, fixed);
  Eigen::VectorXcd values = Eigen::VectorXcd::Zero(fixed.size());
  for (std::size_t k = 1; k < fixed.size(); k += 2) values[k] = 1.0;    // vertical drive
  for (double zeta : {0.0, 0.03}) {
    SCOPED_TRACE("damping " + std::to_string(zeta));
    std::vector<Contact> contacts = network.contacts();
    for (Contact &c : contacts) c.cn = zeta * c.kn;
    const ContactNetwork damped(2, ContactModel::Normal, network.grains(), contacts);
    HelmholtzSolver mumps(LinearSolverChoice::Mumps), umfpack(LinearSolverChoice::Lu);
    const HelmholtzSolution a = mumps.solve(damped.stiffness_matrix(), damped.damping_matrix(),
                                            damped.mass_diagonal(), 0.9, fixed, values);
    const HelmholtzSolution b = umfpack.solve(damped.stiffness_matrix(), damped.damping_matrix(),
                                              damped.mass_diagonal(), 0.9, fixed, values);
    ASSERT_TRUE(a.ok()) << a.message;
    ASSERT_TRUE(b.ok()) << b.message;
    EXPECT_EQ(a.factorisation, "mumps");
    EXPECT_LT((a.q - b.q).norm(), 1e-8 * b.q.norm());
  }
}

// On MPI_COMM_WORLD: the host drives, the other ranks serve.  The answer must
// not depend on the number of ranks (compared with a solve on the host alone).
TEST(MumpsParallel, TeamOfAllRanksGivesTheSingleRankAnswer)
{
  SKIP_WITHOUT_MUMPS();
  std::vector<int> fixed;
  const ContactNetwork network = AcousticTest::disordered_network(40, 25, 9u, fixed);
  Eigen::VectorXcd values = Eigen::VectorXcd::Zero(fixed.size());
  for (std::size_t k = 1; k < fixed.size(); k += 2) values[k] = 1.0;
  HelmholtzSolver team_solver(LinearSolverChoice::Mumps, 1e-6, MPI_COMM_WORLD);
  team_solver.set_reuse_factorisation(true);
  std::vector<Contact> contacts = network.contacts();
  for (double stiffer : {1.0, 1.002}) {
    contacts[100].kn *= stiffer;    // second solve: a tiny change, answered with the earlier factors
    const ContactNetwork net(2, ContactModel::Normal, network.grains(), contacts);
    if (team_solver.host()) {
      const HelmholtzSolution sol =
          team_solver.solve(net.stiffness_matrix(), net.damping_matrix(), net.mass_diagonal(), 0.8, fixed, values);
      team_solver.release_workers();
      HelmholtzSolver alone(LinearSolverChoice::Mumps, 1e-6, MPI_COMM_SELF);
      const HelmholtzSolution reference =
          alone.solve(net.stiffness_matrix(), net.damping_matrix(), net.mass_diagonal(), 0.8, fixed, values);
      ASSERT_TRUE(sol.ok()) << sol.message;
      ASSERT_TRUE(reference.ok()) << reference.message;
      EXPECT_LT((sol.q - reference.q).norm(), 1e-9 * reference.q.norm());
    } else {
      team_solver.serve();
      HelmholtzSolver alone(LinearSolverChoice::Mumps, 1e-6, MPI_COMM_SELF);    // keeps construction symmetric
    }
  }
  if (team_solver.host()) {
    EXPECT_EQ(team_solver.num_factorisations(), 1);
    EXPECT_EQ(team_solver.num_reuses(), 1);
  }
  // several solves between serve() and release_workers(), damped then undamped
  for (double zeta : {0.02, 0.0}) {
    for (Contact &c : contacts) c.cn = zeta * c.kn;
    const ContactNetwork net(2, ContactModel::Normal, network.grains(), contacts);
    if (is_host()) {
      for (double omega : {0.5, 1.2}) {
        const HelmholtzSolution sol = team_solver.solve(net.stiffness_matrix(), net.damping_matrix(),
                                                        net.mass_diagonal(), omega, fixed, values);
        HelmholtzSolver umfpack(LinearSolverChoice::Lu);
        const HelmholtzSolution reference = umfpack.solve(net.stiffness_matrix(), net.damping_matrix(),
                                                          net.mass_diagonal(), omega, fixed, values);
        ASSERT_TRUE(sol.ok()) << sol.message;
        EXPECT_LT((sol.q - reference.q).norm(), 1e-8 * reference.q.norm());
      }
      team_solver.release_workers();
    } else {
      team_solver.serve();
    }
  }
}

// The factorisation work is shared by the ranks of the team (a network large
// enough for MUMPS to split its elimination tree), and the host's answer is
// that of a dense solve
TEST(MumpsParallel, EveryRankFactorises)
{
  SKIP_WITHOUT_MUMPS();
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MumpsTeam team(MPI_COMM_WORLD);
  MumpsLdlt<double> ldlt(team);
  const Eigen::SparseMatrix<double> a = helmholtz_matrix<double>(70, 50, 1.1, 0.0);    // 6860 DOFs
  if (team.host()) {
    ldlt.compute(a);
    ASSERT_EQ(ldlt.info(), Eigen::Success) << ldlt.message();
    const Eigen::MatrixXd b = random_rhs<double>(static_cast<int>(a.rows()), 1);
    const Eigen::MatrixXd x = ldlt.solve(b);
    team.release();
    EXPECT_LT((a * x - b).norm(), 1e-10 * b.norm());
  } else {
    team.serve();
  }
  const double mine = ldlt.local_factorisation_flops();
  std::vector<double> all(size);
  MPI_Allgather(&mine, 1, MPI_DOUBLE, all.data(), 1, MPI_DOUBLE, MPI_COMM_WORLD);
  for (int r = 0; r < size; ++r) EXPECT_GT(all[r], 0.0) << "rank " << r << " did no factorisation work";
}

TEST(MumpsLdlt, ABuildWithoutMumpsRefusesItAndAutoIsLu)
{
  MumpsTeam team(MPI_COMM_SELF);
  const std::string auto_real = make_factoriser<double>(LinearSolverChoice::Auto, team, MumpsSettings())->name();
  const std::string auto_complex = make_factoriser<Complex>(LinearSolverChoice::Auto, team, MumpsSettings())->name();
  if (mumps_available()) {
    EXPECT_EQ(auto_real, "mumps");
    EXPECT_EQ(auto_complex, "mumps");
    return;
  }
  EXPECT_EQ(auto_real, "lu");
  EXPECT_EQ(auto_complex, "lu");
  try {
    MumpsLdlt<double> ldlt(team);
    FAIL() << "MumpsLdlt built without MUMPS";
  } catch (const SolverError &e) {
    EXPECT_NE(std::string(e.what()).find("has no MUMPS (Debian: libmumps-dev"), std::string::npos) << e.what();
  }
  // solver auto still answers, with UMFPACK, as solver lu does
  std::vector<int> fixed;
  const ContactNetwork network = AcousticTest::disordered_network(20, 10, 5u, fixed);
  Eigen::VectorXcd values = Eigen::VectorXcd::Zero(fixed.size());
  for (std::size_t k = 1; k < fixed.size(); k += 2) values[k] = 1.0;
  HelmholtzSolver automatic(LinearSolverChoice::Auto), lu(LinearSolverChoice::Lu);
  const HelmholtzSolution a = automatic.solve(network.stiffness_matrix(), network.damping_matrix(),
                                              network.mass_diagonal(), 0.9, fixed, values);
  const HelmholtzSolution b = lu.solve(network.stiffness_matrix(), network.damping_matrix(),
                                       network.mass_diagonal(), 0.9, fixed, values);
  ASSERT_TRUE(a.ok() && b.ok()) << a.message << b.message;
  EXPECT_EQ(a.factorisation, "lu");
  EXPECT_EQ((a.q - b.q).norm(), 0.0);
}
