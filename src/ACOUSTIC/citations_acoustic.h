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
   The papers the ACOUSTIC styles implement, as LAMMPS's citeme prints
   them (log.cite, and the screen summary) when a run uses the styles.
   Defined once, in citations_acoustic.cpp.
------------------------------------------------------------------------- */

#ifndef LMP_CITATIONS_ACOUSTIC_H
#define LMP_CITATIONS_ACOUSTIC_H

namespace LAMMPS_NS {
namespace AcousticCitations {

  // the two-time-scale model: the friction factor of each contact from the
  // steady basal drive of its network (fix acoustic/mindlin, the tangential
  // sub-models, the network's modes)
  extern const char two_time_scale_model[];
  // the linearised Hertz-Mindlin network, its modes and its pulse response
  // (compute vibration/modes, compute vibration/pulse)
  extern const char confined_wave_propagation[];
  // grain-wall contacts of a sheared granular flow (the tangential sub-models
  // on the walls of fix wall/gran and wall/gran/region)
  extern const char wall_force_fluctuations[];

}    // namespace AcousticCitations
}    // namespace LAMMPS_NS

#endif
