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

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(vibration/pulse,ComputeVibrationPulse);
// clang-format on
#else

#ifndef LMP_COMPUTE_VIBRATION_PULSE_H
#define LMP_COMPUTE_VIBRATION_PULSE_H

#include "compute.h"

#include "acoustic_pulse_response.h"
#include "vibration_network.h"

#include <memory>
#include <string>

namespace LAMMPS_NS {

class ComputeVibrationPulse : public Compute {
 public:
  ComputeVibrationPulse(class LAMMPS *, int, char **);
  ~ComputeVibrationPulse() override;
  void init() override;
  void compute_vector() override;
  void compute_array() override;
  void compute_peratom() override;
  double memory_usage() override;

  // entries of the global vector
  enum { TIME_STEP, STEPS, FREE_DOFS, NVECTOR };

 private:
  // the source or the detector: a group of atoms, or a plane of fix wall/gran
  struct Endpoint {
    std::string group, wall_fix;
    int groupbit = 0;
    int wall = -1;    // index of the wall plane in the network
  };
  Endpoint source, detector;
  std::string fixed_group;
  int fixed_groupbit;
  VibrationNetworkSettings settings;
  double direction[3];
  bool direction_given;    // false: the default, normal to a source wall
  Acoustic::PulseOptions options;
  bool method_given;
  std::unique_ptr<VibrationNetwork> network;
  int ndof;

  bigint solved_step;
  double info[NVECTOR];
  double **signal;           // global array: samples x (time, F_sig)
  double **snapshot_atom;    // per-atom output: displacement at the snapshot time
  int nmax;
  Eigen::VectorXd snapshot;    // rank 0

  void parse_endpoint(class CommandArguments &, const char *word, Endpoint &end);
  void init_endpoint(Endpoint &end, const char *word);
  void solve();
  std::string solve_on_rank0();
  Acoustic::PulseProblem pulse_problem() const;
};

}    // namespace LAMMPS_NS

#endif
#endif
