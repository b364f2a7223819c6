/* ----------------------------------------------------------------------
    ACOUSTIC for LIGGGHTS-PUBLIC 3.8: compute vibration/modes.

    LIGGGHTS is open-source, distributed under the terms of the GNU Public
    License, version 2 or later.  This file is part of the ACOUSTIC
    package and distributed under the same terms.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   compute ID group vibration/modes stiffness hertz E nu [keyword value ...]

   The LAMMPS compute of the same name (doc/compute_vibration_modes.rst):
   the vibration modes K v = omega^2 M v of the contact network of pair
   style gran between the grains of the group, with the grains of a fixed
   group clamped.  The network is walked and gathered on rank 0 by
   AcousticLiggghtsNetwork (the walker fix acoustic/mindlin uses), solved
   there by the C++98 facade of the ACOUSTIC numerics
   (acoustic_gathered_modes.h: the calls of the LAMMPS compute), and the
   results broadcast.  Outputs as in LAMMPS: scalar (zero modes), vector
   (frequencies; in LIGGGHTS of a length fixed when the compute is defined),
   array (histogram), local array (mode, f, participation), per-atom array
   (the shape of one mode).  The walls of the network (fix wall/gran,
   primitive or mesh, nodes of infinite mass) are clamped.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS

ComputeStyle(vibration/modes,ComputeVibrationModes)

#else

#ifndef LMP_COMPUTE_VIBRATION_MODES_H
#define LMP_COMPUTE_VIBRATION_MODES_H

#include "compute.h"

#include "acoustic_gathered_modes.h"
#include "acoustic_liggghts_arguments.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class ComputeVibrationModes : public Compute {
 public:
  ComputeVibrationModes(class LAMMPS *, int &iarg, int, char **);
  ~ComputeVibrationModes();
  void init();
  double compute_scalar();
  void compute_vector();
  void compute_array();
  void compute_local();
  void compute_peratom();
  double memory_usage();

 private:
  std::string caller;
  AcousticNetworkSettings settings;
  Acoustic::GatheredModesInput options;    // method, nmodes, bins, kpm: the facade's input
  std::string fixed_group;                 // empty: none
  int fixed_groupbit;
  int selected_mode;                       // 1-based, 0: none
  int ndof;
  int nfree_defined;                       // free DOFs when defined (dense: the vector's length)
  class AcousticLiggghtsNetwork *network;

  // results of the last solve, valid on timestep solved_step
  bigint solved_step;
  bool solved_with_shapes;
  double nzero;
  std::vector<double> frequencies;     // every rank, size_vector entries (the global vector)
  std::vector<double> found;           // every rank: the frequencies of every mode found
  std::vector<double> participation;   // rank 0
  std::vector<double> shape;           // every rank when a mode is selected: grain by grain
  std::vector<double> tags;            // every rank when a mode is selected: ID of each grain

  double **histogram;
  double **mode_rows;
  int nmode_rows_max;
  double **shape_atom;
  int nmax;

  int free_dofs_now(bool check);
  void solve(bool need_shapes);
};

}

#endif
#endif
