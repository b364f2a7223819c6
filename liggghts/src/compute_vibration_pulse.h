/* ----------------------------------------------------------------------
    ACOUSTIC for LIGGGHTS-PUBLIC 3.8: compute vibration/pulse.

    LIGGGHTS is open-source, distributed under the terms of the GNU Public
    License, version 2 or later.  This file is part of the ACOUSTIC
    package and distributed under the same terms.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   compute ID group vibration/pulse source src detector det
           stiffness hertz E nu duration T [keyword value ...]

   The LAMMPS compute of the same name (doc/compute_vibration_pulse.rst):
   the response of the frozen contact network of pair style gran to a
   delta pulse of the source grains, the force the grains exert on the
   detector grains along the pulse's direction (paper 003's F_sig(t)).  The
   network is walked and gathered on rank 0 by AcousticLiggghtsNetwork (the
   walker fix acoustic/mindlin uses), solved there by the C++98 facade of
   the ACOUSTIC numerics (acoustic_gathered_pulse.h: the calls of the
   LAMMPS compute), and the results broadcast.  Outputs as in LAMMPS: a
   global array (samples rows: t, F_sig), a global vector (time step,
   steps, free DOFs) and, with snapshot, a per-atom array.  Source and
   detector are groups of grains or walls, as for fix acoustic/mindlin's
   source (wall fix-ID: a primitive wall's fix wall/gran; mesh fix-ID: a
   fix mesh/surface of a fix wall/gran ... mesh); every other wall is
   clamped.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS

ComputeStyle(vibration/pulse,ComputeVibrationPulse)

#else

#ifndef LMP_COMPUTE_VIBRATION_PULSE_H
#define LMP_COMPUTE_VIBRATION_PULSE_H

#include "compute.h"

#include "acoustic_gathered_pulse.h"
#include "acoustic_liggghts_arguments.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class ComputeVibrationPulse : public Compute {
 public:
  ComputeVibrationPulse(class LAMMPS *, int &iarg, int, char **);
  ~ComputeVibrationPulse();
  void init();
  void compute_vector();
  void compute_array();
  void compute_peratom();
  double memory_usage();

  // entries of the global vector
  enum { TIME_STEP, STEPS, FREE_DOFS, NVECTOR };

 private:
  std::string caller;
  AcousticNetworkSettings settings;
  Acoustic::GatheredPulseInput options;    // direction, initial, method, duration, samples, ...
  std::string group_names[3];              // source, detector, fixed ("" : none or a wall)
  int groupbits[3];
  std::string wall_ids[2];                 // source, detector: a wall's ID, or ""
  bool wall_is_mesh[2];                    // given as 'mesh ID' (else 'wall ID')
  int walls[2];                            // their index in the network's walls, or -1
  bool direction_given;                    // false: the default, normal to a source wall
  int ndof;
  class AcousticLiggghtsNetwork *network;

  bigint solved_step;
  double info[NVECTOR];
  double **signal;             // global array: samples x (time, F_sig)
  double **snapshot_atom;      // per-atom output: displacement at the snapshot time
  int nmax;
  std::vector<double> snapshot, tags;    // every rank with snapshot: grain by grain

  void parse_endpoint(class AcousticLiggghtsArguments &args, int which, const char *word);
  void check_groups();
  void solve();
};

}

#endif
#endif
