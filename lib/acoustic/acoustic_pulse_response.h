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
   ACOUSTIC package numerics: response of the frozen network to a delta
   pulse of its source (paper 003, Eqs. 1-4).

   On the free DOFs F, with every prescribed DOF (source, detector, clamped)
   held at zero after t = 0:
     M u'' = -K_FF u - C_FF u'.
   The source's unit displacement pattern s (the direction on its
   translations) defines the impulse of a unit delta pulse of the source,
     b = -K_FP s_P,
   and the two initial conditions of paper 003:
     velocity      (A)  u(0) = 0, u'(0) = M^-1 b;
     displacement  (B)  u'(0) = 0, the translations of every grain touching
                        the source (b not zero on its DOFs) displaced by the
                        direction, its rotations not.
   The signal is the force of the grains on the detector DOFs D along the
   detector's pattern t_D (the direction on its translations):
     F_sig(t) = g^T u(t),  g = -K_FD t_D,
   zero at t = 0 in case A: the change of the static force.

   Methods:
     modes      modal superposition on the dense eigenmodes v_n (v^T M v = 1):
                u(t) = sum_n v_n (a_n cos w_n t + c_n sin(w_n t) / w_n),
                a_n = v_n^T M u(0), c_n = v_n^T M u'(0) (zero modes: a_n + c_n t).
                Exact; undamped networks of up to about 10 000 free DOFs.
     integrate  velocity Verlet with the sparse K (symplectic, second order,
                cost ~ contacts x steps); dashpots enter to first order in
                the step.  Default step 0.03 / w_max with w_max^2 bounded by
                Gershgorin's bound of M^-1/2 K M^-1/2, made a divisor of the
                sampling interval.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_PULSE_RESPONSE_H
#define ACOUSTIC_PULSE_RESPONSE_H

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <functional>
#include <string>
#include <vector>

namespace Acoustic {

enum class PulseInitial { Velocity, Displacement };
enum class PulseMethod { Modes, Integrate };

// "velocity" or "displacement"; "modes" or "integrate"; SolverError otherwise
PulseInitial pulse_initial_from_name(const std::string &name);
PulseMethod pulse_method_from_name(const std::string &name);

struct PulseProblem {
  Eigen::SparseMatrix<double> stiffness;    // K, num_dofs x num_dofs
  Eigen::SparseMatrix<double> damping;      // C, same size, or 0 x 0
  Eigen::VectorXd mass;                     // diagonal of M, positive
  std::vector<int> prescribed_dofs;         // held at zero after t = 0
  Eigen::VectorXd source;      // s: unit displacement of the source, on prescribed DOFs
  Eigen::VectorXd detector;    // t_D: force pattern of the detector, on prescribed DOFs
  int dofs_per_grain = 0;      // DOFs stored grain by grain, translations first
  int dimension = 0;           // 2 or 3: the translations of a grain
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();    // of the pulse (initial condition B)
};

struct PulseOptions {
  PulseInitial initial = PulseInitial::Velocity;
  PulseMethod method = PulseMethod::Modes;
  double duration = 0.0;          // T > 0
  int samples = 500;              // >= 2 samples at t = k T / (samples - 1)
  double time_step = 0.0;         // integrate: 0 = automatic
  double snapshot_time = -1.0;    // >= 0: also the displacement at this time
  long max_steps = 100000000;     // integrate: more steps than this is an error
  // integrate, when it takes more than a million steps: called about every
  // tenth of them with the steps done and the total (a progress report)
  std::function<void(long, long)> progress;
};

struct PulseResponse {
  Eigen::VectorXd times;          // the sample times
  Eigen::VectorXd signal;         // F_sig at the sample times
  Eigen::VectorXd snapshot;       // u at the snapshot time (DOF space, 0 on prescribed DOFs)
  double snapshot_time = -1.0;    // the time of the snapshot (integrate: the nearest step)
  double time_step = 0.0;         // integrate: the step used
  long steps = 0;                 // integrate: steps taken
  int num_free = 0;
};

// Throws SolverError on invalid input (sizes, a source that touches no free
// DOF, method modes with damping, more than 20 000 free DOFs for modes, a
// time step of method integrate that is not below the stability bound, more
// integration steps than max_steps) and when the signal is not finite.
PulseResponse pulse_response(const PulseProblem &problem, const PulseOptions &options);

}    // namespace Acoustic

#endif
