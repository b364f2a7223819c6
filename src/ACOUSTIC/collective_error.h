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
   Errors found on some ranks only (a contact, a solve on rank 0), raised
   on every rank: Error::one() would end in MPI_Abort and leave nothing in
   the log file of a batch run; Error::all() on every rank writes the
   ERROR line to screen and log.
------------------------------------------------------------------------- */

#ifndef LMP_COLLECTIVE_ERROR_H
#define LMP_COLLECTIVE_ERROR_H

#include "pointers.h"

#include <string>

namespace LAMMPS_NS {

class CollectiveError : protected Pointers {
 public:
  explicit CollectiveError(class LAMMPS *lmp) : Pointers(lmp) {}

  // keep the first problem found on this rank
  void report(const std::string &message)
  {
    if (problem.empty()) problem = message;
  }
  bool reported() const { return !problem.empty(); }

  // collective: if any rank reported a problem, stop every rank with an ERROR
  // that gives the problem of the lowest such rank
  void raise(const std::string &file, int line);

 private:
  std::string problem;
};

}    // namespace LAMMPS_NS

#endif
