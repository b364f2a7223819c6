/* ----------------------------------------------------------------------
   Unit test: long-wavelength sound speed of a pre-compressed triangular
   lattice of Hertz spheres, paper 003 Eqs. (18) and (19):
     c / sqrt(E* / rho) = 3^(19/12) / (2^(3/2) pi^(1/2)) (p / E*)^(1/6)      (frictionless)
   times sqrt(1 + eta/3) with tangential springs k_t = eta k_n.
   Paper 003's conventions: E* = E / (1 - nu^2) of one grain (twice the
   pair modulus of the Hertz law), rho the density of the spheres
   (m = rho pi d^3 / 6), and p the 2D pressure (force per length) of the
   monolayer divided by its thickness d.  In a triangular lattice each
   contact carries f_n = p d^2 / sqrt(3).

   The lattice is periodic in x (rows of nx grains), with ny free rows
   between two fixed rows.  The uniform (in x) longitudinal modes are those
   of a chain of rows of spacing l = sqrt(3) d / 2 (paper 003, Sec. V B),
   omega_j = (2 c / l) sin(j pi / (2 (ny + 1))) with c = l sqrt(K/m) the
   long-wavelength sound speed, so c follows exactly from the lowest one.
   The match is exact up to round-off; the tolerance asked for is 2 %, the
   test uses 1e-8 so that any error in the stiffness or mass shows up.
------------------------------------------------------------------------- */

#include "acoustic_contact_network.h"
#include "acoustic_dynamical_matrix.h"
#include "acoustic_mindlin_law.h"
#include "acoustic_vibration_modes.h"
#include "network_builders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace Acoustic;

namespace {

const double pi = 3.14159265358979323846;

// Sound speed along y measured from the lowest longitudinal mode, divided by paper 003's prediction.
double measured_over_predicted(ContactModel model, double eta)
{
  const double youngs = 7.0e10, nu = 0.2, density = 2500.0, diameter = 1.0e-3, pressure = 1.0e5;
  const double radius = diameter / 2.0;
  const double mass = density * pi * diameter * diameter * diameter / 6.0;
  const double force = pressure * diameter * diameter / std::sqrt(3.0);
  const double kn = hertz_normal_stiffness(hertz_kappa(youngs, nu, radius, radius), force);

  const int nx = 4, ny = 40;    // rows 1..ny free, rows 0 and ny + 1 fixed
  std::vector<Contact> contacts;
  for (const AcousticTest::Bond &b : AcousticTest::triangular_lattice_bonds(nx, ny + 2, true))
    contacts.push_back(Contact{b.i, b.j, b.normal, kn, eta * kn, 0.0, 0.0});
  const ContactNetwork network(2, model, std::vector<Grain>(nx * (ny + 2), Grain{mass, radius}), contacts);
  std::vector<int> fixed;
  for (int c = 0; c < nx; ++c)
    for (int d = 0; d < network.dofs_per_grain(); ++d) {
      fixed.push_back(network.dof(c, d));
      fixed.push_back(network.dof((ny + 1) * nx + c, d));
    }
  const DynamicalMatrix dynamical(network.stiffness_matrix(), network.mass_diagonal(), fixed,
                                  network.dofs_per_grain());
  const VibrationModes modes = dense_vibration_modes(dynamical);

  // the lowest longitudinal mode: u_y = sin(pi row / (ny + 1)), the same for every grain of a row
  Eigen::VectorXd target = Eigen::VectorXd::Zero(network.num_dofs());
  for (int row = 1; row <= ny; ++row)
    for (int c = 0; c < nx; ++c) target[network.dof(row * nx + c, 1)] = std::sin(pi * row / (ny + 1));
  const Eigen::VectorXd weighted_target = network.mass_diagonal().cwiseProduct(target);
  int best = -1;
  double best_overlap = 0.0;
  for (int k = 0; k < modes.shapes.cols(); ++k) {
    const double overlap = std::abs(modes.shapes.col(k).dot(weighted_target)) /
        std::sqrt(target.dot(weighted_target));
    if (overlap > best_overlap) {
      best_overlap = overlap;
      best = k;
    }
  }
  EXPECT_GT(best_overlap, 0.999);
  // invert the chain dispersion omega_1 = (2 c / l) sin(pi / (2 (ny + 1))) for the sound speed c
  const double omega = 2.0 * pi * modes.frequencies[best];
  const double row_spacing = std::sqrt(3.0) / 2.0 * diameter;
  const double measured = omega * row_spacing / (2.0 * std::sin(pi / (2.0 * (ny + 1))));

  const double e_star = youngs / (1.0 - nu * nu);
  const double predicted = std::sqrt(e_star / density) * std::pow(3.0, 19.0 / 12.0) /
      (std::pow(2.0, 1.5) * std::sqrt(pi)) * std::sqrt(1.0 + eta / 3.0) * std::pow(pressure / e_star, 1.0 / 6.0);
  return measured / predicted;
}

}    // namespace

TEST(TriangularLattice, FrictionlessSoundSpeedMatchesPaper003Eq18)
{
  EXPECT_NEAR(measured_over_predicted(ContactModel::Normal, 0.0), 1.0, 1e-8);
}

TEST(TriangularLattice, FrictionalSoundSpeedMatchesPaper003Eq19)
{
  const double nu = 0.2;
  const double eta = (1.0 - nu) / (2.0 - nu);    // paper 003 Eq. (A4)
  EXPECT_NEAR(measured_over_predicted(ContactModel::Full, eta), 1.0, 1e-8);
}
