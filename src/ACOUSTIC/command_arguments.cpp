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

#include "command_arguments.h"

#include "fix.h"
#include "group.h"
#include "modify.h"
#include "utils.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

CommandArguments::CommandArguments(LAMMPS *lmp, const std::string &cmd, int n, char **words,
                                   int first) :
    Pointers(lmp),
    command(cmd), narg(n), arg(words), position(first), nvalues(0)
{
}

/* ---------------------------------------------------------------------- */

bool CommandArguments::take(const char *key, int n)
{
  if (position >= narg || strcmp(arg[position], key) != 0) return false;
  if (position + n >= narg) utils::missing_cmd_args(FLERR, command + " " + key, error);
  nvalues = n;
  return true;
}

void CommandArguments::expect(const char *key, int n)
{
  if (position >= narg) utils::missing_cmd_args(FLERR, command, error);
  if (!take(key, n))
    error->all(FLERR, position, "{}: expected '{}' as argument {}, got '{}'", command, key,
               position + 1, arg[position]);
}

void CommandArguments::next()
{
  position += 1 + nvalues;
  nvalues = 0;
}

/* ---------------------------------------------------------------------- */

const char *CommandArguments::word(int k) const
{
  return arg[position + k];
}

double CommandArguments::number(int k) const
{
  const double value = utils::numeric(FLERR, arg[position + k], false, lmp);
  // utils::numeric lets 1e400 through as infinity
  if (!std::isfinite(value))
    error->all(FLERR, position + k, "{}: {} must be a finite number, got {}", command,
               arg[position], arg[position + k]);
  return value;
}

int CommandArguments::integer(int k) const
{
  return utils::inumeric(FLERR, arg[position + k], false, lmp);
}

bigint CommandArguments::big_integer(int k) const
{
  return utils::bnumeric(FLERR, arg[position + k], false, lmp);
}

bool CommandArguments::logical(int k) const
{
  return utils::logical(FLERR, arg[position + k], false, lmp) == 1;
}

const char *CommandArguments::group_name(int k) const
{
  if (group->find(arg[position + k]) < 0)
    error->all(FLERR, position + k,
               "{}: {} group {} does not exist; define it with the group "
               "command first",
               command, arg[position], arg[position + k]);
  return arg[position + k];
}

const char *CommandArguments::wall_fix(int k) const
{
  Fix *wall = modify->get_fix_by_id(arg[position + k]);
  if (!wall ||
      !(utils::strmatch(wall->style, "^wall/gran$") ||
        utils::strmatch(wall->style, "^wall/gran/region$")))
    error->all(FLERR, position + k,
               "{}: {} wall {} is not a fix wall/gran or wall/gran/region; "
               "define the wall with one of them first",
               command, arg[position], arg[position + k]);
  return arg[position + k];
}

/* ---------------------------------------------------------------------- */

void CommandArguments::unknown(const std::string &keywords) const
{
  error->all(FLERR, position, "Unknown {} keyword: {}; keywords are {}", command, arg[position],
             keywords);
}
