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
   The words of a command of the ACOUSTIC package (fix acoustic/mindlin,
   compute vibration/modes, compute vibration/pulse), read keyword by
   keyword: one reader, so that the three commands check their values and
   report bad input alike, through LAMMPS's error helpers, with the
   offending word marked in the echo of the input line.
------------------------------------------------------------------------- */

#ifndef LMP_ACOUSTIC_COMMAND_ARGUMENTS_H
#define LMP_ACOUSTIC_COMMAND_ARGUMENTS_H

#include "error.h"
#include "pointers.h"

#include <string>

namespace LAMMPS_NS {

class CommandArguments : protected Pointers {
 public:
  // the words arg[0..narg) of `command` (e.g. "fix acoustic/mindlin"),
  // read from arg[first]
  CommandArguments(class LAMMPS *, const std::string &command, int narg, char **arg, int first);

  bool more() const { return position < narg; }
  int index() const { return position; }
  const char *keyword() const { return arg[position]; }

  // true if the word at the current position is `key`; it must then be
  // followed by `nvalues` words, or the command stops
  bool take(const char *key, int nvalues);
  // the current word must be `key`, followed by `nvalues` words
  void expect(const char *key, int nvalues);
  // past the keyword taken and its values
  void next();

  // value k (1, 2, ...) of the keyword taken
  const char *word(int k) const;
  double number(int k) const;    // a finite floating-point number
  int integer(int k) const;
  bigint big_integer(int k) const;
  bool logical(int k) const;
  // the ID of an existing group, or an ERROR that says how to define it
  const char *group_name(int k) const;
  // the ID of an existing fix wall/gran or wall/gran/region, or an ERROR
  const char *wall_fix(int k) const;

  // an ERROR about value k of the keyword taken (0: the keyword), the word
  // marked; called as reject(FLERR, k, "... {}", value)
  template <typename... Args>
  [[noreturn]] void reject(const std::string &file, int line, int k, const std::string &format,
                           Args &&...args) const
  {
    error->all(file, line, position + k, command + ": " + format, std::forward<Args>(args)...);
  }
  // an ERROR for a keyword the command does not have, listing those it has
  [[noreturn]] void unknown(const std::string &keywords) const;

 private:
  const std::string command;
  const int narg;
  char **const arg;
  int position;    // of the current keyword
  int nvalues;     // of the keyword taken
};

}    // namespace LAMMPS_NS

#endif
