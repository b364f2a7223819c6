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

#ifdef FIX_CLASS
// clang-format off
FixStyle(ACOUSTIC/STATE,FixAcousticState);
// clang-format on
#else

#ifndef LMP_FIX_ACOUSTIC_STATE_H
#define LMP_FIX_ACOUSTIC_STATE_H

#include "fix.h"

#include <cstdint>
#include <string>

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   Internal fix of the ACOUSTIC computes (created and deleted by them, as
   fix STORE/ATOM is by LAMMPS's own computes; argument: the compute's ID):
   records the granular state fingerprint (granular_state.h) at the setup
   and at the end of every run, when the neighbor lists and contact models
   describe the system, so that a compute evaluated between runs can tell
   whether they still do.  At the end of a run it also marks its compute as
   not invoked, so that the first evaluation between runs asks the compute
   (which checks the state) instead of reusing the run's last values.
------------------------------------------------------------------------- */

class FixAcousticState : public Fix {
 public:
  FixAcousticState(class LAMMPS *, int, char **);
  int setmask() override;
  void setup(int) override;
  void post_run() override;

  // collective: the system is the one of the last run's setup or end on
  // every processor (false before any run)
  bool current() const;

 private:
  std::uint64_t recorded;
  bool valid;
  std::string owner;    // the compute's ID
};

}    // namespace LAMMPS_NS

#endif
#endif
