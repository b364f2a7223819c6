/* ----------------------------------------------------------------------
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
   ACOUSTIC package numerics, C++98 facade: the vibration modes of a
   gathered network (the calls of compute vibration/modes on rank 0).
------------------------------------------------------------------------- */

#include "acoustic_gathered_modes.h"

#include "acoustic_dynamical_matrix.h"
#include "acoustic_frequency_histogram.h"
#include "acoustic_gathered_network.h"
#include "acoustic_kpm_density.h"
#include "acoustic_solver_error.h"
#include "acoustic_vibration_modes.h"

#include <exception>
#include <new>

namespace Acoustic {

namespace {

  const char WHERE[] = "gathered modes: ";

  bool fail(GatheredModesResult &result, FacadeStatus::Value status, const char *message)
  {
    result = GatheredModesResult();
    result.status = status;
    try {
      result.message = message;
    } catch (...) {
      result.message.clear();
    }
    return false;
  }

  std::vector<double> values(const Eigen::VectorXd &v)
  {
    return std::vector<double>(v.data(), v.data() + v.size());
  }

  KpmOptions kpm_options(const GatheredModesInput &input)
  {
    KpmOptions kpm;
    if (input.kpm_moments < 0 || input.kpm_vectors < 0)
      throw SolverError(std::string(WHERE) + "kpm_moments and kpm_vectors must be >= 0 (0: the "
                        "default), got " + std::to_string(input.kpm_moments) + " and " +
                        std::to_string(input.kpm_vectors));
    if (input.kpm_moments > 0) kpm.moments = input.kpm_moments;
    if (input.kpm_vectors > 0) kpm.random_vectors = input.kpm_vectors;
    if (input.kpm_seed > 0) kpm.seed = input.kpm_seed;
    return kpm;
  }

}    // namespace

bool solve_gathered_modes(const GatheredModesInput &input, GatheredModesResult &result)
{
  result = GatheredModesResult();
  try {
    const std::string where = WHERE;
    Gathered::require_mpi(where);
    const ContactModel model = Gathered::contact_model(where, input.dimension, input.model);
    const ModeMethod method = mode_method_from_name(input.method);
    if (input.bins != 0) check_histogram_range(input.bins, input.fmin, input.fmax);
    if (method == ModeMethod::Kpm && input.bins == 0)
      throw SolverError(where + "method kpm computes the density of states only: give bins > 0 "
                        "with fmin, fmax");
    if (method == ModeMethod::Lanczos && input.nmodes <= 0)
      throw SolverError(where + "nmodes must be > 0, got " + std::to_string(input.nmodes));
    if (input.mode < 0) throw SolverError(where + "mode must be >= 0, got " +
                                          std::to_string(input.mode));
    if (input.mode > 0 && method == ModeMethod::Kpm)
      throw SolverError(where + "method kpm computes no individual mode: mode must be 0");
    if (input.mode > 0 && !input.with_shapes && method == ModeMethod::Dense)
      throw SolverError(where + "the shape of a mode needs with_shapes");
    const KpmOptions kpm = kpm_options(input);

    std::vector<bool> wall;
    const ContactNetwork network = Gathered::build_network(
        input.dimension, model, Gathered::network_grains(where, input.grains, wall),
        input.contacts);
    std::vector<char> taken;
    Gathered::check_grain_list(where, "fixed", input.fixed, network.num_grains(), taken);
    const int ndof = network.dofs_per_grain();

    // as ComputeVibrationModes::solve_on_rank0: the fixed grains, then the walls
    std::vector<int> fixed_dofs;
    for (int g : input.fixed)
      for (int k = 0; k < ndof; k++) fixed_dofs.push_back(network.dof(g, k));
    for (int g = 0; g < network.num_grains(); g++)
      if (wall[g] && !taken[g])
        for (int k = 0; k < ndof; k++) fixed_dofs.push_back(network.dof(g, k));
    const DynamicalMatrix dynamical(network.stiffness_matrix(), network.mass_diagonal(),
                                    fixed_dofs, ndof);
    if (dynamical.num_free() == 0)
      throw SolverError(where + "every grain is fixed or a wall: no degree of freedom is left");

    VibrationModes modes;
    FrequencyHistogram hist;
    switch (method) {
      case ModeMethod::Dense:
        modes = dense_vibration_modes(dynamical, input.with_shapes);
        break;
      case ModeMethod::Lanczos:
        modes = lanczos_vibration_modes(dynamical, input.nmodes);
        break;
      case ModeMethod::Kpm:
        hist = kpm_frequency_histogram(dynamical, input.bins, input.fmin, input.fmax, kpm);
        // KPM resolves no single eigenvalue: the zero modes are the DOFs
        // without any stiffness (rattlers)
        modes.zero_modes = static_cast<int>(dynamical.decoupled_free_dofs().size());
        break;
    }
    const int nfound = static_cast<int>(modes.frequencies.size());
    if (input.mode > nfound)
      throw SolverError(where + "mode " + std::to_string(input.mode) + " is out of range: method " +
                        mode_method_name(method) + " found " + std::to_string(nfound) +
                        " modes of the network (" + std::to_string(dynamical.num_free()) +
                        " free DOFs); choose mode between 1 and " + std::to_string(nfound));
    if (input.bins > 0 && method != ModeMethod::Kpm)
      hist = frequency_histogram(modes.frequencies, input.bins, input.fmin, input.fmax);

    result.dofs_per_grain = ndof;
    result.num_free = dynamical.num_free();
    result.zero_modes = modes.zero_modes;
    result.frequencies = values(modes.frequencies);
    result.participation = values(modes.participation_ratios);
    if (input.bins > 0) {
      result.bin_centres = values(hist.bin_centres);
      result.density = values(hist.density);
      result.density_error = values(hist.density_error);
    }
    if (input.mode > 0) {
      // the sign of a mode is arbitrary: its largest component positive
      Eigen::VectorXd shape = modes.shapes.col(input.mode - 1);
      Eigen::Index largest = 0;
      shape.cwiseAbs().maxCoeff(&largest);
      if (shape[largest] < 0.0) shape = -shape;
      result.shape = values(shape);
    }
    return true;
  } catch (SolverError &e) {
    return fail(result, FacadeStatus::InvalidInput, e.what());
  } catch (std::bad_alloc &) {
    return fail(result, FacadeStatus::InternalError,
                "gathered modes: out of memory (method dense holds n^2 numbers: use lanczos or "
                "kpm for large networks)");
  } catch (std::exception &e) {
    return fail(result, FacadeStatus::InternalError, e.what());
  } catch (...) {
    return fail(result, FacadeStatus::InternalError, "gathered modes: unknown exception");
  }
}

}    // namespace Acoustic
