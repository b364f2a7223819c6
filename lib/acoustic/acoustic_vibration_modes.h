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
   ACOUSTIC package numerics: eigenmodes K v = omega^2 M v of a network.

   Both methods work on the mass-weighted matrix D of a DynamicalMatrix
   (free DOFs only) and return f = omega / (2 pi), omega = sqrt(max(lambda, 0)).

   Zero modes: lambda with |lambda| <= zero_tolerance * B, where B is the
   Gershgorin upper bound of the spectrum of D
   (DynamicalMatrix::spectrum_upper_bound()).  Rattlers, floating clusters
   and mechanisms give zero modes; a rattler contributes dofs_per_grain.

     dense    every mode, zero modes included (they come first), from a dense
              symmetric eigensolver; memory O(n^2), time O(n^3): for up to
              about 10 000 free DOFs.
     lanczos  the num_modes lowest non-zero modes, by shift-invert Lanczos
              (Spectra) around a small negative shift -1e-6 B, with a sparse
              Cholesky factorisation of D + 1e-6 B I.  DOFs with no stiffness
              at all (rattlers) are exact zero modes and are counted and
              removed first; the remaining zero modes (mechanisms, floating
              clusters) are found by asking for more modes until a non-zero
              one appears.  Highly degenerate zero modes of coupled DOFs may be
              undercounted by Lanczos; dense counts them exactly.
     kpm      density of states only, see acoustic_kpm_density.h.

   Mode shapes are DOF-space vectors, mass-normalised (v^T M v = 1), zero on
   fixed DOFs; participation ratios as in DynamicalMatrix.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_VIBRATION_MODES_H
#define ACOUSTIC_VIBRATION_MODES_H

#include "acoustic_dynamical_matrix.h"

#include <Eigen/Core>

#include <string>

namespace Acoustic {

enum class ModeMethod { Dense, Lanczos, Kpm };

// whether the package was built with Spectra (method lanczos)
bool lanczos_available();

// "dense", "lanczos" or "kpm"; throws SolverError listing the allowed names otherwise.
ModeMethod mode_method_from_name(const std::string &name);
std::string mode_method_name(ModeMethod method);

const double default_zero_mode_tolerance = 1e-8;

struct VibrationModes {
  Eigen::VectorXd eigenvalues;    // lambda = omega^2, ascending
  Eigen::VectorXd frequencies;    // f = sqrt(max(lambda, 0)) / (2 pi), same order
  Eigen::MatrixXd shapes;         // one mass-normalised DOF-space column per mode (if requested)
  Eigen::VectorXd participation_ratios;    // one per mode (if shapes were requested)
  int zero_modes = 0;                      // number of zero modes of the free DOFs
};

// All modes.  Throws SolverError if D is not positive semi-definite (within
// the zero tolerance) or has more than 20 000 free DOFs.
VibrationModes dense_vibration_modes(const DynamicalMatrix &dynamical, bool with_shapes = true,
                                     double zero_tolerance = default_zero_mode_tolerance);

// The num_modes lowest non-zero modes (fewer if the network has fewer), with
// shapes and participation ratios.  Throws SolverError if D is not positive
// semi-definite or Lanczos does not converge.
VibrationModes lanczos_vibration_modes(const DynamicalMatrix &dynamical, int num_modes,
                                       double zero_tolerance = default_zero_mode_tolerance);

}    // namespace Acoustic

#endif
