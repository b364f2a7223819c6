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
   ACOUSTIC package numerics, C++98 facade (acoustic_facade.h): the
   response of a whole contact network gathered on one process to a delta
   pulse of its source: the force on the detector along the pulse's
   direction, F_sig(t) of paper 003 (acoustic_pulse_response.h).

   What compute vibration/pulse of LAMMPS does on rank 0 with its gathered
   network: a ContactNetwork of the grains and contacts
   (acoustic_gathered_network.h), a PulseProblem of its K, C (when a dashpot
   is not 0), M, with every DOF of the source, detector and fixed grains
   and of the walls prescribed, the source's and detector's patterns the
   direction on their translations, and pulse_response: the same calls, so
   the same network gives the compute's numbers to the last bit.

   Walls are grains of infinite mass (HUGE_VAL of <cmath>): clamped, or the
   source or the detector when listed there.  Dashpots: the contacts' cn and
   ct, or, with damping_ratio > 0, those of compute vibration/pulse's
   keyword damping, 2 zeta sqrt(k m_i m_j / (m_i + m_j)) for k_n and k_t of
   each contact with k_n > 0 (a wall's mass infinite).

   Never throws; MPI must be initialised.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_GATHERED_PULSE_H
#define ACOUSTIC_GATHERED_PULSE_H

#include "acoustic_facade.h"
#include "acoustic_gathered_drive.h"

#include <string>
#include <vector>

namespace Acoustic {

struct GatheredPulseInput {
  int dimension;                      // 2 or 3
  FacadeContactModel::Value model;    // normal or full
  std::vector<GatheredGrain> grains;
  std::vector<GatheredContact> contacts;
  double damping_ratio;    // > 0: the dashpots from it (every contact's cn, ct must be 0)
  // grain indices; a grain is in one list at most; the walls not listed are clamped
  std::vector<int> source, detector, fixed;
  double direction[3];    // of the pulse, as given (the compute makes it a unit vector)
  std::string initial;    // "velocity" (default) or "displacement"
  // "auto" (default: integrate when damped or above 10 000 free DOFs, as
  // the compute), "modes" or "integrate"
  std::string method;
  double duration;         // T > 0
  int samples;             // >= 2 samples at t = k T / (samples - 1): 500
  double time_step;        // integrate: 0 = automatic
  double snapshot_time;    // >= 0: also the displacements at this time; < 0: none
  long max_steps;          // integrate: more steps than this is an error: 100 000 000
  // integrate, beyond a million steps: called about every tenth of them with
  // the steps done, the total and progress_data (NULL: no report)
  void (*progress)(long done, long total, void *data);
  void *progress_data;

  GatheredPulseInput() :
      dimension(3), model(FacadeContactModel::Normal), damping_ratio(0.0), initial("velocity"),
      method("auto"), duration(0.0), samples(500), time_step(0.0), snapshot_time(-1.0),
      max_steps(100000000L), progress(0), progress_data(0)
  {
    direction[0] = direction[1] = 0.0;
    direction[2] = 1.0;
  }
};

struct GatheredPulseResult {
  FacadeStatus::Value status;
  std::string message;    // why, when status is not Success
  int dofs_per_grain;
  std::string method;               // "modes" or "integrate": the method used
  std::vector<double> times;        // the sample times
  std::vector<double> signal;       // F_sig at the sample times
  // the displacements at snapshot_time, grain by grain (0 on prescribed DOFs); else empty
  std::vector<double> snapshot;
  double snapshot_time;    // the time of the snapshot (integrate: the nearest step)
  double time_step;        // integrate: the step used
  long steps;              // integrate: steps taken
  int num_free;            // DOFs not prescribed
  bool ok() const { return status == FacadeStatus::Success; }

  GatheredPulseResult() :
      status(FacadeStatus::Success), dofs_per_grain(0), snapshot_time(-1.0), time_step(0.0),
      steps(0), num_free(0)
  {
  }
};

// The signal into result; false (status InvalidInput for bad input, a source
// touching no free DOF, too many steps or a signal that is not finite;
// InternalError for no memory; and a message) otherwise.  Never throws.
ACOUSTIC_FACADE_API bool solve_gathered_pulse(const GatheredPulseInput &input,
                                              GatheredPulseResult &result);

}    // namespace Acoustic

#endif
