// Pulse response of the network (paper 003, Eqs. 1-4) against the closed
// modal solution of a 1D chain between two walls, method integrate against
// method modes and its order of convergence, and the 1D exponents of the
// coherent peak (paper 003, Sec. V A and Table III).
#include "acoustic_contact_network.h"
#include "acoustic_pulse_response.h"
#include "acoustic_solver_error.h"
#include "network_builders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace Acoustic;

namespace {

// N grains of mass m on a line along y, springs k between neighbours and to
// the two walls (grains 0 and N + 1 of the network, prescribed): the source
// is the lower wall, the detector the upper one, direction +y
PulseProblem chain(int n, double m, double k)
{
  std::vector<Grain> grains(n + 2, Grain{m, 0.5});
  std::vector<Contact> contacts;
  for (int g = 0; g <= n; ++g)
    contacts.push_back(Contact{g + 1, g, Eigen::Vector3d(0.0, 1.0, 0.0), k, 0.0, 0.0, 0.0});
  const ContactNetwork network(2, ContactModel::Normal, grains, contacts);
  PulseProblem p;
  p.stiffness = network.stiffness_matrix();
  p.mass = network.mass_diagonal();
  p.dofs_per_grain = 2;
  p.dimension = 2;
  p.direction = Eigen::Vector3d(0.0, 1.0, 0.0);
  p.source = Eigen::VectorXd::Zero(p.mass.size());
  p.detector = Eigen::VectorXd::Zero(p.mass.size());
  for (int d = 0; d < 2; ++d) {
    p.prescribed_dofs.push_back(network.dof(0, d));
    p.prescribed_dofs.push_back(network.dof(n + 1, d));
  }
  p.source[network.dof(0, 1)] = 1.0;
  p.detector[network.dof(n + 1, 1)] = 1.0;
  return p;
}

// the closed modal solution of the chain: modes phi_n(j) = sqrt(2 / (m (N+1)))
// sin(n pi j / (N+1)), w_n = 2 sqrt(k/m) sin(n pi / (2 (N+1))); the force on
// the upper wall is k u_N
double chain_signal(int n, double m, double k, PulseInitial initial, double t)
{
  double force = 0.0;
  for (int mode = 1; mode <= n; ++mode) {
    const double phase = M_PI * mode / (n + 1);
    const double norm = std::sqrt(2.0 / (m * (n + 1)));
    const double first = norm * std::sin(phase), last = norm * std::sin(phase * n);
    const double omega = 2.0 * std::sqrt(k / m) * std::sin(0.5 * phase);
    // A: u'(0) = k/m on grain 1, c_n = m phi_n(1) k/m; B: u(0) = 1 on grain 1, a_n = m phi_n(1)
    const double amplitude = (initial == PulseInitial::Velocity)
        ? k * first * std::sin(omega * t) / omega
        : m * first * std::cos(omega * t);
    force += k * last * amplitude;
  }
  return force;
}

double peak(const Eigen::VectorXd &signal)
{
  return signal.cwiseAbs().maxCoeff();
}

TEST(PulseChain, ModesEqualTheClosedModalSolution)
{
  const int n = 25;
  const double m = 1.3, k = 2.7;
  for (PulseInitial initial : {PulseInitial::Velocity, PulseInitial::Displacement}) {
    PulseOptions o;
    o.initial = initial;
    o.method = PulseMethod::Modes;
    o.duration = 40.0;
    o.samples = 401;
    const PulseResponse r = pulse_response(chain(n, m, k), o);
    ASSERT_EQ(r.signal.size(), 401);
    double largest = 0.0;
    for (int s = 0; s < o.samples; ++s)
      largest = std::max(largest, std::abs(r.signal[s] - chain_signal(n, m, k, initial, r.times[s])));
    EXPECT_LE(largest, 1e-6 * peak(r.signal)) << "peak " << peak(r.signal);
    EXPECT_GT(peak(r.signal), 0.01);
  }
  // A starts from the static force (F_sig(0) = 0)
  PulseOptions o;
  o.duration = 1.0;
  EXPECT_EQ(pulse_response(chain(n, m, k), o).signal[0], 0.0);
}

TEST(PulseChain, IntegrateAgreesWithModesAndConvergesAtSecondOrder)
{
  const int n = 25;
  const double m = 1.0, k = 1.0;
  const PulseProblem p = chain(n, m, k);
  PulseOptions o;
  o.duration = 40.0;
  o.samples = 201;
  o.method = PulseMethod::Modes;
  const PulseResponse exact = pulse_response(p, o);
  o.method = PulseMethod::Integrate;
  double errors[3];
  double steps[3];
  for (int level = 0; level < 3; ++level) {
    o.time_step = (level == 0) ? 0.0 : 0.5 * steps[level - 1];
    const PulseResponse r = pulse_response(p, o);
    steps[level] = r.time_step;
    errors[level] = (r.signal - exact.signal).cwiseAbs().maxCoeff() / peak(exact.signal);
  }
  std::printf("[ chain N = 25 ] default step %.4g: error %.3g of the peak; dt/2: %.3g; dt/4: %.3g\n",
              steps[0], errors[0], errors[1], errors[2]);
  EXPECT_LE(errors[0], 1e-3) << "at the default step";
  // second order: halving the step divides the error by about 4
  EXPECT_NEAR(errors[0] / errors[1], 4.0, 0.4);
  EXPECT_NEAR(errors[1] / errors[2], 4.0, 0.4);
}

TEST(PulseChain, SnapshotIsTheDisplacementAtThatTime)
{
  // at t, the force on the upper wall is k u_N: the snapshot's last grain
  const int n = 12;
  const PulseProblem p = chain(n, 1.0, 1.0);
  for (PulseMethod method : {PulseMethod::Modes, PulseMethod::Integrate}) {
    PulseOptions o;
    o.method = method;
    o.duration = 20.0;
    o.samples = 21;
    o.snapshot_time = 14.0;
    const PulseResponse r = pulse_response(p, o);
    ASSERT_EQ(r.snapshot.size(), p.mass.size());
    EXPECT_NEAR(r.snapshot_time, 14.0, 1e-9);
    EXPECT_NEAR(r.snapshot[2 * n + 1], r.signal[14], 1e-12);
    EXPECT_EQ(r.snapshot[1], 0.0) << "prescribed DOFs stay zero";
  }
}

// amplitude (the first maximum of F, the front) and width (the time from the
// first crossing of half that maximum to the maximum) of the coherent peak,
// by integration of a chain of N grains; the oscillations behind the front
// grow larger than it, as in paper 003's Fig. 5
void coherent_peak(int n, PulseInitial initial, double &amplitude, double &width)
{
  PulseOptions o;
  o.initial = initial;
  o.method = PulseMethod::Integrate;
  o.duration = 1.0 * n + 10.0 * std::cbrt(n) + 20.0;    // c = 1: arrival at ~N
  o.samples = static_cast<int>(o.duration * 40.0) + 1;
  const PulseResponse r = pulse_response(chain(n, 1.0, 1.0), o);
  const Eigen::VectorXd &f = r.signal;
  // the first local maximum above 1 % of the largest |F|: the coherent peak
  const double threshold = 0.01 * f.cwiseAbs().maxCoeff();
  int top = 1;
  while (!(f[top] >= threshold && f[top] >= f[top - 1] && f[top] > f[top + 1])) ++top;
  amplitude = f[top];
  int rise = top;
  while (rise > 0 && f[rise] > 0.5 * amplitude) --rise;
  width = r.times[top] - r.times[rise];
}

TEST(PulseChain, CoherentPeakExponentsOfPaper003TableIII)
{
  // A: F ~ N^-2/3, width ~ N^1/3; B: F ~ N^-1 (paper 003 Eqs. 9, 10, 13)
  const int sizes[2] = {400, 1600};
  double amp_a[2], width_a[2], amp_b[2], width_b[2];
  for (int s = 0; s < 2; ++s) {
    coherent_peak(sizes[s], PulseInitial::Velocity, amp_a[s], width_a[s]);
    coherent_peak(sizes[s], PulseInitial::Displacement, amp_b[s], width_b[s]);
  }
  const double span = std::log(4.0);
  const double gamma_a = -std::log(amp_a[1] / amp_a[0]) / span;
  const double alpha_a = std::log(width_a[1] / width_a[0]) / span;
  const double gamma_b = -std::log(amp_b[1] / amp_b[0]) / span;
  std::printf("[ chain N = 400..1600 ] A: gamma %.3f (2/3), alpha %.3f (1/3); B: gamma %.3f (1)\n",
              gamma_a, alpha_a, gamma_b);
  EXPECT_NEAR(gamma_a, 2.0 / 3.0, 0.03);
  EXPECT_NEAR(alpha_a, 1.0 / 3.0, 0.05);
  EXPECT_NEAR(gamma_b, 1.0, 0.03);
}

TEST(PulseResponse, RejectsInvalidInput)
{
  PulseProblem p = chain(5, 1.0, 1.0);
  PulseOptions o;
  o.duration = 0.0;
  EXPECT_THROW(pulse_response(p, o), SolverError);
  o.duration = 1.0;
  o.samples = 1;
  EXPECT_THROW(pulse_response(p, o), SolverError);
  o.samples = 10;
  p.damping = p.stiffness * 0.01;
  EXPECT_THROW(pulse_response(p, o), SolverError) << "modes with damping";
  o.method = PulseMethod::Integrate;
  EXPECT_NO_THROW(pulse_response(p, o));
  // k = m = 1: Gershgorin bounds w_max^2 by 4, so steps from 2/2 = 1 on are refused
  o.time_step = 1.0;
  EXPECT_THROW(pulse_response(p, o), SolverError) << "a step beyond the stability bound";
  o.time_step = 0.9;
  EXPECT_NO_THROW(pulse_response(p, o));
  o.time_step = 0.0;
  PulseProblem q = chain(5, 1.0, 1.0);
  q.source.setZero();
  q.source[3] = 1.0;    // a free DOF
  EXPECT_THROW(pulse_response(q, o), SolverError);
  PulseProblem deaf = chain(5, 1.0, 1.0);
  deaf.detector.setZero();    // a detector pattern on no DOF
  EXPECT_THROW(pulse_response(deaf, o), SolverError) << "a detector that touches no grain";
  EXPECT_THROW(pulse_initial_from_name("kick"), SolverError);
  EXPECT_THROW(pulse_method_from_name("fast"), SolverError);
}

}    // namespace

namespace {

// A triangular lattice of N rows of nx Hertz balls (diameter 1, density 1:
// m = pi/6), rows parallel to two walls, periodic along the rows, under the
// pressure p (E* = 1, nu = 0: contact force f = p / sqrt(3), normal stiffness
// k = (3 f)^(1/3) / 2, tangential eta k with eta = 1), hard walls below and
// above: the arrival time of the coherent peak at the upper wall after a
// pulse of the lower one (condition A)
double lattice_peak_time(int rows, double p, ContactModel model)
{
  const int nx = 3;
  const double m = M_PI / 6.0, f = p / std::sqrt(3.0);
  const double k = 0.5 * std::cbrt(3.0 * f), eta = 1.0;
  // a ball on a hard wall carries sqrt(3) f: F = (4/3) sqrt(1/2) n^(3/2), k_w = dF/dn
  const double fw = std::sqrt(3.0) * f;
  const double kw = 2.0 * std::sqrt(0.5) * std::sqrt(std::cbrt(std::pow(3.0 * fw / (4.0 * std::sqrt(0.5)), 2.0)));
  const int lower = nx * rows, upper = lower + 1;
  std::vector<Grain> grains(nx * rows + 2, Grain{m, 0.5});
  std::vector<Contact> contacts;
  for (const AcousticTest::Bond &b : AcousticTest::triangular_lattice_bonds(nx, rows, true))
    contacts.push_back(Contact{b.i, b.j, b.normal, k, eta * k, 0.0, 0.0});
  for (int c = 0; c < nx; ++c) {
    contacts.push_back(Contact{c, lower, Eigen::Vector3d(0.0, 1.0, 0.0), kw, eta * kw, 0.0, 0.0});
    contacts.push_back(Contact{upper, (rows - 1) * nx + c, Eigen::Vector3d(0.0, 1.0, 0.0), kw, eta * kw, 0.0, 0.0});
  }
  const ContactNetwork network(2, model, grains, contacts);
  PulseProblem pb;
  pb.stiffness = network.stiffness_matrix();
  pb.mass = network.mass_diagonal();
  pb.dofs_per_grain = network.dofs_per_grain();
  pb.dimension = 2;
  pb.direction = Eigen::Vector3d(0.0, 1.0, 0.0);
  pb.source = Eigen::VectorXd::Zero(pb.mass.size());
  pb.detector = Eigen::VectorXd::Zero(pb.mass.size());
  for (int d = 0; d < network.dofs_per_grain(); ++d) {
    pb.prescribed_dofs.push_back(network.dof(lower, d));
    pb.prescribed_dofs.push_back(network.dof(upper, d));
  }
  pb.source[network.dof(lower, 1)] = 1.0;
  pb.detector[network.dof(upper, 1)] = 1.0;
  // the front arrives at about rows sqrt(3)/2 / c
  const double c_guess = 1.1 * std::pow(p, 1.0 / 6.0);    // Eq. 18, about
  PulseOptions o;
  o.method = PulseMethod::Integrate;
  o.duration = 1.3 * rows * 0.8660254 / c_guess;
  o.samples = 4001;
  const PulseResponse r = pulse_response(pb, o);
  const Eigen::VectorXd &sig = r.signal;
  const double threshold = 0.01 * sig.cwiseAbs().maxCoeff();
  int top = 1;
  while (!(sig[top] >= threshold && sig[top] >= sig[top - 1] && sig[top] > sig[top + 1])) ++top;
  // the parabola through the three samples around the maximum
  const double h = r.times[1] - r.times[0];
  const double a = sig[top - 1], b = sig[top], c = sig[top + 1];
  return r.times[top] + 0.5 * h * (a - c) / (a - 2.0 * b + c);
}

TEST(PulseLattice, FrontSpeedOfPaper003Eqs18And19)
{
  // c / sqrt(E*/rho) = 3^(19/12) / (2^(3/2) pi^(1/2)) (p/E*)^(1/6), times sqrt(1 + eta/3) with friction
  const double p = 1e-4;
  const double frictionless = std::pow(3.0, 19.0 / 12.0) / (std::pow(2.0, 1.5) * std::sqrt(M_PI)) *
      std::pow(p, 1.0 / 6.0);
  const int rows[2] = {150, 300};
  for (ContactModel model : {ContactModel::Normal, ContactModel::Full}) {
    const double t1 = lattice_peak_time(rows[0], p, model), t2 = lattice_peak_time(rows[1], p, model);
    const double speed = (rows[1] - rows[0]) * 0.8660254037844386 / (t2 - t1);
    const double expected = frictionless * ((model == ContactModel::Full) ? std::sqrt(1.0 + 1.0 / 3.0) : 1.0);
    std::printf("[ triangular lattice, p = 1e-4, %s ] c_tof %.5f, paper 003 Eq. %s %.5f (%.2f %%)\n",
                model == ContactModel::Full ? "frictional" : "frictionless", speed,
                model == ContactModel::Full ? "19" : "18", expected, 100.0 * (speed / expected - 1.0));
    EXPECT_NEAR(speed / expected, 1.0, 0.03);
  }
}

}    // namespace
