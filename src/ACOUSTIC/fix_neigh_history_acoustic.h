/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   Steve Plimpton, sjplimp@sandia.gov

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(NEIGH_HISTORY/ACOUSTIC,FixNeighHistoryAcoustic);
// clang-format on
#else

#ifndef LMP_FIX_NEIGH_HISTORY_ACOUSTIC_H
#define LMP_FIX_NEIGH_HISTORY_ACOUSTIC_H

#include "fix_neigh_history.h"

namespace LAMMPS_NS {

// Contact history of pair_style granular/acoustic.  It differs from
// FixNeighHistory only in write_restart(): the write_restart command moves
// atoms between processors and rebuilds the ghost atoms without rebuilding
// the neighbor list, so copying the per-neighbor values to the per-atom
// arrays at that point pairs values with the wrong partners.  Between runs
// the copy taken by post_run() is current and is written as it is.

class FixNeighHistoryAcoustic : public FixNeighHistory {
 public:
  FixNeighHistoryAcoustic(class LAMMPS *, int, char **);
  void write_restart(FILE *) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
