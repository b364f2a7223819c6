/* ----------------------------------------------------------------------
   Unit tests: assembly of K, C, M of a contact network.
------------------------------------------------------------------------- */

#include "acoustic_contact_network.h"
#include "acoustic_solver_error.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <random>
#include <vector>

using namespace Acoustic;

namespace {

Eigen::MatrixXd dense(const Eigen::SparseMatrix<double> &m)
{
  return Eigen::MatrixXd(m);
}

Contact contact(int i, int j, const Eigen::Vector3d &n, double kn, double kt = 0.0, double cn = 0.0, double ct = 0.0)
{
  return Contact{i, j, n, kn, kt, cn, ct};
}

// Random tree of touching spheres (|x_i - x_j| = r_i + r_j on every contact)
// so that rigid rotations are exact zero modes of the full model.
struct TouchingCluster {
  std::vector<Grain> grains;
  std::vector<Contact> contacts;
  std::vector<Eigen::Vector3d> positions;
};

TouchingCluster touching_cluster(int dimension, int ngrains, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  TouchingCluster cluster;
  for (int g = 0; g < ngrains; ++g) {
    const double radius = 0.5 + 0.25 * (1.0 + uniform(rng));
    cluster.grains.push_back(Grain{1.0 + 0.5 * uniform(rng), radius});
    if (g == 0) {
      cluster.positions.push_back(Eigen::Vector3d::Zero());
      continue;
    }
    const int parent = static_cast<int>((g - 1) * (1.0 + uniform(rng)) / 2.0);
    Eigen::Vector3d n(uniform(rng), uniform(rng), dimension == 3 ? uniform(rng) : 0.0);
    n.normalize();
    cluster.positions.push_back(cluster.positions[parent] + (cluster.grains[parent].radius + radius) * n);
    cluster.contacts.push_back(contact(g, parent, n, 2.0 + uniform(rng), 1.0 + 0.5 * uniform(rng)));
  }
  return cluster;
}

}    // namespace

TEST(ContactNetwork, NormalModel2DMatchesHandDerivedMatrix)
{
  // grain 1 right of grain 0 (n = x, k_n = 2); grain 2 up-right of grain 0 (n = (0.6, 0.8), k_n = 5).
  // K = sum k_n (e_i - e_j)(e_i - e_j)^T (x) n n^T; DOFs (ux0, uy0, ux1, uy1, ux2, uy2).
  const ContactNetwork network(2, ContactModel::Normal, {{1.0, 0.5}, {1.0, 0.5}, {1.0, 0.5}},
                               {contact(1, 0, Eigen::Vector3d(1.0, 0.0, 0.0), 2.0, 9.0),
                                contact(2, 0, Eigen::Vector3d(0.6, 0.8, 0.0), 5.0, 9.0)});
  Eigen::MatrixXd expected(6, 6);
  expected <<  3.8,  2.4, -2.0, 0.0, -1.8, -2.4,
               2.4,  3.2,  0.0, 0.0, -2.4, -3.2,
              -2.0,  0.0,  2.0, 0.0,  0.0,  0.0,
               0.0,  0.0,  0.0, 0.0,  0.0,  0.0,
              -1.8, -2.4,  0.0, 0.0,  1.8,  2.4,
              -2.4, -3.2,  0.0, 0.0,  2.4,  3.2;
  EXPECT_LT((dense(network.stiffness_matrix()) - expected).norm(), 1e-13);
  EXPECT_EQ(network.dofs_per_grain(), 2);
  EXPECT_EQ(network.num_dofs(), 6);
}

TEST(ContactNetwork, NormalModel3DMatchesHandDerivedMatrix)
{
  // contact (1, 0): n = (0, 0.6, 0.8), k_n = 10; contact (2, 1): n = z, k_n = 1.
  const ContactNetwork network(3, ContactModel::Normal, {{1.0, 0.5}, {1.0, 0.5}, {1.0, 0.5}},
                               {contact(1, 0, Eigen::Vector3d(0.0, 0.6, 0.8), 10.0),
                                contact(2, 1, Eigen::Vector3d(0.0, 0.0, 1.0), 1.0)});
  Eigen::MatrixXd expected(9, 9);
  expected << 0,    0,    0, 0,    0,    0, 0, 0,  0,
              0,  3.6,  4.8, 0, -3.6, -4.8, 0, 0,  0,
              0,  4.8,  6.4, 0, -4.8, -6.4, 0, 0,  0,
              0,    0,    0, 0,    0,    0, 0, 0,  0,
              0, -3.6, -4.8, 0,  3.6,  4.8, 0, 0,  0,
              0, -4.8, -6.4, 0,  4.8,  7.4, 0, 0, -1,
              0,    0,    0, 0,    0,    0, 0, 0,  0,
              0,    0,    0, 0,    0,    0, 0, 0,  0,
              0,    0,    0, 0,    0,   -1, 0, 0,  1;
  EXPECT_LT((dense(network.stiffness_matrix()) - expected).norm(), 1e-13);
}

TEST(ContactNetwork, FullModel2DTwoDiscsMatchesHandDerivedMatrix)
{
  // disc i = 0 (r = 1) right of disc j = 1 (r = 2), n = x, k_n = 3, k_t = 2.
  // Delta_x = ux0 - ux1, Delta_y = uy0 - uy1 - r_i th0 - r_j th1 (n x theta z = -theta y).
  // K = k_n a a^T + k_t b b^T, a = (1, 0, 0, -1, 0, 0), b = (0, 1, -1, 0, -1, -2).
  const ContactNetwork network(2, ContactModel::Full, {{1.0, 1.0}, {2.0, 2.0}},
                               {contact(0, 1, Eigen::Vector3d(1.0, 0.0, 0.0), 3.0, 2.0)});
  Eigen::MatrixXd expected(6, 6);
  expected <<  3,  0,  0, -3,  0,  0,
               0,  2, -2,  0, -2, -4,
               0, -2,  2,  0,  2,  4,
              -3,  0,  0,  3,  0,  0,
               0, -2,  2,  0,  2,  4,
               0, -4,  4,  0,  4,  8;
  EXPECT_LT((dense(network.stiffness_matrix()) - expected).norm(), 1e-13);

  // rigid rotation by phi about any point p: u = phi z x (x - p), theta = phi
  const Eigen::Vector2d xi(1.0, 0.0), xj(-2.0, 0.0), p(0.3, -0.7);
  Eigen::VectorXd rotation(6);
  rotation << -(xi.y() - p.y()), xi.x() - p.x(), 1.0, -(xj.y() - p.y()), xj.x() - p.x(), 1.0;
  EXPECT_LT((expected * rotation).norm(), 1e-13);
  EXPECT_LT((dense(network.stiffness_matrix()) * rotation).norm(), 1e-13);

  // contact displacement of a given q, by hand
  Eigen::VectorXcd q(6);
  q << 0.1, std::complex<double>(0.2, 0.1), 0.3, -0.4, 0.5, std::complex<double>(0.0, -0.6);
  const std::vector<Eigen::Vector3cd> delta = network.contact_displacements(q);
  ASSERT_EQ(delta.size(), 1u);
  EXPECT_LT(std::abs(delta[0][0] - 0.5), 1e-15);
  EXPECT_LT(std::abs(delta[0][1] - (std::complex<double>(0.2, 0.1) - 0.5 - 1.0 * 0.3 - 2.0 * std::complex<double>(0.0, -0.6))), 1e-15);
  EXPECT_EQ(delta[0][2], 0.0);
}

TEST(ContactNetwork, FullModel3DTwoSpheresMatchesHandDerivedMatrix)
{
  // sphere i = 0 (r = 1) at +x of sphere j = 1 (r = 1.5), n = x, k_n = 4, k_t = 2.
  // n x theta = (0, -theta_z, theta_y), so
  //   Delta_x = ux0 - ux1, Delta_y = uy0 - uy1 - thz0 - 1.5 thz1, Delta_z = uz0 - uz1 + thy0 + 1.5 thy1.
  // DOFs (ux, uy, uz, thx, thy, thz) of grain 0, then of grain 1.
  const ContactNetwork network(3, ContactModel::Full, {{1.0, 1.0}, {3.0, 1.5}},
                               {contact(0, 1, Eigen::Vector3d(1.0, 0.0, 0.0), 4.0, 2.0)});
  Eigen::MatrixXd expected(12, 12);
  expected << 4,  0,  0, 0,  0,  0, -4,  0,  0, 0,   0,   0,
              0,  2,  0, 0,  0, -2,  0, -2,  0, 0,   0,  -3,
              0,  0,  2, 0,  2,  0,  0,  0, -2, 0,   3,   0,
              0,  0,  0, 0,  0,  0,  0,  0,  0, 0,   0,   0,
              0,  0,  2, 0,  2,  0,  0,  0, -2, 0,   3,   0,
              0, -2,  0, 0,  0,  2,  0,  2,  0, 0,   0,   3,
             -4,  0,  0, 0,  0,  0,  4,  0,  0, 0,   0,   0,
              0, -2,  0, 0,  0,  2,  0,  2,  0, 0,   0,   3,
              0,  0, -2, 0, -2,  0,  0,  0,  2, 0,  -3,   0,
              0,  0,  0, 0,  0,  0,  0,  0,  0, 0,   0,   0,
              0,  0,  3, 0,  3,  0,  0,  0, -3, 0, 4.5,   0,
              0, -3,  0, 0,  0,  3,  0,  3,  0, 0,   0, 4.5;
  EXPECT_LT((dense(network.stiffness_matrix()) - expected).norm(), 1e-13);
  EXPECT_EQ(network.dofs_per_grain(), 6);
}

TEST(ContactNetwork, RigidBodyMotionsAreInTheNullSpace)
{
  for (int dimension = 2; dimension <= 3; ++dimension) {
    for (ContactModel model : {ContactModel::Normal, ContactModel::Full}) {
      const TouchingCluster cluster = touching_cluster(dimension, 12, 7u + dimension);
      const ContactNetwork network(dimension, model, cluster.grains, cluster.contacts);
      const Eigen::MatrixXd k = dense(network.stiffness_matrix());
      SCOPED_TRACE("dimension " + std::to_string(dimension) + ", model " + contact_model_name(model));
      EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
      EXPECT_GT(k.norm(), 1.0);

      for (int d = 0; d < dimension; ++d) {    // translations
        Eigen::VectorXd t = Eigen::VectorXd::Zero(network.num_dofs());
        for (int g = 0; g < network.num_grains(); ++g) t[network.dof(g, d)] = 1.0;
        EXPECT_LT((k * t).norm(), 1e-12 * k.norm());
      }
      // rigid rotations about the axes (only z in 2D): u = w x (x - p), theta = w
      const Eigen::Vector3d p(0.4, -0.2, 0.1);
      for (int axis = (dimension == 2 ? 2 : 0); axis < 3; ++axis) {
        const Eigen::Vector3d w = Eigen::Vector3d::Unit(axis);
        Eigen::VectorXd r = Eigen::VectorXd::Zero(network.num_dofs());
        for (int g = 0; g < network.num_grains(); ++g) {
          const Eigen::Vector3d u = w.cross(cluster.positions[g] - p);
          for (int d = 0; d < dimension; ++d) r[network.dof(g, d)] = u[d];
          if (model == ContactModel::Full) {
            if (dimension == 2) r[network.dof(g, 2)] = 1.0;
            else
              for (int d = 0; d < 3; ++d) r[network.dof(g, 3 + d)] = w[d];
          }
        }
        EXPECT_LT((k * r).norm(), 1e-12 * k.norm() * r.norm());
        // and a rigid motion strains no contact (model normal: no normal strain)
        const std::vector<Eigen::Vector3cd> deltas = network.contact_displacements(r.cast<std::complex<double>>());
        for (int c = 0; c < network.num_contacts(); ++c) {
          const Eigen::Vector3cd n = network.contacts()[c].normal.cast<std::complex<double>>();
          const double strain = model == ContactModel::Full ? deltas[c].norm() : std::abs(n.dot(deltas[c]));
          EXPECT_LT(strain, 1e-12 * r.norm());
        }
      }
    }
  }
}

TEST(ContactNetwork, DampingHasThePatternOfStiffness)
{
  const TouchingCluster cluster = touching_cluster(3, 8, 3u);
  std::vector<Contact> damped = cluster.contacts;
  for (Contact &c : damped) {
    c.cn = 0.1 * c.kn;
    c.ct = 0.1 * c.kt;
  }
  const ContactNetwork plain(3, ContactModel::Full, cluster.grains, cluster.contacts);
  const ContactNetwork network(3, ContactModel::Full, cluster.grains, damped);
  EXPECT_FALSE(plain.has_damping());
  EXPECT_EQ(plain.damping_matrix().nonZeros(), 0);
  EXPECT_TRUE(network.has_damping());
  EXPECT_LT((dense(network.damping_matrix()) - 0.1 * dense(network.stiffness_matrix())).norm(), 1e-13);
}

TEST(ContactNetwork, MassHasMomentOfInertiaOfSpheres)
{
  const ContactNetwork full2d(2, ContactModel::Full, {{2.0, 0.5}, {3.0, 1.0}}, {});
  Eigen::VectorXd expected(6);
  expected << 2.0, 2.0, 0.4 * 2.0 * 0.25, 3.0, 3.0, 0.4 * 3.0;
  EXPECT_LT((full2d.mass_diagonal() - expected).norm(), 1e-15);
  EXPECT_LT((Eigen::VectorXd(Eigen::MatrixXd(full2d.mass_matrix()).diagonal()) - expected).norm(), 1e-15);

  const ContactNetwork full3d(3, ContactModel::Full, {{2.0, 0.5}}, {});
  Eigen::VectorXd expected3(6);
  expected3 << 2.0, 2.0, 2.0, 0.2, 0.2, 0.2;
  EXPECT_LT((full3d.mass_diagonal() - expected3).norm(), 1e-15);

  const ContactNetwork normal3d(3, ContactModel::Normal, {{2.0, 0.5}}, {});
  EXPECT_EQ(normal3d.mass_diagonal().size(), 3);
}

TEST(ContactNetwork, RejectsInvalidInput)
{
  const std::vector<Grain> two = {{1.0, 0.5}, {1.0, 0.5}};
  const Eigen::Vector3d x(1.0, 0.0, 0.0);
  EXPECT_THROW(ContactNetwork(4, ContactModel::Normal, two, {}), SolverError);
  EXPECT_THROW(ContactNetwork(2, ContactModel::Normal, two, {contact(0, 2, x, 1.0)}), SolverError);
  EXPECT_THROW(ContactNetwork(2, ContactModel::Normal, two, {contact(1, 1, x, 1.0)}), SolverError);
  EXPECT_THROW(ContactNetwork(2, ContactModel::Normal, two, {contact(0, 1, 2.0 * x, 1.0)}), SolverError);
  EXPECT_THROW(ContactNetwork(2, ContactModel::Normal, two, {contact(0, 1, Eigen::Vector3d(0, 0, 1), 1.0)}),
               SolverError);
  EXPECT_THROW(ContactNetwork(2, ContactModel::Normal, two, {contact(0, 1, x, -1.0)}), SolverError);
  EXPECT_THROW(ContactNetwork(2, ContactModel::Normal, {{0.0, 0.5}, {1.0, 0.5}}, {}), SolverError);
  EXPECT_THROW(ContactNetwork(2, ContactModel::Full, {{1.0, 0.0}, {1.0, 0.5}}, {}), SolverError);
  EXPECT_THROW(contact_model_from_name("tangential"), SolverError);
  EXPECT_EQ(contact_model_from_name("full"), ContactModel::Full);
  const ContactNetwork ok(2, ContactModel::Normal, two, {contact(0, 1, x, 1.0)});
  EXPECT_THROW(ok.contact_displacements(Eigen::VectorXcd::Zero(3)), SolverError);
}

TEST(ContactNetwork, PointDisplacementEqualsJacobianTimesDofs)
{
  // the per-contact shortcut used by the LAMMPS fix against the Jacobian used by the assembly
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int dimension : {2, 3}) {
    for (ContactModel model : {ContactModel::Normal, ContactModel::Full}) {
      const int ndof = dofs_per_grain(dimension, model);
      for (int trial = 0; trial < 5; ++trial) {
        Eigen::Vector3d n(u(rng), u(rng), dimension == 3 ? u(rng) : 0.0);
        n.normalize();
        const double ri = 0.5 + 0.5 * std::abs(u(rng)), rj = 0.5 + 0.5 * std::abs(u(rng));
        Eigen::VectorXcd qi(ndof), qj(ndof), both(2 * ndof);
        for (int k = 0; k < ndof; ++k) {
          qi[k] = std::complex<double>(u(rng), u(rng));
          qj[k] = std::complex<double>(u(rng), u(rng));
        }
        both << qi, qj;
        const Eigen::Vector3cd expected =
            contact_jacobian(dimension, model, n, ri, rj).cast<std::complex<double>>() * both;
        const Eigen::Vector3cd delta = contact_point_displacement(dimension, model, n, ri, rj, qi, qj);
        EXPECT_LT((delta - expected).norm(), 1e-14) << "dimension " << dimension << " model "
                                                     << contact_model_name(model);
      }
    }
  }
}
