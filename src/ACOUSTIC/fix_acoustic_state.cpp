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
   Contributing authors: the ACOUSTIC package developers.
------------------------------------------------------------------------- */

#include "fix_acoustic_state.h"

#include "compute.h"
#include "error.h"
#include "granular_state.h"
#include "modify.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixAcousticState::FixAcousticState(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), recorded(0), valid(false)
{
  if (narg != 4)
    error->all(FLERR,
               "Fix ACOUSTIC/STATE is internal to the ACOUSTIC package: expected fix ID "
               "group-ID ACOUSTIC/STATE owner-compute-ID");
  owner = arg[3];
}

int FixAcousticState::setmask()
{
  return POST_RUN;
}

void FixAcousticState::setup(int /*vflag*/)
{
  recorded = granular_state_fingerprint(lmp);
  valid = true;
}

void FixAcousticState::post_run()
{
  recorded = granular_state_fingerprint(lmp);
  valid = true;
  Compute *compute = modify->get_compute_by_id(owner);
  if (compute) compute->invoked_flag = Compute::INVOKED_NONE;
}

bool FixAcousticState::current() const
{
  int all_valid = valid ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &all_valid, 1, MPI_INT, MPI_MIN, world);
  return all_valid && same_on_every_rank(lmp, granular_state_fingerprint(lmp), recorded);
}
