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
   Fingerprints of what the vibration network of the ACOUSTIC package
   depends on, to tell whether the neighbor lists and contact models of
   the last run still describe the system between runs:
     atom order: the IDs of the owned and ghost atoms of this processor in
       local order (what neighbor lists and contact histories index);
     granular state: the atom order, the positions, radii, masses and group
       masks of those atoms, the box, pair granular (which instance, every
       sub-model's coefficients) and the fixes wall/gran (IDs, instances,
       planes, coefficients).
   Each is a 64-bit FNV-1a hash of this processor's data: compare them on
   every processor (MPI_Allreduce).  The fixes and the pair style are found
   anew at each call: no pointer is kept.
------------------------------------------------------------------------- */

#ifndef LMP_GRANULAR_STATE_H
#define LMP_GRANULAR_STATE_H

#include <cstdint>
#include <string>

namespace LAMMPS_NS {

class LAMMPS;

// FNV-1a over 64-bit words
class Fingerprint {
 public:
  void mix(std::uint64_t value);
  void mix(double value);
  void mix(const std::string &text);
  std::uint64_t value() const { return hash; }

 private:
  std::uint64_t hash = 1469598103934665603ULL;
};

std::uint64_t atom_order_fingerprint(LAMMPS *lmp);
std::uint64_t granular_state_fingerprint(LAMMPS *lmp);

// collective: true when every processor's value equals its `recorded`
bool same_on_every_rank(LAMMPS *lmp, std::uint64_t now, std::uint64_t recorded);

}    // namespace LAMMPS_NS

#endif
