/* -*- c++ -*- ----------------------------------------------------------
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

   Grains joined by contact springs (and optional dashpots), assembled into
   the sparse stiffness K, damping C and diagonal mass M of the vibration
   problem  M q'' + C q' + K q = 0.

   Degrees of freedom (DOFs) are stored grain by grain, grain g owning the
   contiguous range [g * dofs_per_grain(), (g + 1) * dofs_per_grain()):
     model Normal, 2D: (ux, uy)               3D: (ux, uy, uz)
     model Full,   2D: (ux, uy, theta_z)      3D: (ux, uy, uz, theta_x, theta_y, theta_z)
   Mass: m per translation, the sphere's moment of inertia 0.4 m r^2 per
   rotation.

   Contact c = (i, j) with unit normal n = (x_i - x_j) / |x_i - x_j| (from j
   to i).  Relative displacement of the contact point:
     Full:   Delta = (u_i + theta_i x (-r_i n)) - (u_j + theta_j x (r_j n))
     Normal: Delta = u_i - u_j
   Energy 1/2 k_n (Delta.n)^2 + 1/2 k_t |Delta - (Delta.n) n|^2 (k_t is not
   used by model Normal); the dashpots c_n, c_t act on dDelta/dt the same way.
   In 2D the normal must lie in the xy plane and only in-plane translations
   and the rotation about z exist.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_CONTACT_NETWORK_H
#define ACOUSTIC_CONTACT_NETWORK_H

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <string>
#include <vector>

namespace Acoustic {

enum class ContactModel { Normal, Full };

// "normal" or "full"; throws SolverError listing the allowed names otherwise.
ContactModel contact_model_from_name(const std::string &name);
std::string contact_model_name(ContactModel model);

// DOFs per grain: dimension (model Normal), 3 in 2D or 6 in 3D (model Full).
int dofs_per_grain(int dimension, ContactModel model);

// 3 x (2 dofs_per_grain) map from the DOFs (q_i, q_j) of a contact's two grains
// to the relative displacement Delta of its contact point (see above).
// (at most 3 x 12: fixed storage, no allocation per contact)
typedef Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 12> ContactJacobian;
ContactJacobian contact_jacobian(int dimension, ContactModel model, const Eigen::Vector3d &normal,
                                 double radius_i, double radius_j);

// Delta of one contact from the complex DOF values of its two grains
// (dofs_per_grain values each); what contact_displacements() computes for
// every contact of a network, for a caller that holds the grain values itself.
Eigen::Vector3cd contact_point_displacement(int dimension, ContactModel model,
                                            const Eigen::Vector3d &normal, double radius_i,
                                            double radius_j, const Eigen::VectorXcd &q_i,
                                            const Eigen::VectorXcd &q_j);

struct Grain {
  double mass;      // > 0 and finite
  double radius;    // > 0 and finite (used by model Full: lever arm and moment of inertia)
};

struct Contact {
  int i;    // grain indices, i != j
  int j;
  Eigen::Vector3d normal;    // unit vector from j to i (z component 0 in 2D)
  double kn;                 // normal stiffness >= 0
  double kt;                 // tangential stiffness >= 0 (model Full only)
  double cn;                 // normal dashpot >= 0
  double ct;                 // tangential dashpot >= 0 (model Full only)
};

class ContactNetwork {
 public:
  // Validates the input (dimension 2 or 3, grain and contact data) and throws
  // SolverError with the offending grain or contact on error.
  ContactNetwork(int dimension, ContactModel model, std::vector<Grain> grains,
                 std::vector<Contact> contacts);

  int dimension() const { return dimension_; }
  ContactModel model() const { return model_; }
  int dofs_per_grain() const;
  int num_grains() const { return static_cast<int>(grains_.size()); }
  int num_contacts() const { return static_cast<int>(contacts_.size()); }
  int num_dofs() const { return num_grains() * dofs_per_grain(); }
  // index of DOF `component` (0 .. dofs_per_grain()-1, translations first) of a grain
  int dof(int grain, int component) const { return grain * dofs_per_grain() + component; }

  const std::vector<Grain> &grains() const { return grains_; }
  const std::vector<Contact> &contacts() const { return contacts_; }

  // Symmetric positive semi-definite stiffness K (num_dofs x num_dofs).
  Eigen::SparseMatrix<double> stiffness_matrix() const;
  // Damping C from the dashpots; has no stored entries when every dashpot is 0.
  Eigen::SparseMatrix<double> damping_matrix() const;
  // Diagonal of M.
  Eigen::VectorXd mass_diagonal() const;
  Eigen::SparseMatrix<double> mass_matrix() const;
  bool has_damping() const;

  // Complex relative displacement Delta of every contact (same order as
  // contacts()) for the complex DOF vector q (size num_dofs()).
  std::vector<Eigen::Vector3cd> contact_displacements(const Eigen::VectorXcd &q) const;

 private:
  // 3 x (2 dofs_per_grain) map from (q_i, q_j) to Delta for contact c.
  ContactJacobian contact_jacobian(const Contact &c) const;
  Eigen::SparseMatrix<double> assemble(bool dashpots) const;

  int dimension_;
  ContactModel model_;
  std::vector<Grain> grains_;
  std::vector<Contact> contacts_;
};

}    // namespace Acoustic

#endif
