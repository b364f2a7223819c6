/* ----------------------------------------------------------------------
   Unit tests: eigenmodes of contact networks (dense and Lanczos).
------------------------------------------------------------------------- */

#include "acoustic_contact_network.h"
#include "acoustic_dynamical_matrix.h"
#include "acoustic_frequency_histogram.h"
#include "acoustic_solver_error.h"
#include "acoustic_vibration_modes.h"
#include "network_builders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

using namespace Acoustic;

namespace {

const double pi = 3.14159265358979323846;

// n grains along x between two fixed grains (indices 0 and n + 1), 2D, model normal.
ContactNetwork fixed_chain(int n, double m, double k)
{
  std::vector<Contact> contacts;
  for (int g = 0; g <= n; ++g) contacts.push_back(Contact{g + 1, g, Eigen::Vector3d(1, 0, 0), k, 0, 0, 0});
  return ContactNetwork(2, ContactModel::Normal, std::vector<Grain>(n + 2, Grain{m, 0.5}), contacts);
}

std::vector<int> grain_dofs(const ContactNetwork &network, const std::vector<int> &grains)
{
  std::vector<int> dofs;
  for (int g : grains)
    for (int d = 0; d < network.dofs_per_grain(); ++d) dofs.push_back(network.dof(g, d));
  return dofs;
}

// omega_j = 2 sqrt(k/m) sin(j pi / (2 (n + 1))), j = 1..n
double chain_frequency(int j, int n, double m, double k)
{
  return 2.0 * std::sqrt(k / m) * std::sin(j * pi / (2.0 * (n + 1))) / (2.0 * pi);
}

}    // namespace

TEST(VibrationModes, DenseChainFrequenciesShapesAndParticipation)
{
  const int n = 30;
  const double m = 2.0, k = 3.0;
  const ContactNetwork network = fixed_chain(n, m, k);
  const DynamicalMatrix dynamical(network.stiffness_matrix(), network.mass_diagonal(),
                                  grain_dofs(network, {0, n + 1}), network.dofs_per_grain());
  const VibrationModes modes = dense_vibration_modes(dynamical);
  ASSERT_EQ(modes.frequencies.size(), 2 * n);
  EXPECT_EQ(modes.zero_modes, n);    // the y DOFs carry no stiffness
  for (int j = 1; j <= n; ++j)
    EXPECT_NEAR(modes.frequencies[n + j - 1], chain_frequency(j, n, m, k), 1e-8 * chain_frequency(j, n, m, k));

  // lowest chain mode: u_g = sin(pi g / (n + 1)), mass-normalised
  const Eigen::VectorXd v = modes.shapes.col(n);
  Eigen::VectorXd expected = Eigen::VectorXd::Zero(network.num_dofs());
  for (int g = 1; g <= n; ++g) expected[network.dof(g, 0)] = std::sin(pi * g / (n + 1));
  expected /= std::sqrt(m * expected.squaredNorm());
  EXPECT_LT(std::min((v - expected).norm(), (v + expected).norm()), 1e-8 * expected.norm());
  EXPECT_NEAR(v.dot(network.mass_diagonal().cwiseProduct(v)), 1.0, 1e-12);
  // PR of a sine mode on n grains: (sum s^2)^2 / (n sum s^4) = ((n+1)/2)^2 / (n 3(n+1)/8) = 2(n+1)/(3n)
  for (int j = 1; j <= 3; ++j)
    EXPECT_NEAR(modes.participation_ratios[n + j - 1], 2.0 * (n + 1) / (3.0 * n), 1e-10);
}

TEST(VibrationModes, LanczosChainFrequencies)
{
  if (!lanczos_available()) GTEST_SKIP() << "the package is built without Spectra";
  const int n = 150;
  const double m = 0.7, k = 11.0;
  const ContactNetwork network = fixed_chain(n, m, k);
  const DynamicalMatrix dynamical(network.stiffness_matrix(), network.mass_diagonal(),
                                  grain_dofs(network, {0, n + 1}), network.dofs_per_grain());
  const VibrationModes modes = lanczos_vibration_modes(dynamical, 6);
  ASSERT_EQ(modes.frequencies.size(), 6);
  EXPECT_EQ(modes.zero_modes, n);
  for (int j = 1; j <= 6; ++j)
    EXPECT_NEAR(modes.frequencies[j - 1], chain_frequency(j, n, m, k), 1e-8 * chain_frequency(j, n, m, k));
  for (int j = 0; j < 6; ++j) {
    const Eigen::VectorXd v = modes.shapes.col(j);
    EXPECT_NEAR(v.dot(network.mass_diagonal().cwiseProduct(v)), 1.0, 1e-10);
    EXPECT_NEAR(modes.participation_ratios[j], 2.0 * (n + 1) / (3.0 * n), 1e-8);
  }
}

TEST(VibrationModes, LanczosFindsZeroModesOfFloatingParts)
{
  if (!lanczos_available()) GTEST_SKIP() << "the package is built without Spectra";
  // chain held at both ends plus a free-floating 2-grain pair along x: the pair has one
  // translation zero mode in x and two decoupled y DOFs, the chain n decoupled y DOFs.
  const int n = 60;
  std::vector<Contact> contacts;
  for (int g = 0; g <= n; ++g) contacts.push_back(Contact{g + 1, g, Eigen::Vector3d(1, 0, 0), 1.0, 0, 0, 0});
  contacts.push_back(Contact{n + 3, n + 2, Eigen::Vector3d(1, 0, 0), 1.0, 0, 0, 0});
  const ContactNetwork network(2, ContactModel::Normal, std::vector<Grain>(n + 4, Grain{1.0, 0.5}), contacts);
  const DynamicalMatrix dynamical(network.stiffness_matrix(), network.mass_diagonal(),
                                  grain_dofs(network, {0, n + 1}), network.dofs_per_grain());
  const VibrationModes lanczos = lanczos_vibration_modes(dynamical, 3);
  const VibrationModes dense = dense_vibration_modes(dynamical, false);
  EXPECT_EQ(dense.zero_modes, n + 3);
  EXPECT_EQ(lanczos.zero_modes, n + 3);
  ASSERT_EQ(lanczos.frequencies.size(), 3);
  for (int j = 0; j < 3; ++j)
    EXPECT_NEAR(lanczos.frequencies[j], dense.frequencies[dense.zero_modes + j], 1e-9 * dense.frequencies.maxCoeff());
}

TEST(VibrationModes, RattlersGiveZeroModes)
{
  // 10 x 10 triangular patch, bottom row fixed, three interior grains without contacts
  const int nx = 10, ny = 10;
  const std::set<int> rattlers = {3 * nx + 4, 5 * nx + 2, 7 * nx + 6};
  std::vector<Contact> contacts;
  for (const AcousticTest::Bond &b : AcousticTest::triangular_lattice_bonds(nx, ny, false))
    if (!rattlers.count(b.i) && !rattlers.count(b.j)) contacts.push_back(Contact{b.i, b.j, b.normal, 1.0, 0.4, 0, 0});
  std::vector<int> bottom;
  for (int c = 0; c < nx; ++c) bottom.push_back(c);

  for (ContactModel model : {ContactModel::Normal, ContactModel::Full}) {
    SCOPED_TRACE(contact_model_name(model));
    const ContactNetwork network(2, model, std::vector<Grain>(nx * ny, Grain{1.0, 0.5}), contacts);
    const DynamicalMatrix dynamical(network.stiffness_matrix(), network.mass_diagonal(), grain_dofs(network, bottom),
                                    network.dofs_per_grain());
    const int expected = static_cast<int>(rattlers.size()) * network.dofs_per_grain();
    const VibrationModes dense = dense_vibration_modes(dynamical);
    EXPECT_EQ(dense.zero_modes, expected);
    // the zero modes live on the rattlers only
    Eigen::VectorXd off_rattlers = Eigen::VectorXd::Ones(network.num_dofs());
    for (int dof : grain_dofs(network, std::vector<int>(rattlers.begin(), rattlers.end()))) off_rattlers[dof] = 0.0;
    for (int z = 0; z < dense.zero_modes; ++z)
      EXPECT_LT(dense.shapes.col(z).cwiseProduct(off_rattlers).norm(), 1e-8);
    if (!lanczos_available()) continue;    // a build without Spectra
    const VibrationModes lanczos = lanczos_vibration_modes(dynamical, 4);
    EXPECT_EQ(lanczos.zero_modes, expected);
    for (int j = 0; j < 4; ++j)
      EXPECT_NEAR(lanczos.frequencies[j], dense.frequencies[expected + j], 1e-9 * dense.frequencies.maxCoeff());
  }
}

TEST(VibrationModes, RejectsUnstableNetworks)
{
  // a negative spring between two grains held by positive springs to fixed grains
  const Eigen::Vector3d x(1, 0, 0);
  const ContactNetwork network(2, ContactModel::Normal, std::vector<Grain>(4, Grain{1.0, 0.5}),
                               {Contact{1, 0, x, 1.0, 0, 0, 0}, Contact{3, 2, x, 1.0, 0, 0, 0}});
  Eigen::SparseMatrix<double> k = network.stiffness_matrix();
  Eigen::SparseMatrix<double> bad(k.rows(), k.cols());
  bad.insert(2, 2) = -5.0;    // ux of grain 1 pushed outwards
  k += bad;
  const DynamicalMatrix dynamical(k, network.mass_diagonal(), {0, 1, 6, 7}, 2);
  EXPECT_THROW(dense_vibration_modes(dynamical), SolverError);
  EXPECT_THROW(lanczos_vibration_modes(dynamical, 1), SolverError);
  EXPECT_THROW(mode_method_from_name("arpack"), SolverError);
  EXPECT_EQ(mode_method_from_name("kpm"), ModeMethod::Kpm);
}

TEST(FrequencyHistogram, CountsAndNormalises)
{
  Eigen::VectorXd f(7);
  f << 0.0, 0.5, 1.0, 1.5, 2.5, 4.0, 9.0;    // 9.0 is outside [0, 4]
  const FrequencyHistogram hist = frequency_histogram(f, 4, 0.0, 4.0);
  EXPECT_EQ(hist.counted, 6.0);
  EXPECT_DOUBLE_EQ(hist.bin_width, 1.0);
  Eigen::VectorXd centres(4), density(4);
  centres << 0.5, 1.5, 2.5, 3.5;
  density << 2.0 / 6.0, 2.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0;    // 4.0 falls in the last bin
  EXPECT_LT((hist.bin_centres - centres).norm(), 1e-15);
  EXPECT_LT((hist.density - density).norm(), 1e-15);
  EXPECT_NEAR(hist.density.sum() * hist.bin_width, 1.0, 1e-15);
  EXPECT_EQ(frequency_histogram(f, 3, 20.0, 30.0).density.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_THROW(frequency_histogram(f, 0, 0.0, 1.0), SolverError);
  EXPECT_THROW(frequency_histogram(f, 4, 2.0, 1.0), SolverError);
}

TEST(VibrationModes, ABuildWithoutSpectraRefusesMethodLanczos)
{
  if (lanczos_available()) {
    EXPECT_EQ(mode_method_from_name("lanczos"), ModeMethod::Lanczos);
    return;
  }
  try {
    mode_method_from_name("lanczos");
    FAIL() << "method lanczos accepted without Spectra";
  } catch (const SolverError &e) {
    EXPECT_NE(std::string(e.what()).find("Spectra (Debian: libspectra-dev"), std::string::npos) << e.what();
  }
  EXPECT_EQ(mode_method_from_name("dense"), ModeMethod::Dense);
  EXPECT_EQ(mode_method_from_name("kpm"), ModeMethod::Kpm);
}
