/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   Steve Plimpton, sjplimp@sandia.gov

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

#include "fix_neigh_history_acoustic.h"

#include "comm.h"
#include "update.h"

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

FixNeighHistoryAcoustic::FixNeighHistoryAcoustic(LAMMPS *lmp, int narg, char **arg) :
    FixNeighHistory(lmp, narg, arg)
{
}

/* ----------------------------------------------------------------------
   during a run (restart every N steps) the neighbor list matches the atoms:
   copy the per-neighbor values to the per-atom arrays as FixNeighHistory
   does; between runs (write_restart command) keep the copy of post_run()
------------------------------------------------------------------------- */

void FixNeighHistoryAcoustic::write_restart(FILE *fp)
{
  if (update->whichflag != 0) pre_exchange();
  if (comm->me == 0) {
    int size = 0;
    fwrite(&size, sizeof(int), 1, fp);
  }
}
