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
   ACOUSTIC package numerics: the halo of a network distributed over MPI
   ranks.

   In a domain decomposition each rank holds the contacts it counts and
   the grains they touch: the grains it owns, then copies of grains owned
   by other ranks (ghosts; a periodic image of an own grain is a ghost
   too), then prescribed nodes nobody owns (walls).  Per-grain values are
   stored grain by grain, `width` complex numbers per grain.  A halo
   exchange moves them between the owners and their ghosts:
     forward: every ghost receives the values of the grain it copies;
     reverse: every ghost's values are added to those of its owner (the
              ghosts' own values are left as they are).
   The prescribed nodes after the ghosts are not touched.  Both calls are
   collective over the ranks of the decomposition.

   The LAMMPS styles implement it with LAMMPS's own forward and reverse
   communication; the unit tests with MPI point-to-point messages.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_HALO_EXCHANGE_H
#define ACOUSTIC_HALO_EXCHANGE_H

#include <complex>

namespace Acoustic {

class HaloExchange {
 public:
  virtual ~HaloExchange() = default;
  virtual void forward(std::complex<double> *values, int width) = 0;
  virtual void reverse(std::complex<double> *values, int width) = 0;
};

}    // namespace Acoustic

#endif
