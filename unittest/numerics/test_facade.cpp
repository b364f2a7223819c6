/* ----------------------------------------------------------------------
   Unit tests: the C++98 facade of the numerics (acoustic_gathered_drive.h,
   acoustic_contact_factor.h) in the shared library acoustic_liggghts:
   closed forms, the same bits as the classes (and the calls of fix
   acoustic/mindlin) it wraps, C++98 callers (facade_cxx98.cpp), and bad
   input returned as a status with a message, never thrown.
------------------------------------------------------------------------- */

#include "acoustic_contact_factor.h"
#include "acoustic_gathered_drive.h"
#include "facade_cxx98.h"

#include "acoustic_contact_network.h"
#include "acoustic_helmholtz_solver.h"
#include "acoustic_mindlin_law.h"
#include "acoustic_mumps_ldlt.h"
#include "network_builders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <functional>
#include <limits>
#include <ostream>
#include <random>
#include <string>
#include <vector>

using namespace Acoustic;
using Complex = std::complex<double>;

namespace {

const double inf = std::numeric_limits<double>::infinity();
const double qnan = std::numeric_limits<double>::quiet_NaN();

bool same_bits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

// index of the first entry whose bits differ, -1 if none (and equal sizes)
long first_difference(const std::vector<double> &a, const std::vector<double> &b)
{
  if (a.size() != b.size()) return 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (!same_bits(a[k], b[k])) return static_cast<long>(k);
  return -1;
}

bool all_finite(const std::vector<double> &v)
{
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

Complex dof_value(const GatheredDriveResult &r, int grain, int component)
{
  const std::size_t at = 2 * static_cast<std::size_t>(grain * r.dofs_per_grain + component);
  return Complex(r.q[at], r.q[at + 1]);
}

std::vector<double> pairs(const Eigen::VectorXcd &q)
{
  std::vector<double> v;
  for (Eigen::Index k = 0; k < q.size(); ++k) {
    v.push_back(q[k].real());
    v.push_back(q[k].imag());
  }
  return v;
}

/* ----------------------------------------------------------------------
   the gathered drive
------------------------------------------------------------------------- */

// Two grains of mass m in a row on a wall driven with amplitude 1, springs
// of complex stiffness k* = k + i omega c (wall - 0 - 1, grain 1 free):
//   k* (q0 - 1) + k* (q0 - q1) - w^2 m q0 = 0,   k* (q1 - q0) - w^2 m q1 = 0
// so q1 = k* q0 / a and q0 = k* a / ((2 k* - w^2 m) a - k*^2), a = k* - w^2 m.
void two_grain_closed_form(double m, double k, double c, double omega, Complex &q0, Complex &q1)
{
  const Complex ks(k, omega * c);
  const Complex a = ks - omega * omega * m;
  q0 = ks * a / ((2.0 * ks - omega * omega * m) * a - ks * ks);
  q1 = ks * q0 / a;
}

struct ChainCase {
  double c, omega;
};

// readable parameter in the test names
void PrintTo(const ChainCase &cc, std::ostream *os)
{
  *os << "c=" << cc.c << ",omega=" << cc.omega;
}

class FacadeChain : public ::testing::TestWithParam<ChainCase> {};

TEST_P(FacadeChain, ClosedForm)
{
  const double m = 0.8, k = 1.3;    // eigenfrequencies 0.788 and 2.06 (undamped)
  const ChainCase cc = GetParam();
  // built by C++98 code: contacts reversed, the wall's from the wall side
  const GatheredDriveInput input = FacadeCxx98::chain_input(2, m, k, cc.c, cc.omega);
  GatheredDriveResult result;
  ASSERT_TRUE(solve_gathered_drive(input, result)) << result.message;
  EXPECT_EQ(result.status, FacadeStatus::Success);
  EXPECT_TRUE(result.message.empty());
  ASSERT_EQ(result.dofs_per_grain, 2);
  ASSERT_EQ(result.q.size(), 2u * 2u * 3u);
  EXPECT_LT(result.relative_residual, 1e-12);
  EXPECT_EQ(result.factorisation, "lu");
  Complex q0, q1;
  two_grain_closed_form(m, k, cc.c, cc.omega, q0, q1);
  EXPECT_LT(std::abs(dof_value(result, 0, 0) - q0), 1e-12 * std::abs(q0));
  EXPECT_LT(std::abs(dof_value(result, 1, 0) - q1), 1e-12 * std::abs(q1));
  // y: no spring, no drive; the wall: x driven, y clamped by the facade
  EXPECT_EQ(dof_value(result, 0, 1), Complex(0.0));
  EXPECT_EQ(dof_value(result, 1, 1), Complex(0.0));
  EXPECT_EQ(dof_value(result, 2, 0), Complex(1.0));
  EXPECT_EQ(dof_value(result, 2, 1), Complex(0.0));
  if (cc.c == 0.0) {
    EXPECT_EQ(q0.imag(), 0.0);
    EXPECT_EQ(result.q[1], 0.0);    // undamped: real
  }
}

INSTANTIATE_TEST_SUITE_P(Facade, FacadeChain,
                         ::testing::Values(ChainCase{0.0, 0.5}, ChainCase{0.0, 1.4},
                                           ChainCase{0.0, 3.0}, ChainCase{0.05, 0.788},
                                           ChainCase{0.2, 1.4}));

TEST(FacadeGatheredDrive, FrequencyOrAngularFrequency)
{
  GatheredDriveInput input = FacadeCxx98::chain_input(2, 0.8, 1.3, 0.1, -1.0);
  const double f = 0.21;
  input.frequency = f;
  GatheredDriveResult by_f, by_omega;
  ASSERT_TRUE(solve_gathered_drive(input, by_f)) << by_f.message;
  input.frequency = -1.0;
  input.angular_frequency = 2.0 * M_PI * f;
  ASSERT_TRUE(solve_gathered_drive(input, by_omega)) << by_omega.message;
  EXPECT_EQ(first_difference(by_f.q, by_omega.q), -1);
}

// what FixAcousticMindlin does with its gathered network on rank 0
// (VibrationNetwork::index_contacts, drive_dofs, solve_drive), written out
struct FixReference {
  std::vector<double> q;
  double residual;
  std::string factorisation;
};

FixReference fix_reference(int dim, ContactModel model, std::vector<Grain> grains,
                           const std::vector<Contact> &given, const std::vector<int> &walls,
                           int source_wall, const std::vector<int> &source_grains,
                           const double *direction, double frequency, LinearSolverChoice choice)
{
  std::vector<Contact> contacts;
  for (const Contact &c : given) {
    const bool flip = c.i > c.j;    // from the lower to the higher ID
    const double sign = flip ? -1.0 : 1.0;
    contacts.push_back(Contact{flip ? c.j : c.i, flip ? c.i : c.j,
                               Eigen::Vector3d(sign * c.normal[0], sign * c.normal[1],
                                               sign * c.normal[2]),
                               c.kn, c.kt, c.cn, c.ct});
  }
  std::sort(contacts.begin(), contacts.end(), [](const Contact &a, const Contact &b) {
    return (a.i < b.i) || (a.i == b.i && a.j < b.j);
  });
  for (int w : walls) grains[w] = Grain{1.0, 1.0};
  const ContactNetwork net(dim, model, grains, contacts);
  const int ndof = net.dofs_per_grain();
  std::vector<int> prescribed;
  std::vector<Complex> amplitudes;
  for (std::size_t k = 0; k < walls.size(); ++k)
    for (int d = 0; d < ndof; ++d) {
      prescribed.push_back(net.dof(walls[k], d));
      amplitudes.push_back((static_cast<int>(k) == source_wall && d < dim) ? direction[d] : 0.0);
    }
  for (int g : source_grains) {    // source_mode all
    for (int d = 0; d < dim; ++d) {
      prescribed.push_back(net.dof(g, d));
      amplitudes.push_back(direction[d]);
    }
    for (int d = dim; d < ndof; ++d) {
      prescribed.push_back(net.dof(g, d));
      amplitudes.push_back(0.0);
    }
  }
  Eigen::VectorXcd qp(static_cast<Eigen::Index>(amplitudes.size()));
  for (std::size_t k = 0; k < amplitudes.size(); ++k) qp[k] = amplitudes[k];
  MumpsSettings settings;
  if (dim == 3 && metis_available()) settings.ordering = MumpsOrdering::Metis;
  HelmholtzSolver solver(choice, 1e-6, MPI_COMM_SELF, settings);
  const Eigen::SparseMatrix<double> K = net.stiffness_matrix();
  const Eigen::SparseMatrix<double> C =
      net.has_damping() ? net.damping_matrix() : Eigen::SparseMatrix<double>(0, 0);
  const Eigen::VectorXd M = net.mass_diagonal();
  const HelmholtzSolution sol = solver.solve(K, C, M, 2.0 * M_PI * frequency, prescribed, qp);
  EXPECT_TRUE(sol.ok()) << sol.message;
  return FixReference{pairs(sol.q), sol.relative_residual, sol.factorisation};
}

GatheredContact facade_contact(const Contact &c)
{
  GatheredContact g;
  g.i = c.i;
  g.j = c.j;
  for (int d = 0; d < 3; ++d) g.normal[d] = c.normal[d];
  g.kn = c.kn;
  g.kt = c.kt;
  g.cn = c.cn;
  g.ct = c.ct;
  return g;
}

// A 3 x 3 x 3 disordered packing (model full, damped) between a driven
// bottom wall and a clamped top wall: the facade gives the bits of the
// fix's path, whatever the order and orientation of the contacts.
TEST(FacadeGatheredDrive, SameBitsAsTheFixPathWithWalls)
{
  const AcousticTest::TestNetwork t = AcousticTest::disordered_3d(3, 3, ContactModel::Full, 0.05, 7);
  std::vector<Grain> grains = t.network.grains();
  std::vector<Contact> contacts = t.network.contacts();
  const int ngrains = static_cast<int>(grains.size());
  const int bottom = ngrains, top = ngrains + 1;
  grains.push_back(Grain{inf, 0.0});
  grains.push_back(Grain{inf, 0.0});
  for (int g = 0; g < 9; ++g) {    // layer z = 0 on the bottom wall, z = 2 under the top one
    contacts.push_back(Contact{g, bottom, Eigen::Vector3d(0, 0, 1), 1.1, 0.35, 0.04, 0.02});
    contacts.push_back(Contact{top, 18 + g, Eigen::Vector3d(0, 0, 1), 0.9, 0.3, 0.03, 0.01});
  }
  const double direction[3] = {0.6, 0.0, 0.8}, f = 0.23;

  GatheredDriveInput input;
  input.dimension = 3;
  input.model = FacadeContactModel::Full;
  for (const Grain &g : grains) input.grains.push_back(GatheredGrain(g.mass, g.radius));
  for (const Contact &c : contacts) input.contacts.push_back(facade_contact(c));
  // the source wall's translations; its rotations and the top wall: clamped by the facade
  for (int d = 0; d < 3; ++d) input.prescribed.push_back(PrescribedDof(bottom, d, direction[d]));
  input.frequency = f;
  GatheredDriveResult result;
  ASSERT_TRUE(solve_gathered_drive(input, result)) << result.message;
  ASSERT_EQ(result.dofs_per_grain, 6);

  const FixReference ref = fix_reference(3, ContactModel::Full, grains, contacts, {bottom, top}, 0,
                                         {}, direction, f, LinearSolverChoice::Auto);
  EXPECT_EQ(first_difference(result.q, ref.q), -1);
  EXPECT_TRUE(same_bits(result.relative_residual, ref.residual));
  EXPECT_EQ(result.factorisation, ref.factorisation);
  EXPECT_TRUE(all_finite(result.q));
  EXPECT_EQ(dof_value(result, bottom, 2), Complex(0.8));
  EXPECT_EQ(dof_value(result, top, 2), Complex(0.0));

  // contacts shuffled and half of them reversed: the same bits
  std::mt19937 rng(11);
  std::shuffle(input.contacts.begin(), input.contacts.end(), rng);
  for (std::size_t k = 0; k < input.contacts.size(); k += 2) {
    GatheredContact &c = input.contacts[k];
    std::swap(c.i, c.j);
    for (double &x : c.normal) x = -x;
  }
  GatheredDriveResult shuffled;
  ASSERT_TRUE(solve_gathered_drive(input, shuffled)) << shuffled.message;
  EXPECT_EQ(first_difference(shuffled.q, ref.q), -1);
}

// 2D, model normal, undamped, source grains prescribed in x and y (the fix's
// source_mode all), every factorisation: the bits of the classes called directly
class FacadeSolvers : public ::testing::TestWithParam<const char *> {};

TEST_P(FacadeSolvers, SameBitsAsTheClasses)
{
  const std::string solver = GetParam();
  if (solver == "mumps" && !mumps_available()) GTEST_SKIP() << "built without MUMPS";
  std::vector<int> fixed;
  const ContactNetwork net = AcousticTest::disordered_network(6, 5, 3, fixed);
  const double direction[3] = {0.0, 1.0, 0.0}, f = 0.11;
  GatheredDriveInput input;
  input.dimension = 2;
  input.model = FacadeContactModel::Normal;
  input.solver = solver;
  for (const Grain &g : net.grains()) input.grains.push_back(GatheredGrain(g.mass, g.radius));
  for (const Contact &c : net.contacts()) input.contacts.push_back(facade_contact(c));
  std::vector<int> sources;
  for (int g = 0; g < 6; ++g) {
    sources.push_back(g);
    for (int d = 0; d < 2; ++d) input.prescribed.push_back(PrescribedDof(g, d, direction[d]));
  }
  input.frequency = f;
  GatheredDriveResult result;
  ASSERT_TRUE(solve_gathered_drive(input, result)) << result.message;
  const FixReference ref = fix_reference(2, ContactModel::Normal, net.grains(), net.contacts(), {},
                                         -1, sources, direction, f, linear_solver_from_name(solver));
  EXPECT_EQ(first_difference(result.q, ref.q), -1);
  EXPECT_TRUE(same_bits(result.relative_residual, ref.residual));
  EXPECT_EQ(result.factorisation, ref.factorisation);
  EXPECT_NE(dof_value(result, 20, 1), Complex(0.0));
}

INSTANTIATE_TEST_SUITE_P(Facade, FacadeSolvers, ::testing::Values("auto", "lu", "ldlt", "mumps"));

// the status of a failed solve, with a finite q of the right size
TEST(FacadeGatheredDrive, SingularSolveIsAStatus)
{
  // omega = 0: nothing holds the grains in y
  GatheredDriveInput input = FacadeCxx98::chain_input(2, 0.8, 1.3, 0.0, 0.0);
  GatheredDriveResult result;
  bool ok = true;
  EXPECT_NO_THROW(ok = solve_gathered_drive(input, result));
  EXPECT_FALSE(ok);
  EXPECT_EQ(result.status, FacadeStatus::FactorisationFailed);
  EXPECT_NE(result.message.find("singular"), std::string::npos) << result.message;
  ASSERT_EQ(result.q.size(), 12u);
  EXPECT_TRUE(all_finite(result.q));
  EXPECT_EQ(dof_value(result, 0, 0), Complex(0.0));    // free DOFs 0
  EXPECT_EQ(dof_value(result, 2, 0), Complex(1.0));    // prescribed ones as given
  EXPECT_TRUE(std::isfinite(result.relative_residual));
}

// each bad input: InvalidInput, a message naming the problem, no result, nothing thrown
TEST(FacadeGatheredDrive, BadInputIsAStatus)
{
  struct Case {
    const char *expect;
    std::function<void(GatheredDriveInput &)> spoil;
  };
  const std::vector<Case> cases = {
      {"dimension must be 2 or 3, got 1", [](GatheredDriveInput &in) { in.dimension = 1; }},
      {"unknown contact model 7",
       [](GatheredDriveInput &in) { in.model = static_cast<FacadeContactModel::Value>(7); }},
      {"one of the two", [](GatheredDriveInput &in) { in.frequency = 0.1; }},
      {"one of the two", [](GatheredDriveInput &in) { in.angular_frequency = -1.0; }},
      {"the angular frequency must be finite, got nan",
       [](GatheredDriveInput &in) { in.angular_frequency = qnan; }},
      {"the frequency must be finite, got inf",
       [](GatheredDriveInput &in) {
         in.angular_frequency = -1.0;
         in.frequency = inf;
       }},
      {"solver iterative works on the network distributed",
       [](GatheredDriveInput &in) { in.solver = "iterative"; }},
      {"unknown solver 'cholesky': allowed are auto, lu, ldlt, mumps",
       [](GatheredDriveInput &in) { in.solver = "cholesky"; }},
      {"unknown ordering 'amd'", [](GatheredDriveInput &in) { in.ordering = "amd"; }},
      {"residual tolerance must be positive",
       [](GatheredDriveInput &in) { in.residual_tolerance = 0.0; }},
      {"grain 0 has mass 0", [](GatheredDriveInput &in) { in.grains[0].mass = 0.0; }},
      {"grain 1 has mass nan", [](GatheredDriveInput &in) { in.grains[1].mass = qnan; }},
      {"grain 2 has mass -inf", [](GatheredDriveInput &in) { in.grains[2].mass = -inf; }},
      // the contacts are sorted inside: the message keeps the caller's index
      {"contact 0 refers to a grain outside 0..2",
       [](GatheredDriveInput &in) { in.contacts[0].i = 5; }},
      {"contact 0 joins grain 1 to itself", [](GatheredDriveInput &in) { in.contacts[0].i = 1; }},
      {"contact 1 has a normal that is not a unit vector",
       [](GatheredDriveInput &in) { in.contacts[1].normal[0] = -0.5; }},
      {"contact 0 has a normal with a z component",
       [](GatheredDriveInput &in) {
         in.contacts[0].normal[0] = -0.6;
         in.contacts[0].normal[2] = 0.8;
       }},
      {"contact 0 has a stiffness that is negative",
       [](GatheredDriveInput &in) { in.contacts[0].kn = -1.0; }},
      {"contact 1 has a dashpot coefficient",
       [](GatheredDriveInput &in) { in.contacts[1].cn = qnan; }},
      {"grain 0 has a radius that is not positive",
       [](GatheredDriveInput &in) {
         in.model = FacadeContactModel::Full;
         in.grains[0].radius = 0.0;
       }},
      {"prescribed DOF 0 (grain 9, component 0) names a grain outside 0..2",
       [](GatheredDriveInput &in) { in.prescribed[0].grain = 9; }},
      {"prescribed DOF 0 (grain 2, component 2) names a component outside 0..1",
       [](GatheredDriveInput &in) { in.prescribed[0].component = 2; }},
      {"prescribed DOF 0 (grain 2, component 0) has an amplitude that is not finite",
       [](GatheredDriveInput &in) { in.prescribed[0].amplitude = inf; }},
      {"prescribed DOF 1 (grain 2, component 0) is prescribed twice",
       [](GatheredDriveInput &in) { in.prescribed.push_back(PrescribedDof(2, 0, 0.5)); }},
      {"solver ldlt needs an undamped problem",
       [](GatheredDriveInput &in) {
         in.solver = "ldlt";
         in.contacts[0].cn = 0.1;
       }},
  };
  for (const Case &c : cases) {
    GatheredDriveInput input = FacadeCxx98::chain_input(2, 0.8, 1.3, 0.0, 0.5);
    c.spoil(input);
    GatheredDriveResult result;
    result.q.assign(3, qnan);    // an earlier result is not left behind
    bool ok = true;
    EXPECT_NO_THROW(ok = solve_gathered_drive(input, result)) << c.expect;
    EXPECT_FALSE(ok) << c.expect;
    EXPECT_EQ(result.status, FacadeStatus::InvalidInput) << c.expect;
    EXPECT_NE(result.message.find(c.expect), std::string::npos)
        << "expected '" << c.expect << "' in '" << result.message << "'";
    EXPECT_TRUE(result.q.empty()) << c.expect;
    EXPECT_EQ(result.relative_residual, 0.0) << c.expect;
  }
}

// calls from C++98 code (facade_cxx98.cpp): the same bits as from C++17
TEST(FacadeCxx98, SameBitsAsFromCxx17)
{
  const GatheredDriveInput input = FacadeCxx98::chain_input(3, 0.8, 1.3, 0.07, 1.1);
  GatheredDriveResult from98, from17;
  ASSERT_TRUE(FacadeCxx98::solve(input, from98)) << from98.message;
  ASSERT_TRUE(solve_gathered_drive(input, from17)) << from17.message;
  EXPECT_EQ(from98.q.size(), 2u * 2u * 4u);
  EXPECT_EQ(first_difference(from98.q, from17.q), -1);
  EXPECT_EQ(from98.factorisation, "lu");

  const double qi_re[3] = {0.3, -0.2, 0.5}, qi_im[3] = {0.1, 0.0, 0.05};
  const double qj_re[3] = {0.1, 0.0, 0.4}, qj_im[3] = {0.0, 0.2, 0.0};
  ContactFactorResult r98;
  ASSERT_TRUE(FacadeCxx98::contact_factor(qi_re, qi_im, qj_re, qj_im, 2e-3, 1000.0, 0.5, 2.0, 1.0,
                                          0.1, r98))
      << r98.message;
  EXPECT_NEAR(r98.tangential_amplitude, 2e-3 * std::sqrt(0.13), 1e-15);
  EXPECT_NEAR(r98.factor, 1.0 - 1000.0 * 2e-3 * std::sqrt(0.13) / (0.5 * 2.0), 1e-14);

  std::string message;
  int status = -1;
  EXPECT_FALSE(FacadeCxx98::bad_drive(message, status));
  EXPECT_EQ(status, FacadeStatus::InvalidInput);
  EXPECT_NE(message.find("dimension must be 2 or 3, got 4"), std::string::npos) << message;
}

/* ----------------------------------------------------------------------
   the contact factor
------------------------------------------------------------------------- */

ContactFactorInput contact_input(int dim, FacadeContactModel::Value model, const double *qi,
                                 const double *qj)
{
  ContactFactorInput in;
  in.dimension = dim;
  in.model = model;
  in.normal[2] = 1.0;
  in.radius_i = in.radius_j = 0.5;
  in.q_i = qi;
  in.q_j = qj;
  in.amplitude = 2e-3;
  in.tangential_stiffness = 1000.0;
  in.friction_coefficient = 0.5;
  in.normal_force = 2.0;
  in.cmu = 1.0;
  in.mu_min = 0.1;
  return in;
}

TEST(FacadeContactFactor, HandComputation3dNormal)
{
  // Delta = q_i - q_j = (0.2 + 0.1i, -0.2 - 0.2i, 0.1 + 0.05i); n = z:
  // |Delta_t|^2 = 0.05 + 0.08 = 0.13
  const double qi[6] = {0.3, 0.1, -0.2, 0.0, 0.5, 0.05}, qj[6] = {0.1, 0.0, 0.0, 0.2, 0.4, 0.0};
  ContactFactorInput in = contact_input(3, FacadeContactModel::Normal, qi, qj);
  ContactFactorResult r;
  ASSERT_TRUE(contact_mindlin_factor(in, r)) << r.message;
  const double ut = 2e-3 * std::sqrt(0.13);
  EXPECT_NEAR(r.tangential_amplitude, ut, 1e-15 * ut);
  const double s = 1.0 - 1.0 * 1000.0 * ut / (0.5 * 2.0);    // 0.279
  EXPECT_NEAR(r.factor, s, 1e-14);
  EXPECT_EQ(r.status, FacadeStatus::Success);
  EXPECT_TRUE(r.message.empty());

  in.mu_min = 0.5;    // clamped from below
  ASSERT_TRUE(contact_mindlin_factor(in, r));
  EXPECT_EQ(r.factor, 0.5);
  in.mu_min = 0.1;
  in.cmu = 0.5;    // C_mu scales the reduction
  ASSERT_TRUE(contact_mindlin_factor(in, r));
  EXPECT_NEAR(r.factor, 1.0 - 0.5 * 1000.0 * ut / (0.5 * 2.0), 1e-14);
  in.normal_force = 0.0;    // no load: no reduction
  ASSERT_TRUE(contact_mindlin_factor(in, r));
  EXPECT_EQ(r.factor, 1.0);
  in.normal_force = 2.0;
  in.compute_factor = false;    // U_t only
  ASSERT_TRUE(contact_mindlin_factor(in, r));
  EXPECT_EQ(r.factor, 1.0);
  EXPECT_NEAR(r.tangential_amplitude, ut, 1e-15 * ut);
}

TEST(FacadeContactFactor, HandComputation2dFull)
{
  // Delta = u_i - u_j + n x (0, 0, T), T = r_i theta_i + r_j theta_j, is
  // (u_i - u_j) + (n_y T, -n_x T); its tangential part is its component
  // along t = (-n_y, n_x)
  const double qi[6] = {0.2, 0.1, -0.1, 0.3, 0.4, -0.2}, qj[6] = {0.05, 0.0, 0.1, -0.1, -0.3, 0.1};
  ContactFactorInput in = contact_input(2, FacadeContactModel::Full, qi, qj);
  in.normal[0] = 0.6;
  in.normal[1] = 0.8;
  in.normal[2] = 0.0;
  in.radius_i = 0.5;
  in.radius_j = 0.7;
  const Complex ux(0.2 - 0.05, 0.1 - 0.0), uy(-0.1 - 0.1, 0.3 + 0.1);
  const Complex T = 0.5 * Complex(0.4, -0.2) + 0.7 * Complex(-0.3, 0.1);
  const Complex dx = ux + 0.8 * T, dy = uy - 0.6 * T;
  const double ut = 2e-3 * std::abs(-0.8 * dx + 0.6 * dy);
  ContactFactorResult r;
  ASSERT_TRUE(contact_mindlin_factor(in, r)) << r.message;
  EXPECT_NEAR(r.tangential_amplitude, ut, 1e-14 * ut);
  EXPECT_NEAR(r.factor, std::max(0.1, 1.0 - 1000.0 * ut / (0.5 * 2.0)), 1e-13);
}

TEST(FacadeContactFactor, WallWithItsPrescribedMotion)
{
  // a grain on a flat wall (radius 0, as fix acoustic/mindlin passes) moving along x
  const double qi[12] = {0.5, 0.0, 0.1, 0.0, 0.2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.3, 0.0};
  const double wall[12] = {1.0, 0.0};
  ContactFactorInput in = contact_input(3, FacadeContactModel::Full, qi, wall);
  in.radius_j = 0.0;
  // Delta = (0.5 - 1, 0.1, 0.2) + z x (0, 0, 0.5 * 0.3): the rotation about z is
  // along the normal and moves nothing; tangential part (-0.5, 0.1)
  const double ut = 2e-3 * std::sqrt(0.26);
  ContactFactorResult r;
  ASSERT_TRUE(contact_mindlin_factor(in, r)) << r.message;
  EXPECT_NEAR(r.tangential_amplitude, ut, 1e-15 * ut);
}

// the three calls fix acoustic/mindlin made before it called the facade
void three_calls(const ContactFactorInput &in, double &ut, double &s)
{
  const ContactModel model =
      in.model == FacadeContactModel::Full ? ContactModel::Full : ContactModel::Normal;
  const int ndof = dofs_per_grain(in.dimension, model);
  Eigen::VectorXcd qi(ndof), qj(ndof);
  for (int k = 0; k < ndof; k++) {
    qi[k] = std::complex<double>(in.q_i[2 * k], in.q_i[2 * k + 1]);
    qj[k] = std::complex<double>(in.q_j[2 * k], in.q_j[2 * k + 1]);
  }
  const Eigen::Vector3d n(in.normal[0], in.normal[1], in.normal[2]);
  MindlinFrictionLaw law;
  law.cmu = in.cmu;
  law.mu_min = in.mu_min;
  const Eigen::Vector3cd delta =
      contact_point_displacement(in.dimension, model, n, in.radius_i, in.radius_j, qi, qj);
  ut = tangential_amplitude(delta, n, in.amplitude);
  s = friction_factor(law, in.tangential_stiffness, ut, in.friction_coefficient, in.normal_force);
}

TEST(FacadeContactFactor, SameBitsAsTheThreeCalls)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int reduced = 0, clamped = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int dim = 2 + trial % 2;
    const FacadeContactModel::Value model =
        (trial / 2) % 2 ? FacadeContactModel::Full : FacadeContactModel::Normal;
    double qi[12], qj[12];
    for (int k = 0; k < 12; ++k) {
      qi[k] = u(rng);
      qj[k] = u(rng);
    }
    ContactFactorInput in = contact_input(dim, model, qi, qj);
    Eigen::Vector3d n(u(rng), u(rng), dim == 3 ? u(rng) : 0.0);
    n.normalize();
    for (int d = 0; d < 3; ++d) in.normal[d] = n[d];
    in.radius_i = 0.3 + 0.5 * std::abs(u(rng));
    in.radius_j = (trial % 7 == 0) ? 0.0 : 0.3 + 0.5 * std::abs(u(rng));    // a wall
    in.amplitude = 1e-3 * std::abs(u(rng));
    in.tangential_stiffness = 500.0 * std::abs(u(rng));
    in.friction_coefficient = 0.5 * std::abs(u(rng));
    in.normal_force = 1.0 * u(rng);
    in.cmu = 1.5 * std::abs(u(rng));
    in.mu_min = 0.2 * std::abs(u(rng));
    double ut = 0.0, s = 0.0;
    three_calls(in, ut, s);
    ContactFactorResult r;
    ASSERT_TRUE(contact_mindlin_factor(in, r)) << r.message;
    EXPECT_TRUE(same_bits(r.tangential_amplitude, ut)) << trial;
    EXPECT_TRUE(same_bits(r.factor, s)) << trial;
    in.compute_factor = false;
    ASSERT_TRUE(contact_mindlin_factor(in, r)) << r.message;
    EXPECT_TRUE(same_bits(r.tangential_amplitude, ut)) << trial;
    EXPECT_EQ(r.factor, 1.0);
    if (s < 1.0 && s > in.mu_min) reduced++;
    if (s == in.mu_min) clamped++;
  }
  EXPECT_GT(reduced, 20);    // the law's three branches were met
  EXPECT_GT(clamped, 20);
}

TEST(FacadeContactFactor, BadInputIsAStatus)
{
  const double qi[12] = {0.3, 0.1, -0.2, 0.0, 0.5, 0.05}, qj[12] = {0.1, 0.0, 0.0, 0.2, 0.4, 0.0};
  double q_nan[12] = {0.0};
  q_nan[3] = qnan;
  struct Case {
    const char *expect;
    std::function<void(ContactFactorInput &)> spoil;
  };
  const std::vector<Case> cases = {
      {"dimension must be 2 or 3, got 4", [](ContactFactorInput &in) { in.dimension = 4; }},
      {"unknown contact model 9",
       [](ContactFactorInput &in) { in.model = static_cast<FacadeContactModel::Value>(9); }},
      {"null pointer", [](ContactFactorInput &in) { in.q_j = nullptr; }},
      {"the vibration amplitude U0 must be >= 0", [](ContactFactorInput &in) { in.amplitude = -1.0; }},
      {"the contact normal must be a unit vector",
       [](ContactFactorInput &in) { in.normal[0] = 0.5; }},
      {"the contact displacement is not finite", [&](ContactFactorInput &in) { in.q_i = q_nan; }},
      {"the friction coefficient must be >= 0",
       [](ContactFactorInput &in) { in.friction_coefficient = -0.1; }},
      {"the tangential stiffness must be >= 0",
       [](ContactFactorInput &in) { in.tangential_stiffness = qnan; }},
      {"mu_min must lie in [0, 1]", [](ContactFactorInput &in) { in.mu_min = 2.0; }},
      {"C_mu must be >= 0", [](ContactFactorInput &in) { in.cmu = -1.0; }},
      {"the normal force is NaN", [](ContactFactorInput &in) { in.normal_force = qnan; }},
  };
  for (const Case &c : cases) {
    ContactFactorInput in = contact_input(3, FacadeContactModel::Normal, qi, qj);
    c.spoil(in);
    ContactFactorResult r;
    r.tangential_amplitude = qnan;    // an earlier result is not left behind
    r.factor = qnan;
    bool ok = true;
    EXPECT_NO_THROW(ok = contact_mindlin_factor(in, r)) << c.expect;
    EXPECT_FALSE(ok) << c.expect;
    EXPECT_EQ(r.status, FacadeStatus::InvalidInput) << c.expect;
    EXPECT_NE(r.message.find(c.expect), std::string::npos)
        << "expected '" << c.expect << "' in '" << r.message << "'";
    EXPECT_EQ(r.tangential_amplitude, 0.0) << c.expect;
    EXPECT_EQ(r.factor, 1.0) << c.expect;
  }
  // without the factor the law is not read (as fix acoustic/mindlin without set_factors)
  ContactFactorInput in = contact_input(3, FacadeContactModel::Normal, qi, qj);
  in.compute_factor = false;
  in.friction_coefficient = -0.1;
  ContactFactorResult r;
  EXPECT_TRUE(contact_mindlin_factor(in, r)) << r.message;
  // a result reused after a failure: the message is cleared
  in.dimension = 5;
  EXPECT_FALSE(contact_mindlin_factor(in, r));
  in.dimension = 3;
  EXPECT_TRUE(contact_mindlin_factor(in, r));
  EXPECT_TRUE(r.message.empty());
  EXPECT_EQ(r.status, FacadeStatus::Success);
}

}    // namespace
