/* ----------------------------------------------------------------------
   Unit tests: the Helmholtz solver (driven harmonic response).
------------------------------------------------------------------------- */

#include "acoustic_contact_network.h"
#include "acoustic_helmholtz_solver.h"
#include "acoustic_solver_error.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <complex>
#include <ostream>
#include <vector>

using namespace Acoustic;
using Complex = std::complex<double>;

namespace Acoustic {
// readable test parameter in the output of a parametrised test
void PrintTo(LinearSolverChoice choice, std::ostream *os)
{
  *os << linear_solver_name(choice);
}
}    // namespace Acoustic

namespace {

// Chain of grains 0..n_free along x in 2D (model normal): equal masses m, springs k between
// neighbours, dashpots c.  The y DOFs carry mass only.
ContactNetwork chain(int n_free, double m, double k, double c = 0.0)
{
  std::vector<Grain> grains(n_free + 1, Grain{m, 0.5});
  std::vector<Contact> contacts;
  for (int g = 0; g < n_free; ++g) contacts.push_back(Contact{g + 1, g, Eigen::Vector3d(1, 0, 0), k, 0.0, c, 0.0});
  return ContactNetwork(2, ContactModel::Normal, grains, contacts);
}

struct Source {
  std::vector<int> dofs;
  Eigen::VectorXcd values;
};

// grain 0 prescribed: ux = 1, uy = 0
Source chain_source()
{
  Source s;
  s.dofs = {0, 1};
  s.values = Eigen::VectorXcd::Zero(2);
  s.values[0] = 1.0;
  return s;
}

// Fixed-free chain driven at grain 0 with unit amplitude (free end at grain N):
//   in the band, cos(theta) = 1 - m w^2/(2k):  q_n = cos((N + 1/2 - n) theta) / cos((N + 1/2) theta)
//   above it, cosh(phi) = m w^2/(2k) - 1:      q_n = (-1)^n sinh((N + 1/2 - n) phi) / sinh((N + 1/2) phi)
double chain_closed_form(int n, int n_free, double m, double k, double omega)
{
  const double c = 1.0 - m * omega * omega / (2.0 * k);
  const double big_n = n_free + 0.5;
  if (c >= -1.0) {
    const double theta = std::acos(c);
    return std::cos((big_n - n) * theta) / std::cos(big_n * theta);
  }
  const double phi = std::acosh(-c);
  return (n % 2 == 0 ? 1.0 : -1.0) * std::sinh((big_n - n) * phi) / std::sinh(big_n * phi);
}

// what HelmholtzSolution::factorisation reports for a choice (auto is MUMPS)
std::string expected_factorisation(LinearSolverChoice choice)
{
  switch (choice) {
    case LinearSolverChoice::Ldlt:
      return "ldlt";
    case LinearSolverChoice::Lu:
      return "lu";
    default:
      return "mumps";
  }
}

const std::vector<LinearSolverChoice> all_choices = {LinearSolverChoice::Auto, LinearSolverChoice::Ldlt,
                                                     LinearSolverChoice::Lu, LinearSolverChoice::Mumps};

class DrivenChain : public ::testing::TestWithParam<LinearSolverChoice> {};

}    // namespace

TEST_P(DrivenChain, MatchesClosedFormBelowAndAboveTheBand)
{
  const int n_free = 25;
  const double m = 2.0, k = 3.0;
  const double band_edge = 2.0 * std::sqrt(k / m);
  const ContactNetwork network = chain(n_free, m, k);
  const Source source = chain_source();
  HelmholtzSolver solver(GetParam());
  for (double fraction : {0.07, 0.37, 0.81, 1.3, 2.5}) {
    const double omega = fraction * band_edge;
    SCOPED_TRACE("omega / band edge = " + std::to_string(fraction));
    const HelmholtzSolution sol = solver.solve(network.stiffness_matrix(), network.damping_matrix(),
                                               network.mass_diagonal(), omega, source.dofs, source.values);
    ASSERT_TRUE(sol.ok()) << sol.message;
    EXPECT_EQ(sol.factorisation, expected_factorisation(GetParam()));
    EXPECT_LT(sol.relative_residual, 1e-12);
    double scale = 0.0;
    for (int n = 0; n <= n_free; ++n) scale = std::max(scale, std::abs(chain_closed_form(n, n_free, m, k, omega)));
    for (int n = 0; n <= n_free; ++n) {
      EXPECT_NEAR(sol.q[network.dof(n, 0)].real(), chain_closed_form(n, n_free, m, k, omega), 1e-10 * scale);
      EXPECT_EQ(sol.q[network.dof(n, 0)].imag(), 0.0);
      EXPECT_EQ(sol.q[network.dof(n, 1)], 0.0);    // mass-only DOFs stay at rest
    }
  }
  // one pattern: one analysis, one numeric factorisation per solve
  EXPECT_EQ(solver.num_analyses(), 1);
  EXPECT_EQ(solver.num_factorisations(), 5);
}

INSTANTIATE_TEST_SUITE_P(Solvers, DrivenChain,
                         ::testing::ValuesIn(all_choices),
                         [](const ::testing::TestParamInfo<LinearSolverChoice> &info) {
                           return linear_solver_name(info.param);
                         });

TEST(HelmholtzSolver, DampedChainMatchesDenseComplexSolve)
{
  const int n_free = 30;
  const double m = 1.5, k = 4.0, c = 0.2;
  const ContactNetwork network = chain(n_free, m, k, c);
  const Source source = chain_source();
  ASSERT_TRUE(network.has_damping());

  for (double omega : {0.5, 2.0, 3.1, 5.0}) {
    for (LinearSolverChoice choice : {LinearSolverChoice::Auto, LinearSolverChoice::Lu}) {
      SCOPED_TRACE(linear_solver_name(choice));
      HelmholtzSolver solver(choice);    // complex symmetric: MUMPS (auto) or complex LU
      const HelmholtzSolution sol = solver.solve(network.stiffness_matrix(), network.damping_matrix(),
                                                 network.mass_diagonal(), omega, source.dofs, source.values);
      ASSERT_TRUE(sol.ok()) << sol.message;
      EXPECT_EQ(sol.factorisation, expected_factorisation(choice));

      // independent dense solve of the x DOFs of grains 1..N:
      // (K + i w C - w^2 M) with K, C tridiagonal (free end), right-hand side (k + i w c) at grain 1
      const Complex spring(k, omega * c);
      Eigen::MatrixXcd a = Eigen::MatrixXcd::Zero(n_free, n_free);
      for (int r = 0; r < n_free; ++r) {
        a(r, r) = (r + 1 < n_free ? 2.0 : 1.0) * spring - omega * omega * m;
        if (r + 1 < n_free) a(r, r + 1) = a(r + 1, r) = -spring;
      }
      Eigen::VectorXcd b = Eigen::VectorXcd::Zero(n_free);
      b[0] = spring;
      const Eigen::VectorXcd expected = a.partialPivLu().solve(b);
      for (int r = 0; r < n_free; ++r)
        EXPECT_LT(std::abs(sol.q[network.dof(r + 1, 0)] - expected[r]), 1e-10 * expected.cwiseAbs().maxCoeff());
      EXPECT_GT(expected.imag().cwiseAbs().maxCoeff(), 1e-3);    // the damping matters
    }
  }
}

TEST(HelmholtzSolver, ReusesSymbolicAnalysisWhilePatternIsUnchanged)
{
  for (LinearSolverChoice choice : all_choices) {
    SCOPED_TRACE(linear_solver_name(choice));
    const Source source = chain_source();
    HelmholtzSolver solver(choice);
    const ContactNetwork first = chain(40, 1.0, 2.0);
    HelmholtzSolution sol = solver.solve(first.stiffness_matrix(), first.damping_matrix(), first.mass_diagonal(),
                                         1.1, source.dofs, source.values);
    ASSERT_TRUE(sol.ok());
    EXPECT_EQ(solver.num_analyses(), 1);
    EXPECT_EQ(solver.num_factorisations(), 1);

    // same pattern, other values and frequency: numeric refactorisation only
    const ContactNetwork second = chain(40, 1.7, 5.0);
    sol = solver.solve(second.stiffness_matrix(), second.damping_matrix(), second.mass_diagonal(), 2.3,
                       source.dofs, source.values);
    ASSERT_TRUE(sol.ok());
    EXPECT_EQ(solver.num_analyses(), 1);
    EXPECT_EQ(solver.num_factorisations(), 2);
    HelmholtzSolver fresh(choice);
    const HelmholtzSolution reference = fresh.solve(second.stiffness_matrix(), second.damping_matrix(),
                                                    second.mass_diagonal(), 2.3, source.dofs, source.values);
    EXPECT_LT((sol.q - reference.q).norm(), 1e-12 * reference.q.norm());

    // a new contact changes the pattern: analysed again
    std::vector<Contact> contacts = second.contacts();
    contacts.push_back(Contact{10, 5, Eigen::Vector3d(1, 0, 0), 0.5, 0.0, 0.0, 0.0});
    const ContactNetwork third(2, ContactModel::Normal, second.grains(), contacts);
    sol = solver.solve(third.stiffness_matrix(), third.damping_matrix(), third.mass_diagonal(), 2.3, source.dofs,
                       source.values);
    ASSERT_TRUE(sol.ok());
    EXPECT_EQ(solver.num_analyses(), 2);
    EXPECT_EQ(solver.num_factorisations(), 3);
    HelmholtzSolver fresh_third(choice);
    const HelmholtzSolution reference_third = fresh_third.solve(
        third.stiffness_matrix(), third.damping_matrix(), third.mass_diagonal(), 2.3, source.dofs, source.values);
    EXPECT_LT((sol.q - reference_third.q).norm(), 1e-12 * reference_third.q.norm());

    // a different set of prescribed DOFs changes the free-free pattern too
    Source bigger = source;
    bigger.dofs.push_back(third.dof(40, 0));
    bigger.values.conservativeResize(3);
    bigger.values[2] = Complex(0.0, 1.0);
    sol = solver.solve(third.stiffness_matrix(), third.damping_matrix(), third.mass_diagonal(), 2.3, bigger.dofs,
                       bigger.values);
    ASSERT_TRUE(sol.ok());
    EXPECT_EQ(solver.num_analyses(), 3);
    EXPECT_EQ(sol.q[third.dof(40, 0)], Complex(0.0, 1.0));

    const SolverTimings &t = solver.last_timings();
    EXPECT_GE(t.analysis, 0.0);
    EXPECT_GT(t.factorisation + t.solve, 0.0);
  }
}

TEST(HelmholtzSolver, SingularAtZeroFrequencyWithFloatingGrains)
{
  // grains 0-1-2 chain, grains 3-4 a separate pair (floating), grain 5 alone
  const Eigen::Vector3d x(1, 0, 0);
  const ContactNetwork network(2, ContactModel::Normal, std::vector<Grain>(6, Grain{1.0, 0.5}),
                               {Contact{1, 0, x, 1.0, 0, 0, 0}, Contact{2, 1, x, 1.0, 0, 0, 0},
                                Contact{4, 3, x, 1.0, 0, 0, 0}});
  const Source source = chain_source();
  for (LinearSolverChoice choice : all_choices) {
    SCOPED_TRACE(linear_solver_name(choice));
    HelmholtzSolver solver(choice);
    const HelmholtzSolution sol = solver.solve(network.stiffness_matrix(), network.damping_matrix(),
                                               network.mass_diagonal(), 0.0, source.dofs, source.values);
    EXPECT_EQ(sol.status, SolveStatus::FactorisationFailed);
    EXPECT_FALSE(sol.message.empty());
    EXPECT_TRUE(sol.q.allFinite());
    EXPECT_EQ(sol.q[0], 1.0);
    EXPECT_EQ(sol.q.tail(sol.q.size() - 2).cwiseAbs().maxCoeff(), 0.0);

    // the same network is fine at omega > 0: floating grains just stay at rest
    const HelmholtzSolution moving = solver.solve(network.stiffness_matrix(), network.damping_matrix(),
                                                  network.mass_diagonal(), 0.3, source.dofs, source.values);
    EXPECT_TRUE(moving.ok()) << moving.message;
    EXPECT_GT(std::abs(moving.q[network.dof(2, 0)]), 0.1);
    EXPECT_EQ(moving.q.segment(network.dof(3, 0), 6).cwiseAbs().maxCoeff(), 0.0);
  }
}

TEST(HelmholtzSolver, SingularOnAnEigenfrequency)
{
  // one free grain of mass 1 on a spring k = 1 to the source: A = k - w^2 m = 0 at w = 1
  const ContactNetwork network(2, ContactModel::Normal, std::vector<Grain>(2, Grain{1.0, 0.5}),
                               {Contact{1, 0, Eigen::Vector3d(1, 0, 0), 1.0, 0, 0, 0}});
  const Source source = chain_source();
  for (LinearSolverChoice choice : all_choices) {
    SCOPED_TRACE(linear_solver_name(choice));
    HelmholtzSolver solver(choice);
    const HelmholtzSolution sol = solver.solve(network.stiffness_matrix(), network.damping_matrix(),
                                               network.mass_diagonal(), 1.0, source.dofs, source.values);
    EXPECT_FALSE(sol.ok());
    EXPECT_EQ(sol.status, SolveStatus::FactorisationFailed);
    if (choice == LinearSolverChoice::Mumps || choice == LinearSolverChoice::Auto) {
      EXPECT_NE(sol.message.find("MUMPS error INFOG(1) = -10"), std::string::npos) << sol.message;
    }
    EXPECT_TRUE(sol.q.allFinite());
    EXPECT_TRUE(std::isfinite(sol.relative_residual));
    // just off resonance it solves: q_1 = k / (k - w^2 m)
    const HelmholtzSolution near = solver.solve(network.stiffness_matrix(), network.damping_matrix(),
                                                network.mass_diagonal(), 0.9, source.dofs, source.values);
    ASSERT_TRUE(near.ok()) << near.message;
    EXPECT_NEAR(near.q[2].real(), 1.0 / (1.0 - 0.81), 1e-12);
  }
}

TEST(HelmholtzSolver, ZeroSourceGivesZeroResponse)
{
  const ContactNetwork network = chain(5, 1.0, 1.0);
  HelmholtzSolver solver;
  const HelmholtzSolution sol = solver.solve(network.stiffness_matrix(), network.damping_matrix(),
                                             network.mass_diagonal(), 0.7, {0, 1}, Eigen::VectorXcd::Zero(2));
  EXPECT_TRUE(sol.ok());
  EXPECT_EQ(sol.q.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(solver.num_factorisations(), 0);
}

TEST(HelmholtzSolver, RejectsInvalidInput)
{
  const ContactNetwork network = chain(5, 1.0, 1.0, 0.1);
  const Source source = chain_source();
  const Eigen::SparseMatrix<double> k = network.stiffness_matrix(), c = network.damping_matrix();
  const Eigen::VectorXd m = network.mass_diagonal();
  HelmholtzSolver ldlt(LinearSolverChoice::Ldlt);
  EXPECT_THROW(ldlt.solve(k, c, m, 1.0, source.dofs, source.values), SolverError);    // damped: not for ldlt
  EXPECT_NO_THROW(ldlt.solve(k, Eigen::SparseMatrix<double>(), m, 1.0, source.dofs, source.values));
  HelmholtzSolver solver;
  EXPECT_THROW(solver.solve(k, c, m, -1.0, source.dofs, source.values), SolverError);
  EXPECT_THROW(solver.solve(k, c, m, 1.0, {0, 0}, source.values), SolverError);
  EXPECT_THROW(solver.solve(k, c, m, 1.0, {0, 99}, source.values), SolverError);
  EXPECT_THROW(solver.solve(k, c, m, 1.0, {0}, source.values), SolverError);
  EXPECT_THROW(solver.solve(k, c, Eigen::VectorXd::Zero(m.size()), 1.0, source.dofs, source.values), SolverError);
  EXPECT_THROW(HelmholtzSolver(LinearSolverChoice::Auto, 0.0), SolverError);
  // omega^2 m beyond the range of doubles: a clear refusal, not a "resonance"
  try {
    solver.solve(k, Eigen::SparseMatrix<double>(), m, 2.0 * M_PI * 1e200, source.dofs, source.values);
    FAIL() << "omega = 2 pi 1e200 accepted";
  } catch (const SolverError &e) {
    EXPECT_NE(std::string(e.what()).find("the frequency is out of range for this network"),
              std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("omega = 6.28319e+200"), std::string::npos) << e.what();
  }
  EXPECT_THROW(solver.solve(k, c, m, 1e200, source.dofs, source.values), SolverError);
  EXPECT_EQ(linear_solver_from_name("ldlt"), LinearSolverChoice::Ldlt);
  EXPECT_EQ(linear_solver_from_name("mumps"), LinearSolverChoice::Mumps);
  try {
    linear_solver_from_name("cg");
    FAIL() << "unknown solver name accepted";
  } catch (const SolverError &e) {
    EXPECT_NE(std::string(e.what()).find("auto, ldlt, lu, mumps"), std::string::npos);
  }
}

TEST(HelmholtzSolver, EarlierFactorsPreconditionASlightlyChangedNetwork)
{
  // undamped (real) and damped (complex) factorisations
  for (double c : {0.0, 0.05}) {
    for (LinearSolverChoice choice : {LinearSolverChoice::Auto, LinearSolverChoice::Lu, LinearSolverChoice::Mumps}) {
      SCOPED_TRACE(linear_solver_name(choice) + (c > 0.0 ? " damped" : " undamped"));
      const Source source = chain_source();
      HelmholtzSolver solver(choice);
      solver.set_reuse_factorisation(true);
      const ContactNetwork first = chain(40, 1.0, 2.0, c);
      HelmholtzSolution sol = solver.solve(first.stiffness_matrix(), first.damping_matrix(),
                                           first.mass_diagonal(), 1.1, source.dofs, source.values);
      ASSERT_TRUE(sol.ok());
      const long factorisations = solver.num_factorisations();

      // one more contact and a slightly stiffer one: solved with the earlier factors
      std::vector<Contact> contacts = first.contacts();
      contacts[7].kn *= 1.01;
      contacts.push_back(Contact{12, 10, Eigen::Vector3d(1, 0, 0), 0.02, 0.0, c > 0 ? 0.001 : 0.0, 0.0});
      const ContactNetwork second(2, ContactModel::Normal, first.grains(), contacts);
      sol = solver.solve(second.stiffness_matrix(), second.damping_matrix(), second.mass_diagonal(), 1.1,
                         source.dofs, source.values);
      ASSERT_TRUE(sol.ok()) << sol.message;
      EXPECT_EQ(solver.num_reuses(), 1);
      EXPECT_EQ(solver.num_factorisations(), factorisations);
      EXPECT_NE(sol.factorisation.find("earlier factors"), std::string::npos) << sol.factorisation;
      HelmholtzSolver fresh(choice);
      const HelmholtzSolution reference = fresh.solve(second.stiffness_matrix(), second.damping_matrix(),
                                                      second.mass_diagonal(), 1.1, source.dofs, source.values);
      EXPECT_LT((sol.q - reference.q).norm(), 1e-7 * reference.q.norm());
      EXPECT_LE(sol.relative_residual, solver.residual_tolerance());

      // a very different network: the iteration gives up and the matrix is factorised
      const ContactNetwork third = chain(40, 1.0, 9.0, c);
      sol = solver.solve(third.stiffness_matrix(), third.damping_matrix(), third.mass_diagonal(), 3.9,
                         source.dofs, source.values);
      ASSERT_TRUE(sol.ok()) << sol.message;
      EXPECT_GT(solver.num_factorisations(), factorisations);
      HelmholtzSolver fresh_third(choice);
      const HelmholtzSolution reference_third = fresh_third.solve(
          third.stiffness_matrix(), third.damping_matrix(), third.mass_diagonal(), 3.9, source.dofs, source.values);
      EXPECT_LT((sol.q - reference_third.q).norm(), 1e-7 * reference_third.q.norm());

      // after that failure the next 4 solves factorise directly, even for tiny changes;
      // the 5th is answered with the earlier factors again
      const long reuses = solver.num_reuses();
      for (int k = 1; k <= 5; ++k) {
        std::vector<Contact> nudged = third.contacts();
        nudged[3].kn *= 1.0 + 1e-4 * k;
        const ContactNetwork net(2, ContactModel::Normal, third.grains(), nudged);
        const long before = solver.num_factorisations();
        sol = solver.solve(net.stiffness_matrix(), net.damping_matrix(), net.mass_diagonal(), 3.9, source.dofs,
                           source.values);
        ASSERT_TRUE(sol.ok()) << sol.message;
        EXPECT_EQ(solver.num_factorisations(), before + (k <= 4 ? 1 : 0)) << "solve " << k;
      }
      EXPECT_EQ(solver.num_reuses(), reuses + 1);
    }
  }
}

TEST(HelmholtzSolver, LastSolutionAnswersTheSameSystem)
{
  // with reuse on, the same system, or the same up to round-off, is answered by the
  // last solution whatever the back-off; with reuse off it is factorised again.
  // Any real change of A or b is solved anew.
  for (double c : {0.0, 0.1}) {
    for (bool reuse : {false, true}) {
      SCOPED_TRACE(std::string(reuse ? "reuse on" : "reuse off") + (c > 0.0 ? ", damped" : ""));
      const ContactNetwork network = chain(20, 1.0, 2.0, c);
      const Source source = chain_source();
      HelmholtzSolver solver;
      solver.set_reuse_factorisation(reuse);
      const HelmholtzSolution first = solver.solve(network.stiffness_matrix(), network.damping_matrix(),
                                                   network.mass_diagonal(), 1.3, source.dofs, source.values);
      ASSERT_TRUE(first.ok()) << first.message;
      const HelmholtzSolution again = solver.solve(network.stiffness_matrix(), network.damping_matrix(),
                                                   network.mass_diagonal(), 1.3, source.dofs, source.values);
      ASSERT_TRUE(again.ok()) << again.message;
      EXPECT_EQ(solver.num_factorisations(), reuse ? 1 : 2);
      EXPECT_EQ(solver.num_reuses(), reuse ? 1 : 0);
      EXPECT_LT((again.q - first.q).norm(), 1e-12 * first.q.norm());
      EXPECT_EQ(again.factorisation.find("earlier solution") != std::string::npos, reuse) << again.factorisation;

      // the same up to round-off
      std::vector<Contact> contacts = network.contacts();
      contacts[4].kn *= 1.0 + 1e-13;
      const ContactNetwork nudged(2, ContactModel::Normal, network.grains(), contacts);
      const HelmholtzSolution close = solver.solve(nudged.stiffness_matrix(), nudged.damping_matrix(),
                                                   nudged.mass_diagonal(), 1.3, source.dofs, source.values);
      ASSERT_TRUE(close.ok()) << close.message;
      EXPECT_EQ(solver.num_factorisations(), reuse ? 1 : 3);
      EXPECT_LT((close.q - first.q).norm(), 1e-9 * first.q.norm());

      // another amplitude of the source (b changes): not the last solution
      Source louder = source;
      louder.values *= 2.0;
      const HelmholtzSolution twice = solver.solve(network.stiffness_matrix(), network.damping_matrix(),
                                                   network.mass_diagonal(), 1.3, louder.dofs, louder.values);
      ASSERT_TRUE(twice.ok()) << twice.message;
      EXPECT_EQ(twice.factorisation.find("earlier solution"), std::string::npos);
      EXPECT_LT((twice.q - 2.0 * first.q).norm(), 1e-10 * first.q.norm());
      // another frequency (A changes): not the last solution either
      const HelmholtzSolution other = solver.solve(network.stiffness_matrix(), network.damping_matrix(),
                                                   network.mass_diagonal(), 1.31, source.dofs, source.values);
      ASSERT_TRUE(other.ok()) << other.message;
      EXPECT_EQ(other.factorisation.find("earlier solution"), std::string::npos);
      EXPECT_GT((other.q - first.q).norm(), 1e-6 * first.q.norm());
    }
  }
}
