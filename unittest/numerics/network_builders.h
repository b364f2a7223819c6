/* ----------------------------------------------------------------------
   Test helpers: small contact networks with known geometry.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_TEST_NETWORK_BUILDERS_H
#define ACOUSTIC_TEST_NETWORK_BUILDERS_H

#include "acoustic_contact_network.h"

#include <Eigen/Core>

#include <cmath>
#include <random>
#include <vector>

namespace AcousticTest {

// Bond of a lattice: grains i, j and the unit normal from j to i.
struct Bond {
  int i;
  int j;
  Eigen::Vector3d normal;
};

// Triangular lattice of equal discs in the xy plane: ny rows of nx grains,
// grain (row, col) has index row * nx + col and sits at
// x = (2 col + row % 2) R, y = sqrt(3) row R.  With periodic_x the rows wrap
// around in x (nx >= 3).  Returns each nearest-neighbour bond once.
inline std::vector<Bond> triangular_lattice_bonds(int nx, int ny, bool periodic_x)
{
  std::vector<Bond> bonds;
  const double s = std::sqrt(3.0) / 2.0;
  auto column = [&](int c) { return periodic_x ? (c + nx) % nx : c; };
  for (int row = 0; row < ny; ++row) {
    for (int col = 0; col < nx; ++col) {
      const int here = row * nx + col;
      if (periodic_x || col + 1 < nx) bonds.push_back({row * nx + column(col + 1), here, Eigen::Vector3d(1.0, 0.0, 0.0)});
      if (row + 1 == ny) continue;
      // upper neighbours at x -+ R: columns col - 1, col (even rows) or col, col + 1 (odd rows)
      const int left = (row % 2 == 0) ? col - 1 : col;
      const int right = left + 1;
      if (periodic_x || left >= 0)
        bonds.push_back({(row + 1) * nx + column(left), here, Eigen::Vector3d(-0.5, s, 0.0)});
      if (periodic_x || right < nx)
        bonds.push_back({(row + 1) * nx + column(right), here, Eigen::Vector3d(0.5, s, 0.0)});
    }
  }
  return bonds;
}

// Disordered 2D network (model normal) on a triangular patch of nx x ny grains:
// masses uniform in [0.5, 1.5], stiffnesses uniform in [0.2, 1.8], contact
// directions rotated by up to +-0.15 rad.  fixed_dofs returns the bottom row.
inline Acoustic::ContactNetwork disordered_network(int nx, int ny, unsigned seed, std::vector<int> &fixed_dofs)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Acoustic::Grain> grains;
  for (int g = 0; g < nx * ny; ++g) grains.push_back(Acoustic::Grain{0.5 + uniform(rng), 0.5});
  std::vector<Acoustic::Contact> contacts;
  for (const Bond &b : triangular_lattice_bonds(nx, ny, false)) {
    const double angle = std::atan2(b.normal.y(), b.normal.x()) + 0.3 * (uniform(rng) - 0.5);
    contacts.push_back(Acoustic::Contact{b.i, b.j, Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0),
                                         0.2 + 1.6 * uniform(rng), 0.0, 0.0, 0.0});
  }
  Acoustic::ContactNetwork network(2, Acoustic::ContactModel::Normal, grains, contacts);
  fixed_dofs.clear();
  for (int c = 0; c < nx; ++c)
    for (int d = 0; d < 2; ++d) fixed_dofs.push_back(network.dof(c, d));
  return network;
}

// Disordered 3D network: a simple cubic lattice of n x n x nz grains with
// bonds to the 6 neighbours and to 4 of the 12 face diagonals, directions
// tilted at random, random masses, stiffnesses and radii; dashpots for the
// damping ratio zeta.  The bottom layer (z = 0) is the source.
struct TestNetwork {
  Acoustic::ContactNetwork network;
  std::vector<int> source_grains;
};

inline TestNetwork disordered_3d(int n, int nz, Acoustic::ContactModel model, double zeta, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  auto index = [&](int x, int y, int z) { return (z * n + y) * n + x; };
  std::vector<Acoustic::Grain> grains;
  for (int g = 0; g < n * n * nz; ++g) grains.push_back(Acoustic::Grain{0.6 + 0.8 * uniform(rng), 0.4 + 0.2 * uniform(rng)});
  std::vector<Acoustic::Contact> contacts;
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
          contacts.push_back(Acoustic::Contact{i, j, normal, kn, kt, 2.0 * zeta * std::sqrt(kn * meff),
                                     2.0 * zeta * std::sqrt(kt * meff)});
        }
  TestNetwork t{Acoustic::ContactNetwork(3, model, grains, contacts), {}};
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) t.source_grains.push_back(index(x, y, 0));
  return t;
}

}    // namespace AcousticTest

#endif
