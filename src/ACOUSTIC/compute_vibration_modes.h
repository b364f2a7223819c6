/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   Steve Plimpton, sjplimp@sandia.gov

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(vibration/modes,ComputeVibrationModes);
// clang-format on
#else

#ifndef LMP_COMPUTE_VIBRATION_MODES_H
#define LMP_COMPUTE_VIBRATION_MODES_H

#include "compute.h"

#include "acoustic_kpm_density.h"
#include "acoustic_vibration_modes.h"
#include "vibration_network.h"

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class ComputeVibrationModes : public Compute {
 public:
  ComputeVibrationModes(class LAMMPS *, int, char **);
  ~ComputeVibrationModes() override;
  void init() override;
  double compute_scalar() override;
  void compute_vector() override;
  void compute_array() override;
  void compute_peratom() override;
  void compute_local() override;
  int lock_length() override;
  double memory_usage() override;

 private:
  VibrationNetworkSettings settings;
  Acoustic::ModeMethod method;
  std::string fixed_group;    // empty: no fixed atoms
  int fixed_groupbit;
  int nmodes;    // method lanczos
  int nbins;     // 0: no histogram
  double fmin, fmax;
  int selected_mode;    // 1-based index of the mode shape output, 0: none
  Acoustic::KpmOptions kpm;
  std::unique_ptr<VibrationNetwork> network;
  int ndof;    // DOFs per grain

  // results of the last solve, valid on timestep solved_step
  bigint solved_step;
  bool solved_with_shapes;
  double nzero;                         // number of zero modes
  std::vector<double> frequencies;      // every rank
  std::vector<double> participation;    // rank 0
  Eigen::VectorXd selected_shape;       // rank 0: DOF-space shape of selected_mode

  double **histogram;    // global array, nbins x 3
  double **mode_rows;    // local array, rank 0: (index, f, PR) per mode
  int nmode_rows_max;
  double **shape_atom;    // per-atom output
  int nmax;

  void solve(bool need_shapes);
  std::string solve_on_rank0(bool with_shapes);
};

}    // namespace LAMMPS_NS

#endif
#endif
