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
   vibration modes K v = omega^2 M v of a whole contact network gathered on
   one process, with some grains clamped.

   What compute vibration/modes of LAMMPS does on rank 0 with its gathered
   network: a ContactNetwork of the grains and contacts
   (acoustic_gathered_network.h: grains in the caller's order, contacts
   sorted by grain indices), a DynamicalMatrix of its K and M with every DOF
   of the fixed grains and of the walls clamped, and dense_vibration_modes,
   lanczos_vibration_modes or kpm_frequency_histogram
   (acoustic_vibration_modes.h, acoustic_kpm_density.h), then
   frequency_histogram: the same calls, so the same network gives the
   compute's numbers to the last bit.  For that, give the grains in the
   compute's order (by atom ID, the walls after every atom) and ask for the
   shapes when the compute does (its local or per-atom output is used, or
   keyword mode).

   The modes are those of the undamped network: the dashpots of the
   contacts are not read.  Walls are grains of infinite mass (HUGE_VAL of
   <cmath>): every DOF of a wall is clamped.  Frequencies f = omega / (2 pi)
   in the inverse time unit of the masses and stiffnesses.

   Never throws; MPI must be initialised (the sparse factorisation of
   method lanczos runs on the calling process).
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_GATHERED_MODES_H
#define ACOUSTIC_GATHERED_MODES_H

#include "acoustic_facade.h"
#include "acoustic_gathered_drive.h"

#include <string>
#include <vector>

namespace Acoustic {

struct GatheredModesInput {
  int dimension;                      // 2 or 3
  FacadeContactModel::Value model;    // normal or full
  std::vector<GatheredGrain> grains;
  std::vector<GatheredContact> contacts;    // cn, ct not read
  std::vector<int> fixed;                   // grains clamped (every DOF), each once
  std::string method;    // "dense" (default), "lanczos" or "kpm" (histogram only)
  int nmodes;            // method lanczos: the lowest nmodes non-zero modes (10)
  int bins;              // > 0: a histogram of bins bins over [fmin, fmax]; 0: none
  double fmin, fmax;
  // method kpm: 0 for the library's defaults (KpmOptions: 256 moments, 32
  // vectors, seed 2021)
  int kpm_moments, kpm_vectors;
  unsigned long kpm_seed;
  bool with_shapes;    // participation ratios (and the shape of `mode`); lanczos: always
  int mode;            // > 0: the shape of this mode (1-based, ascending f); needs with_shapes

  GatheredModesInput() :
      dimension(3), model(FacadeContactModel::Normal), method("dense"), nmodes(10), bins(0),
      fmin(0.0), fmax(0.0), kpm_moments(0), kpm_vectors(0), kpm_seed(0), with_shapes(false),
      mode(0)
  {
  }
};

struct GatheredModesResult {
  FacadeStatus::Value status;
  std::string message;    // why, when status is not Success
  int dofs_per_grain;
  int num_free;           // DOFs not clamped
  int zero_modes;         // zero modes of the free DOFs (kpm: the DOFs without stiffness)
  std::vector<double> frequencies;      // ascending, zero modes first (dense); empty with kpm
  std::vector<double> participation;    // one per mode with shapes, else empty
  std::vector<double> bin_centres, density, density_error;    // bins entries each, or empty
  // the shape of `mode`: dofs_per_grain grains.size() numbers, grain by grain
  // (translations first), mass-normalised, 0 on clamped DOFs, its largest
  // component positive (as compute vibration/modes makes it); else empty
  std::vector<double> shape;
  bool ok() const { return status == FacadeStatus::Success; }

  GatheredModesResult() :
      status(FacadeStatus::Success), dofs_per_grain(0), num_free(0), zero_modes(0)
  {
  }
};

// The modes into result; false otherwise, with a status and a message:
// InvalidInput for bad input, a mode out of range, no free DOF, and what the
// library reports by SolverError (K not positive semi-definite, too many
// DOFs for dense, Lanczos not converged); InternalError for no memory.
// Never throws.
ACOUSTIC_FACADE_API bool solve_gathered_modes(const GatheredModesInput &input,
                                              GatheredModesResult &result);

}    // namespace Acoustic

#endif
