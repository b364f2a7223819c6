/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   ACOUSTIC package numerics: the linearised contact network.
------------------------------------------------------------------------- */

#include "acoustic_contact_network.h"

#include "acoustic_solver_error.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace Acoustic {

namespace {

  bool finite_nonnegative(double x)
  {
    return std::isfinite(x) && x >= 0.0;
  }

  bool finite_positive(double x)
  {
    return std::isfinite(x) && x > 0.0;
  }

  // matrix of the cross product a x b = [a]_x b
  Eigen::Matrix3d cross_matrix(const Eigen::Vector3d &a)
  {
    Eigen::Matrix3d m;
    m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
    return m;
  }

}    // namespace

ContactModel contact_model_from_name(const std::string &name)
{
  if (name == "normal") return ContactModel::Normal;
  if (name == "full") return ContactModel::Full;
  throw SolverError("unknown contact model '" + name + "': allowed models are normal, full");
}

std::string contact_model_name(ContactModel model)
{
  return model == ContactModel::Normal ? "normal" : "full";
}

ContactNetwork::ContactNetwork(int dimension, ContactModel model, std::vector<Grain> grains,
                               std::vector<Contact> contacts) :
    dimension_(dimension),
    model_(model), grains_(std::move(grains)), contacts_(std::move(contacts))
{
  if (dimension_ != 2 && dimension_ != 3)
    throw SolverError("contact network: dimension must be 2 or 3, got " +
                      std::to_string(dimension_));
  for (std::size_t g = 0; g < grains_.size(); ++g) {
    if (!finite_positive(grains_[g].mass))
      throw SolverError(
          "contact network: grain " + std::to_string(g) +
          " has a mass that is not positive and finite; give frozen grains their real "
          "mass and prescribe or fix their degrees of freedom instead");
    if (model_ == ContactModel::Full && !finite_positive(grains_[g].radius))
      throw SolverError("contact network: grain " + std::to_string(g) +
                        " has a radius that is not positive and finite (model full needs radii)");
  }
  const int ngrains = num_grains();
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    const Contact &c = contacts_[k];
    // built only when a check fails: this loop runs over every contact
    auto which = [k]() {
      return "contact network: contact " + std::to_string(k) + " ";
    };
    if (c.i < 0 || c.i >= ngrains || c.j < 0 || c.j >= ngrains)
      throw SolverError(which() + "refers to a grain outside 0.." + std::to_string(ngrains - 1));
    if (c.i == c.j)
      throw SolverError(which() + "joins grain " + std::to_string(c.i) + " to itself");
    if (!c.normal.allFinite() || std::abs(c.normal.norm() - 1.0) > 1e-8)
      throw SolverError(which() + "has a normal that is not a unit vector");
    if (dimension_ == 2 && std::abs(c.normal.z()) > 1e-12)
      throw SolverError(which() + "has a normal with a z component in a 2D network");
    if (!finite_nonnegative(c.kn) || !finite_nonnegative(c.kt))
      throw SolverError(which() + "has a stiffness that is negative or not finite");
    if (!finite_nonnegative(c.cn) || !finite_nonnegative(c.ct))
      throw SolverError(which() + "has a dashpot coefficient that is negative or not finite");
  }
}

int dofs_per_grain(int dimension, ContactModel model)
{
  if (model == ContactModel::Normal) return dimension;
  return dimension == 2 ? 3 : 6;
}

int ContactNetwork::dofs_per_grain() const
{
  return Acoustic::dofs_per_grain(dimension_, model_);
}

ContactJacobian contact_jacobian(int dimension, ContactModel model, const Eigen::Vector3d &normal,
                                 double radius_i, double radius_j)
{
  // Delta = (u_i - u_j) + n x (r_i theta_i + r_j theta_j)
  const int ndof = dofs_per_grain(dimension, model);
  ContactJacobian jac = ContactJacobian::Zero(3, 2 * ndof);
  for (int d = 0; d < dimension; ++d) {
    jac(d, d) = 1.0;
    jac(d, ndof + d) = -1.0;
  }
  if (model == ContactModel::Full) {
    const Eigen::Matrix3d nx = cross_matrix(normal);
    if (dimension == 2) {    // only theta_z: column z of [n]_x
      jac.col(2) = radius_i * nx.col(2);
      jac.col(ndof + 2) = radius_j * nx.col(2);
    } else {
      jac.block(0, 3, 3, 3) = radius_i * nx;
      jac.block(0, ndof + 3, 3, 3) = radius_j * nx;
    }
  }
  return jac;
}

Eigen::Vector3cd contact_point_displacement(int dimension, ContactModel model,
                                            const Eigen::Vector3d &normal, double radius_i,
                                            double radius_j, const Eigen::VectorXcd &q_i,
                                            const Eigen::VectorXcd &q_j)
{
  const int ndof = dofs_per_grain(dimension, model);
  if (q_i.size() != ndof || q_j.size() != ndof)
    throw SolverError("contact point displacement: each grain needs " + std::to_string(ndof) +
                      " DOF values, got " + std::to_string(q_i.size()) + " and " +
                      std::to_string(q_j.size()));
  // Delta = (u_i - u_j) + n x (r_i theta_i + r_j theta_j), as contact_jacobian()
  Eigen::Vector3cd delta = Eigen::Vector3cd::Zero();
  delta.head(dimension) = q_i.head(dimension) - q_j.head(dimension);
  if (model == ContactModel::Full) {
    Eigen::Vector3cd theta = Eigen::Vector3cd::Zero();
    if (dimension == 2)
      theta.z() = radius_i * q_i[2] + radius_j * q_j[2];
    else
      theta = radius_i * q_i.segment<3>(3) + radius_j * q_j.segment<3>(3);
    delta.x() += normal.y() * theta.z() - normal.z() * theta.y();
    delta.y() += normal.z() * theta.x() - normal.x() * theta.z();
    delta.z() += normal.x() * theta.y() - normal.y() * theta.x();
  }
  return delta;
}

ContactJacobian ContactNetwork::contact_jacobian(const Contact &c) const
{
  return Acoustic::contact_jacobian(dimension_, model_, c.normal, grains_[c.i].radius,
                                    grains_[c.j].radius);
}

// K (or C) directly in compressed column storage, without sorting triplets:
// the columns of grain g hold the dofs_per_grain() x dofs_per_grain() blocks of
// g and of its contact partners, in the order of their indices.
Eigen::SparseMatrix<double> ContactNetwork::assemble(bool dashpots) const
{
  const int ndof = dofs_per_grain();
  const int ngrains = num_grains();
  auto coefficients = [&](const Contact &c) {
    const double normal = dashpots ? c.cn : c.kn;
    const double tangential = (model_ == ContactModel::Full) ? (dashpots ? c.ct : c.kt) : 0.0;
    return std::make_pair(normal, tangential);
  };
  auto included = [&](const Contact &c) {
    const std::pair<double, double> k = coefficients(c);
    return !dashpots || k.first != 0.0 || k.second != 0.0;
  };

  // block rows of each grain's columns: itself and its partners, sorted, once
  // each (no block at all for a grain without contact)
  std::vector<int> first(ngrains + 1, 0);
  for (const Contact &c : contacts_)
    if (included(c)) {
      ++first[c.i + 1];
      ++first[c.j + 1];
    }
  for (int g = 0; g < ngrains; ++g) first[g + 1] += first[g] + (first[g + 1] > 0 ? 1 : 0);
  std::vector<int> partners(first[ngrains]);
  std::vector<int> filled(first.begin(), first.end() - 1);
  for (int g = 0; g < ngrains; ++g)
    if (first[g + 1] > first[g]) partners[filled[g]++] = g;
  for (const Contact &c : contacts_)
    if (included(c)) {
      partners[filled[c.i]++] = c.j;
      partners[filled[c.j]++] = c.i;
    }
  std::vector<int> nblocks(ngrains);
  for (int g = 0; g < ngrains; ++g) {
    const auto begin = partners.begin() + first[g], end = partners.begin() + first[g + 1];
    std::sort(begin, end);
    nblocks[g] = static_cast<int>(std::unique(begin, end) - begin);
  }

  // column starts: every column of grain g has nblocks[g] * ndof entries
  const int n = num_dofs();
  std::vector<int> outer(n + 1, 0);
  for (int g = 0; g < ngrains; ++g)
    for (int d = 0; d < ndof; ++d) outer[g * ndof + d + 1] = nblocks[g] * ndof;
  for (int col = 0; col < n; ++col) outer[col + 1] += outer[col];
  std::vector<int> inner(outer[n]);
  std::vector<double> values(outer[n], 0.0);
  for (int g = 0; g < ngrains; ++g)
    for (int d = 0; d < ndof; ++d) {
      int *rows = inner.data() + outer[g * ndof + d];
      for (int b = 0; b < nblocks[g]; ++b)
        for (int r = 0; r < ndof; ++r) rows[b * ndof + r] = partners[first[g] + b] * ndof + r;
    }
  // adds block (row grain h, column grain g) of a contact's local matrix
  auto add_block = [&](int h, int g, const Eigen::Ref<const Eigen::MatrixXd> &block) {
    const auto begin = partners.begin() + first[g], end = begin + nblocks[g];
    const int b = static_cast<int>(std::lower_bound(begin, end, h) - begin);
    for (int d = 0; d < ndof; ++d) {
      double *column = values.data() + outer[g * ndof + d] + b * ndof;
      for (int r = 0; r < ndof; ++r) column[r] += block(r, d);
    }
  };

  for (const Contact &c : contacts_) {
    if (!included(c)) continue;
    const std::pair<double, double> k = coefficients(c);
    const Eigen::Matrix3d nn = c.normal * c.normal.transpose();
    if (model_ == ContactModel::Normal) {
      // translations only: blocks +-k_n n n^T, no Jacobian product needed
      const Eigen::Matrix3d block = k.first * nn, negative = -block;
      add_block(c.i, c.i, block.topLeftCorner(ndof, ndof));
      add_block(c.j, c.j, block.topLeftCorner(ndof, ndof));
      add_block(c.i, c.j, negative.topLeftCorner(ndof, ndof));
      add_block(c.j, c.i, negative.topLeftCorner(ndof, ndof));
      continue;
    }
    const Eigen::Matrix3d spring = k.first * nn + k.second * (Eigen::Matrix3d::Identity() - nn);
    const ContactJacobian jac = contact_jacobian(c);
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 12, 12> local =
        jac.transpose() * spring * jac;
    add_block(c.i, c.i, local.topLeftCorner(ndof, ndof));
    add_block(c.j, c.j, local.bottomRightCorner(ndof, ndof));
    add_block(c.i, c.j, local.topRightCorner(ndof, ndof));
    add_block(c.j, c.i, local.bottomLeftCorner(ndof, ndof));
  }
  return Eigen::Map<const Eigen::SparseMatrix<double>>(n, n, outer[n], outer.data(), inner.data(),
                                                       values.data());
}

Eigen::SparseMatrix<double> ContactNetwork::stiffness_matrix() const
{
  return assemble(false);
}

Eigen::SparseMatrix<double> ContactNetwork::damping_matrix() const
{
  return assemble(true);
}

Eigen::VectorXd ContactNetwork::mass_diagonal() const
{
  const int ndof = dofs_per_grain();
  Eigen::VectorXd mass(num_dofs());
  for (int g = 0; g < num_grains(); ++g) {
    const double m = grains_[g].mass;
    const double inertia = 0.4 * m * grains_[g].radius * grains_[g].radius;
    for (int d = 0; d < ndof; ++d) mass[dof(g, d)] = d < dimension_ ? m : inertia;
  }
  return mass;
}

Eigen::SparseMatrix<double> ContactNetwork::mass_matrix() const
{
  const Eigen::VectorXd mass = mass_diagonal();
  Eigen::SparseMatrix<double> matrix(num_dofs(), num_dofs());
  matrix.reserve(Eigen::VectorXi::Ones(num_dofs()));
  for (int k = 0; k < num_dofs(); ++k) matrix.insert(k, k) = mass[k];
  matrix.makeCompressed();
  return matrix;
}

bool ContactNetwork::has_damping() const
{
  for (const Contact &c : contacts_)
    if (c.cn > 0.0 || (model_ == ContactModel::Full && c.ct > 0.0)) return true;
  return false;
}

std::vector<Eigen::Vector3cd> ContactNetwork::contact_displacements(const Eigen::VectorXcd &q) const
{
  if (q.size() != num_dofs())
    throw SolverError("contact displacements: the DOF vector has " + std::to_string(q.size()) +
                      " entries, the network has " + std::to_string(num_dofs()) + " DOFs");
  const int ndof = dofs_per_grain();
  std::vector<Eigen::Vector3cd> delta;
  delta.reserve(contacts_.size());
  for (const Contact &c : contacts_)
    delta.push_back(contact_point_displacement(dimension_, model_, c.normal, grains_[c.i].radius,
                                               grains_[c.j].radius, q.segment(c.i * ndof, ndof),
                                               q.segment(c.j * ndof, ndof)));
  return delta;
}

}    // namespace Acoustic
