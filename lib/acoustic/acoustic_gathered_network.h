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
   ACOUSTIC package numerics, inside the C++98 facade (C++17, not exported):
   the ContactNetwork of a gathered network, as the gathered drive, modes
   and pulse build it (acoustic_gathered_drive.h, acoustic_gathered_modes.h,
   acoustic_gathered_pulse.h).

   Grains in the caller's order (by atom ID, the walls after every atom, as
   the LAMMPS styles gather them); a grain of infinite mass (HUGE_VAL) is a
   wall, whose mass and radius become the LAMMPS styles' placeholders (1, 1)
   and whose DOFs the callers prescribe.  Contacts are taken from the lower
   to the higher grain index (the normal reversed, exactly) and sorted by
   (i, j), as the LAMMPS styles gather them: the same network gives the
   same matrices to the last bit.  Errors are thrown as SolverError whose
   message begins with `where` ("gathered modes: ").
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_GATHERED_NETWORK_H
#define ACOUSTIC_GATHERED_NETWORK_H

#include "acoustic_contact_network.h"
#include "acoustic_facade.h"
#include "acoustic_gathered_drive.h"

#include <string>
#include <vector>

namespace Acoustic {
namespace Gathered {

  // "%g" of value
  std::string number(double value);

  // SolverError unless MPI is initialised and not finalised
  void require_mpi(const std::string &where);

  // the ContactModel of a facade model; SolverError for a bad dimension or model
  ContactModel contact_model(const std::string &where, int dimension,
                             FacadeContactModel::Value model);

  // the grains of the network; wall[g] true for the walls
  std::vector<Grain> network_grains(const std::string &where,
                                    const std::vector<GatheredGrain> &grains,
                                    std::vector<bool> &wall);

  // the network of the grains (from network_grains) and the contacts
  ContactNetwork build_network(int dimension, ContactModel model, std::vector<Grain> grains,
                               const std::vector<GatheredContact> &contacts);

  // the grain indices of a list, checked (in 0 .. ngrains - 1, each once
  // across every list marked in `taken`, which it updates); `what` names
  // the list in the messages
  void check_grain_list(const std::string &where, const char *what, const std::vector<int> &list,
                        int ngrains, std::vector<char> &taken);

}    // namespace Gathered
}    // namespace Acoustic

#endif
