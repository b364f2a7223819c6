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
   ACOUSTIC package numerics: exception type.

   Every function of namespace Acoustic reports invalid input and
   unrecoverable numerical trouble by throwing Acoustic::SolverError.  The
   message says what went wrong and how to fix it, so that an adapter (the
   LAMMPS styles) can print it unchanged in an ERROR or WARNING line.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_SOLVER_ERROR_H
#define ACOUSTIC_SOLVER_ERROR_H

#include <stdexcept>
#include <string>

namespace Acoustic {

class SolverError : public std::runtime_error {
 public:
  explicit SolverError(const std::string &message) : std::runtime_error(message) {}
};

// Thrown by a collective function on the ranks that found nothing wrong
// when another rank threw SolverError: the message is on that rank.
class SolverErrorElsewhere : public SolverError {
 public:
  SolverErrorElsewhere() : SolverError("invalid input on another rank") {}
};

}    // namespace Acoustic

#endif
