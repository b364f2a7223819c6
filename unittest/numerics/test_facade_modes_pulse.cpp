/* ----------------------------------------------------------------------
   Unit tests: the C++98 facade's vibration modes and pulse response of a
   gathered network (acoustic_gathered_modes.h, acoustic_gathered_pulse.h)
   in the shared library acoustic_liggghts: a chain's closed forms (filled
   by C++98 code, facade_cxx98.cpp), the same bits as the classes called as
   compute vibration/modes and vibration/pulse call them, and bad input
   returned as a status with a message.
------------------------------------------------------------------------- */

#include "acoustic_gathered_modes.h"
#include "acoustic_gathered_pulse.h"
#include "facade_cxx98.h"

#include "acoustic_contact_network.h"
#include "acoustic_dynamical_matrix.h"
#include "acoustic_frequency_histogram.h"
#include "acoustic_kpm_density.h"
#include "acoustic_mindlin_law.h"
#include "acoustic_pulse_response.h"
#include "acoustic_vibration_modes.h"
#include "network_builders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace Acoustic;

namespace {

bool same_bits(const std::vector<double> &a, const Eigen::VectorXd &b)
{
  if (static_cast<Eigen::Index>(a.size()) != b.size()) return false;
  return a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// the chain's x eigenfrequencies, fixed at both ends, ascending
std::vector<double> chain_frequencies(int n, double m, double k)
{
  std::vector<double> f;
  for (int j = 1; j <= n; ++j)
    f.push_back(2.0 * std::sqrt(k / m) * std::sin(j * M_PI / (2.0 * (n + 1))) / (2.0 * M_PI));
  return f;
}

// a test network in the order the LAMMPS computes gather it (contacts from
// the lower to the higher grain, sorted), and the facade's input of it
// (contacts given as the builder made them, i > j)
struct Gathered {
  ContactNetwork network;
  std::vector<GatheredGrain> grains;
  std::vector<GatheredContact> contacts;
  std::vector<int> source;
};

Gathered gathered(const AcousticTest::TestNetwork &t, bool with_dashpots)
{
  const ContactNetwork &net = t.network;
  std::vector<Contact> sorted;
  std::vector<GatheredContact> given;
  for (Contact c : net.contacts()) {
    if (!with_dashpots) c.cn = c.ct = 0.0;
    GatheredContact g;
    g.i = c.i;
    g.j = c.j;
    for (int d = 0; d < 3; ++d) g.normal[d] = c.normal[d];
    g.kn = c.kn;
    g.kt = c.kt;
    g.cn = c.cn;
    g.ct = c.ct;
    given.push_back(g);
    if (c.i > c.j) {
      std::swap(c.i, c.j);
      c.normal = -c.normal;
    }
    sorted.push_back(c);
  }
  std::stable_sort(sorted.begin(), sorted.end(), [](const Contact &a, const Contact &b) {
    return a.i < b.i || (a.i == b.i && a.j < b.j);
  });
  std::vector<GatheredGrain> grains;
  for (const Grain &g : net.grains()) grains.push_back(GatheredGrain(g.mass, g.radius));
  return Gathered{ContactNetwork(net.dimension(), net.model(), net.grains(), sorted), grains, given,
                  t.source_grains};
}

FacadeContactModel::Value facade_model(ContactModel model)
{
  return model == ContactModel::Full ? FacadeContactModel::Full : FacadeContactModel::Normal;
}

/* ----------------------------------------------------------------------
   modes
------------------------------------------------------------------------- */

TEST(FacadeGatheredModes, ChainBetweenWalls)
{
  const int n = 7;
  const double m = 0.8, k = 1.3;
  for (bool walls : {true, false}) {
    GatheredModesInput input = FacadeCxx98::chain_modes_input(n, m, k, walls);
    input.with_shapes = true;
    input.mode = 1;
    GatheredModesResult r;
    ASSERT_TRUE(FacadeCxx98::solve_modes(input, r)) << r.message;
    EXPECT_EQ(r.status, FacadeStatus::Success);
    EXPECT_EQ(r.dofs_per_grain, 2);
    EXPECT_EQ(r.num_free, 2 * n);
    // y has no stiffness: n zero modes first, then the chain's
    EXPECT_EQ(r.zero_modes, n);
    ASSERT_EQ(r.frequencies.size(), 2u * n);
    const std::vector<double> f = chain_frequencies(n, m, k);
    for (int j = 0; j < n; ++j) {
      EXPECT_EQ(r.frequencies[j], 0.0);
      EXPECT_NEAR(r.frequencies[n + j], f[j], 1e-13 * f[n - 1]) << "mode " << n + j + 1;
    }
    // mode 1 is a zero mode of y; shapes are mass-normalised, clamped ends 0
    ASSERT_EQ(r.shape.size(), 2u * (n + 2));
    EXPECT_EQ(r.participation.size(), 2u * n);
    double norm = 0.0;
    for (int g = 0; g < n; ++g) norm += m * (r.shape[2 * g] * r.shape[2 * g] + r.shape[2 * g + 1] * r.shape[2 * g + 1]);
    EXPECT_NEAR(norm, 1.0, 1e-12);
    for (int g = n; g < n + 2; ++g) EXPECT_EQ(r.shape[2 * g] + std::fabs(r.shape[2 * g + 1]), 0.0);
  }
  // the shape of the lowest x mode: sin(pi p / (n + 1)) at x position p,
  // largest component positive
  GatheredModesInput input = FacadeCxx98::chain_modes_input(n, m, k, true);
  input.with_shapes = true;
  input.mode = n + 1;
  GatheredModesResult r;
  ASSERT_TRUE(solve_gathered_modes(input, r)) << r.message;
  const double a = std::sqrt(2.0 / (m * (n + 1)));
  for (int g = 0; g < n; ++g) {
    EXPECT_NEAR(r.shape[2 * g], a * std::sin(M_PI * (g + 1) / (n + 1)), 1e-12);
    EXPECT_EQ(r.shape[2 * g + 1], 0.0);
  }
}

TEST(FacadeGatheredModes, ChainHistogramAndLanczos)
{
  const int n = 9;
  const double m = 1.1, k = 0.7;
  const std::vector<double> f = chain_frequencies(n, m, k);
  GatheredModesInput input = FacadeCxx98::chain_modes_input(n, m, k, true);
  input.bins = 4;
  input.fmin = 0.01;
  input.fmax = f[n - 1] * 1.01;
  GatheredModesResult r;
  ASSERT_TRUE(solve_gathered_modes(input, r)) << r.message;
  ASSERT_EQ(r.bin_centres.size(), 4u);
  // the x modes (the zero modes are below fmin), the density normalised over them
  const double width = (input.fmax - input.fmin) / 4;
  for (int b = 0; b < 4; ++b) {
    int in_bin = 0;
    for (double fj : f) in_bin += (fj >= input.fmin + b * width && fj < input.fmin + (b + 1) * width);
    EXPECT_NEAR(r.density[b] * width * n, in_bin, 1e-12) << "bin " << b;
    EXPECT_NEAR(r.bin_centres[b], input.fmin + (b + 0.5) * width, 1e-15);
  }
  EXPECT_TRUE(r.participation.empty());
  EXPECT_TRUE(r.shape.empty());
  if (!lanczos_available()) GTEST_SKIP() << "built without Spectra";
  input.method = "lanczos";
  input.nmodes = 3;
  input.bins = 0;
  ASSERT_TRUE(solve_gathered_modes(input, r)) << r.message;
  ASSERT_EQ(r.frequencies.size(), 3u);
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(r.frequencies[j], f[j], 1e-10 * f[j]);
  EXPECT_EQ(r.zero_modes, n);
}

// the same bits as the classes called as compute vibration/modes calls them
TEST(FacadeGatheredModes, SameBitsAsTheClasses)
{
  for (ContactModel model : {ContactModel::Normal, ContactModel::Full}) {
    const Gathered g = gathered(AcousticTest::disordered_3d(3, 3, model, 0.0, 17), false);
    const int ndof = g.network.dofs_per_grain();
    std::vector<int> fixed_dofs;
    for (int s : g.source)
      for (int d = 0; d < ndof; ++d) fixed_dofs.push_back(g.network.dof(s, d));
    const DynamicalMatrix dynamical(g.network.stiffness_matrix(), g.network.mass_diagonal(),
                                    fixed_dofs, ndof);
    GatheredModesInput input;
    input.dimension = 3;
    input.model = facade_model(model);
    input.grains = g.grains;
    input.contacts = g.contacts;
    input.fixed = g.source;
    input.bins = 5;
    input.fmin = 0.0;
    input.fmax = 0.5;
    for (bool shapes : {false, true}) {
      input.with_shapes = shapes;
      input.mode = shapes ? 4 : 0;
      GatheredModesResult r;
      ASSERT_TRUE(solve_gathered_modes(input, r)) << r.message;
      const VibrationModes modes = dense_vibration_modes(dynamical, shapes);
      EXPECT_TRUE(same_bits(r.frequencies, modes.frequencies));
      EXPECT_TRUE(same_bits(r.participation, modes.participation_ratios));
      EXPECT_EQ(r.zero_modes, modes.zero_modes);
      const FrequencyHistogram h = frequency_histogram(modes.frequencies, 5, 0.0, 0.5);
      EXPECT_TRUE(same_bits(r.density, h.density));
      EXPECT_TRUE(same_bits(r.bin_centres, h.bin_centres));
      if (shapes) {
        Eigen::VectorXd v = modes.shapes.col(3);
        Eigen::Index largest = 0;
        v.cwiseAbs().maxCoeff(&largest);
        if (v[largest] < 0.0) v = -v;
        EXPECT_TRUE(same_bits(r.shape, v));
      }
    }
    input.method = "kpm";
    input.mode = 0;
    input.kpm_moments = 64;
    input.kpm_vectors = 4;
    input.kpm_seed = 7;
    GatheredModesResult r;
    ASSERT_TRUE(solve_gathered_modes(input, r)) << r.message;
    KpmOptions kpm;
    kpm.moments = 64;
    kpm.random_vectors = 4;
    kpm.seed = 7;
    const FrequencyHistogram h = kpm_frequency_histogram(dynamical, 5, 0.0, 0.5, kpm);
    EXPECT_TRUE(same_bits(r.density, h.density));
    EXPECT_TRUE(same_bits(r.density_error, h.density_error));
    EXPECT_TRUE(r.frequencies.empty());
    if (lanczos_available()) {
      input.method = "lanczos";
      input.nmodes = 6;
      input.bins = 0;
      ASSERT_TRUE(solve_gathered_modes(input, r)) << r.message;
      const VibrationModes lanczos = lanczos_vibration_modes(dynamical, 6);
      EXPECT_TRUE(same_bits(r.frequencies, lanczos.frequencies));
    }
  }
}

TEST(FacadeGatheredModes, BadInputIsAStatus)
{
  struct Case {
    const char *what;
    void (*spoil)(GatheredModesInput &);
    const char *says;
  };
  const Case cases[] = {
      {"method", [](GatheredModesInput &in) { in.method = "arnoldi"; }, "arnoldi"},
      {"kpm without bins", [](GatheredModesInput &in) { in.method = "kpm"; }, "bins"},
      {"fixed twice", [](GatheredModesInput &in) { in.fixed = {0, 0}; }, "listed twice"},
      {"fixed outside", [](GatheredModesInput &in) { in.fixed = {99}; }, "outside"},
      {"mode out of range", [](GatheredModesInput &in) { in.with_shapes = true; in.mode = 99; }, "out of range"},
      {"all fixed", [](GatheredModesInput &in) { in.fixed = {0, 1, 2}; }, "no degree of freedom"},
      {"bad mass", [](GatheredModesInput &in) { in.grains[1].mass = -1.0; }, "mass"},
      {"dimension", [](GatheredModesInput &in) { in.dimension = 4; }, "dimension"},
      {"bins range", [](GatheredModesInput &in) { in.bins = 3; in.fmin = 2.0; in.fmax = 1.0; }, "fmin"},
  };
  for (const Case &c : cases) {
    GatheredModesInput input = FacadeCxx98::chain_modes_input(3, 1.0, 1.0, true);
    c.spoil(input);
    GatheredModesResult r;
    EXPECT_FALSE(solve_gathered_modes(input, r)) << c.what;
    EXPECT_EQ(r.status, FacadeStatus::InvalidInput) << c.what;
    EXPECT_NE(r.message.find(c.says), std::string::npos) << c.what << ": " << r.message;
    EXPECT_TRUE(r.frequencies.empty()) << c.what;
  }
}

/* ----------------------------------------------------------------------
   pulse
------------------------------------------------------------------------- */

// the force on the detector of the chain after a unit delta pulse of the
// source (initial velocity k/m of grain 1), by the chain's closed-form modes
double chain_signal(int n, double m, double k, double t)
{
  double F = 0.0;
  for (int j = 1; j <= n; ++j) {
    const double w = 2.0 * std::sqrt(k / m) * std::sin(j * M_PI / (2.0 * (n + 1)));
    const double v1 = std::sin(j * M_PI / (n + 1)), vn = std::sin(j * M_PI * n / (n + 1));
    F += 2.0 / (m * (n + 1)) * v1 * vn * k * std::sin(w * t) / w;
  }
  return k * F;
}

TEST(FacadeGatheredPulse, ChainClosedForm)
{
  const int n = 6, samples = 201;
  const double m = 0.9, k = 1.2, T = 40.0;
  double scale = 0.0;
  for (int s = 0; s < samples; ++s)
    scale = std::max(scale, std::fabs(chain_signal(n, m, k, T * s / (samples - 1))));
  ASSERT_GT(scale, 0.1);
  for (const char *method : {"auto", "modes", "integrate"}) {
    GatheredPulseInput input = FacadeCxx98::chain_pulse_input(n, m, k, T, samples);
    input.method = method;
    const bool integrate = std::strcmp(method, "integrate") == 0;
    if (integrate) input.time_step = 0.0005;
    GatheredPulseResult r;
    ASSERT_TRUE(FacadeCxx98::solve_pulse(input, r)) << r.message;
    EXPECT_EQ(r.method, integrate ? "integrate" : "modes");
    EXPECT_EQ(r.num_free, 2 * n);
    ASSERT_EQ(r.signal.size(), static_cast<std::size_t>(samples));
    const double tolerance = integrate ? 1e-5 : 1e-12;
    for (int s = 0; s < samples; ++s) {
      EXPECT_DOUBLE_EQ(r.times[s], T * s / (samples - 1));
      EXPECT_NEAR(r.signal[s], chain_signal(n, m, k, r.times[s]), tolerance * scale) << "t = " << r.times[s];
    }
  }
}

TEST(FacadeGatheredPulse, DefaultsAreTheLibrarys)
{
  const GatheredPulseInput input;
  const PulseOptions options;
  EXPECT_EQ(input.samples, options.samples);
  EXPECT_EQ(input.max_steps, options.max_steps);
  EXPECT_EQ(input.time_step, options.time_step);
  EXPECT_EQ(input.snapshot_time, options.snapshot_time);
}

// the same bits as compute vibration/pulse's PulseProblem and pulse_response
TEST(FacadeGatheredPulse, SameBitsAsTheClasses)
{
  struct Case {
    ContactModel model;
    double zeta;
    const char *initial;
  };
  for (const Case &c : {Case{ContactModel::Normal, 0.0, "velocity"},
                        Case{ContactModel::Full, 0.0, "displacement"},
                        Case{ContactModel::Full, 0.05, "velocity"}}) {
    const AcousticTest::TestNetwork t = AcousticTest::disordered_3d(3, 4, c.model, 0.0, 5);
    const Gathered g = gathered(t, false);
    const int ndof = g.network.dofs_per_grain();
    const int ngrains = g.network.num_grains();
    // the damped network as the compute builds it: dashpots from zeta
    std::vector<Contact> damped = g.network.contacts();
    for (Contact &ct : damped) {
      ct.cn = dashpot_coefficient(c.zeta, ct.kn, g.grains[ct.i].mass, g.grains[ct.j].mass);
      ct.ct = dashpot_coefficient(c.zeta, ct.kt, g.grains[ct.i].mass, g.grains[ct.j].mass);
    }
    const ContactNetwork net(3, c.model, g.network.grains(), damped);
    const double dir[3] = {0.2, -0.3, 0.9};
    const double norm = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    std::vector<int> detector;
    for (int s = 0; s < 9; ++s) detector.push_back(ngrains - 9 + s);
    const std::vector<int> fixed = {9};    // a grain of the second layer

    PulseProblem p;
    p.stiffness = net.stiffness_matrix();
    if (net.has_damping()) p.damping = net.damping_matrix();
    p.mass = net.mass_diagonal();
    p.dofs_per_grain = ndof;
    p.dimension = 3;
    p.direction = Eigen::Vector3d(dir[0] / norm, dir[1] / norm, dir[2] / norm);
    p.source = Eigen::VectorXd::Zero(net.num_dofs());
    p.detector = Eigen::VectorXd::Zero(net.num_dofs());
    auto prescribe = [&](int gr, Eigen::VectorXd *pattern) {
      for (int d = 0; d < ndof; d++) {
        p.prescribed_dofs.push_back(net.dof(gr, d));
        if (pattern && d < 3) (*pattern)[net.dof(gr, d)] = p.direction[d];
      }
    };
    for (int s : g.source) prescribe(s, &p.source);
    for (int s : detector) prescribe(s, &p.detector);
    for (int s : fixed) prescribe(s, nullptr);
    PulseOptions o;
    o.initial = pulse_initial_from_name(c.initial);
    o.method = c.zeta > 0.0 ? PulseMethod::Integrate : PulseMethod::Modes;
    o.duration = 15.0;
    o.samples = 50;
    o.snapshot_time = 3.0;
    const PulseResponse expected = pulse_response(p, o);

    GatheredPulseInput input;
    input.dimension = 3;
    input.model = facade_model(c.model);
    input.grains = g.grains;
    input.contacts = g.contacts;
    input.damping_ratio = c.zeta;
    input.source = g.source;
    input.detector = detector;
    input.fixed = fixed;
    for (int d = 0; d < 3; ++d) input.direction[d] = p.direction[d];
    input.initial = c.initial;
    input.duration = 15.0;
    input.samples = 50;
    input.snapshot_time = 3.0;
    GatheredPulseResult r;
    ASSERT_TRUE(solve_gathered_pulse(input, r)) << r.message;
    EXPECT_EQ(r.method, c.zeta > 0.0 ? "integrate" : "modes");
    EXPECT_TRUE(same_bits(r.times, expected.times));
    EXPECT_TRUE(same_bits(r.signal, expected.signal));
    EXPECT_TRUE(same_bits(r.snapshot, expected.snapshot));
    EXPECT_EQ(r.steps, expected.steps);
    EXPECT_EQ(r.time_step, expected.time_step);
    EXPECT_EQ(r.num_free, expected.num_free);
    EXPECT_GT(Eigen::Map<const Eigen::VectorXd>(r.signal.data(), r.signal.size()).cwiseAbs().maxCoeff(), 0.0);
  }
}

// a wall (infinite mass) as the source: the same as a prescribed grain
TEST(FacadeGatheredPulse, WallSourceIsAPrescribedGrain)
{
  const int n = 4;
  GatheredPulseInput input = FacadeCxx98::chain_pulse_input(n, 1.0, 1.0, 20.0, 41);
  GatheredPulseResult grain, wall;
  ASSERT_TRUE(solve_gathered_pulse(input, grain)) << grain.message;
  input.grains[0].mass = HUGE_VAL;
  input.grains[n + 1].mass = HUGE_VAL;
  ASSERT_TRUE(solve_gathered_pulse(input, wall)) << wall.message;
  EXPECT_EQ(grain.signal, wall.signal);
  // a wall not listed is clamped: the detector then sees nothing of a source elsewhere
  input.source = {1};
  GatheredPulseResult clamped;
  ASSERT_TRUE(solve_gathered_pulse(input, clamped)) << clamped.message;
  EXPECT_EQ(clamped.num_free, 2 * (n - 1));
}

static long progress_calls = 0;
static void count_progress(long, long, void *data)
{
  ++*static_cast<long *>(data);
}

TEST(FacadeGatheredPulse, ProgressIsReported)
{
  GatheredPulseInput input = FacadeCxx98::chain_pulse_input(2, 1.0, 1.0, 2000.0, 11);
  input.method = "integrate";
  input.time_step = 0.001;    // 2 000 000 steps
  input.progress = count_progress;
  input.progress_data = &progress_calls;
  GatheredPulseResult r;
  ASSERT_TRUE(solve_gathered_pulse(input, r)) << r.message;
  EXPECT_EQ(r.steps, 2000000);
  EXPECT_GE(progress_calls, 5);
}

TEST(FacadeGatheredPulse, BadInputIsAStatus)
{
  struct Case {
    const char *what;
    void (*spoil)(GatheredPulseInput &);
    const char *says;
  };
  const Case cases[] = {
      {"method", [](GatheredPulseInput &in) { in.method = "fft"; }, "fft"},
      {"initial", [](GatheredPulseInput &in) { in.initial = "force"; }, "force"},
      {"no source", [](GatheredPulseInput &in) { in.source.clear(); }, "source has no grain"},
      {"no detector", [](GatheredPulseInput &in) { in.detector.clear(); }, "detector has no grain"},
      {"source is detector", [](GatheredPulseInput &in) { in.detector = {0}; }, "listed twice"},
      {"duration", [](GatheredPulseInput &in) { in.duration = -1.0; }, "duration"},
      {"damped modes", [](GatheredPulseInput &in) { in.damping_ratio = 0.1; in.method = "modes"; }, "undamped"},
      {"both dashpots", [](GatheredPulseInput &in) { in.damping_ratio = 0.1; in.contacts[0].cn = 1.0; }, "not both"},
      {"direction", [](GatheredPulseInput &in) { in.direction[0] = HUGE_VAL; }, "direction"},
      {"too many steps", [](GatheredPulseInput &in) { in.method = "integrate"; in.max_steps = 10; }, "steps"},
  };
  for (const Case &c : cases) {
    GatheredPulseInput input = FacadeCxx98::chain_pulse_input(3, 1.0, 1.0, 10.0, 11);
    c.spoil(input);
    GatheredPulseResult r;
    EXPECT_FALSE(solve_gathered_pulse(input, r)) << c.what;
    EXPECT_EQ(r.status, FacadeStatus::InvalidInput) << c.what;
    EXPECT_NE(r.message.find(c.says), std::string::npos) << c.what << ": " << r.message;
    EXPECT_TRUE(r.signal.empty()) << c.what;
  }
}

}    // namespace
