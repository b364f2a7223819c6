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
   ACOUSTIC package numerics, C++98 facade: the network of a gathered
   drive, modes or pulse (see the header).
------------------------------------------------------------------------- */

#include "acoustic_gathered_network.h"

#include "acoustic_solver_error.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace Acoustic {
namespace Gathered {

  std::string number(double value)
  {
    char text[32];
    std::snprintf(text, sizeof(text), "%g", value);
    return text;
  }

  void require_mpi(const std::string &where)
  {
    int mpi_initialised = 0, mpi_finalised = 0;
    MPI_Initialized(&mpi_initialised);
    MPI_Finalized(&mpi_finalised);
    if (!mpi_initialised || mpi_finalised)
      throw SolverError(where +
                        "MPI is not initialised (or already finalised): the solvers run on "
                        "MPI_COMM_SELF; call MPI_Init first");
  }

  ContactModel contact_model(const std::string &where, int dimension,
                             FacadeContactModel::Value model)
  {
    if (dimension != 2 && dimension != 3)
      throw SolverError(where + "dimension must be 2 or 3, got " + std::to_string(dimension));
    if (model != FacadeContactModel::Normal && model != FacadeContactModel::Full)
      throw SolverError(where + "unknown contact model " + std::to_string(static_cast<int>(model)) +
                        " (FacadeContactModel::Normal or Full)");
    return (model == FacadeContactModel::Full) ? ContactModel::Full : ContactModel::Normal;
  }

  std::vector<Grain> network_grains(const std::string &where,
                                    const std::vector<GatheredGrain> &input,
                                    std::vector<bool> &wall)
  {
    std::vector<Grain> grains(input.size());
    wall.assign(input.size(), false);
    for (std::size_t g = 0; g < input.size(); ++g) {
      const double mass = input[g].mass;
      if (mass == HUGE_VAL) {
        wall[g] = true;
        grains[g].mass = 1.0;
        grains[g].radius = 1.0;
        continue;
      }
      if (!(std::isfinite(mass) && mass > 0.0))
        throw SolverError(where + "grain " + std::to_string(g) + " has mass " + number(mass) +
                          "; give a positive, finite mass, or +infinity for a wall (whose DOFs "
                          "are then prescribed)");
      grains[g].mass = mass;
      grains[g].radius = input[g].radius;
    }
    return grains;
  }

  namespace {
    Contact network_contact(const GatheredContact &c, bool flip)
    {
      Contact contact;
      const double sign = flip ? -1.0 : 1.0;
      contact.i = flip ? c.j : c.i;
      contact.j = flip ? c.i : c.j;
      contact.normal = Eigen::Vector3d(sign * c.normal[0], sign * c.normal[1], sign * c.normal[2]);
      contact.kn = c.kn;
      contact.kt = c.kt;
      contact.cn = c.cn;
      contact.ct = c.ct;
      return contact;
    }
  }    // namespace

  ContactNetwork build_network(int dimension, ContactModel model, std::vector<Grain> grains,
                               const std::vector<GatheredContact> &input)
  {
    std::vector<Contact> contacts;
    contacts.reserve(input.size());
    for (const GatheredContact &c : input) contacts.push_back(network_contact(c, c.i > c.j));
    std::stable_sort(contacts.begin(), contacts.end(), [](const Contact &a, const Contact &b) {
      return (a.i < b.i) || (a.i == b.i && a.j < b.j);
    });
    try {
      return ContactNetwork(dimension, model, grains, std::move(contacts));
    } catch (SolverError &) {
      // the same checks on the contacts as given, for the message
      std::vector<Contact> as_given;
      as_given.reserve(input.size());
      for (const GatheredContact &c : input) as_given.push_back(network_contact(c, false));
      ContactNetwork check(dimension, model, std::move(grains), std::move(as_given));
      throw;
    }
  }

  void check_grain_list(const std::string &where, const char *what, const std::vector<int> &list,
                        int ngrains, std::vector<char> &taken)
  {
    taken.resize(static_cast<std::size_t>(ngrains), 0);
    for (std::size_t k = 0; k < list.size(); ++k) {
      const int g = list[k];
      if (g < 0 || g >= ngrains)
        throw SolverError(where + what + " grain " + std::to_string(k) + " is " +
                          std::to_string(g) + ", outside 0.." + std::to_string(ngrains - 1));
      if (taken[g])
        throw SolverError(where + what + " grain " + std::to_string(g) +
                          " is listed twice (in this list or another one): a grain is a "
                          "source, a detector or fixed, one of the three");
      taken[g] = 1;
    }
  }

}    // namespace Gathered
}    // namespace Acoustic
