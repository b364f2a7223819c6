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
   ACOUSTIC package numerics, C++98 facade: the pulse response of a
   gathered network (the calls of compute vibration/pulse on rank 0).
------------------------------------------------------------------------- */

#include "acoustic_gathered_pulse.h"

#include "acoustic_gathered_network.h"
#include "acoustic_mindlin_law.h"
#include "acoustic_pulse_response.h"
#include "acoustic_solver_error.h"

#include <cmath>
#include <exception>
#include <new>

namespace Acoustic {

namespace {

  const char WHERE[] = "gathered pulse: ";
  // method auto: integrate above this many free DOFs (compute vibration/pulse's AUTO_INTEGRATE_DOFS)
  const long AUTO_INTEGRATE_DOFS = 10000;

  bool fail(GatheredPulseResult &result, FacadeStatus::Value status, const char *message)
  {
    result = GatheredPulseResult();
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

  // the contacts with the dashpots of damping_ratio, as VibrationNetwork::network_contact
  std::vector<GatheredContact> damped_contacts(const GatheredPulseInput &input)
  {
    const std::string where = WHERE;
    if (!(std::isfinite(input.damping_ratio) && input.damping_ratio >= 0.0))
      throw SolverError(where + "damping_ratio must be >= 0 and finite, got " +
                        Gathered::number(input.damping_ratio));
    std::vector<GatheredContact> contacts = input.contacts;
    if (input.damping_ratio == 0.0) return contacts;
    const int ngrains = static_cast<int>(input.grains.size());
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      GatheredContact &c = contacts[k];
      if (c.cn != 0.0 || c.ct != 0.0)
        throw SolverError(where + "contact " + std::to_string(k) +
                          " has dashpots cn, ct: give them or damping_ratio, not both");
      if (c.i < 0 || c.i >= ngrains || c.j < 0 || c.j >= ngrains) continue;    // the network says
      if (!(c.kn > 0.0)) continue;
      c.cn = dashpot_coefficient(input.damping_ratio, c.kn, input.grains[c.i].mass,
                                 input.grains[c.j].mass);
      c.ct = dashpot_coefficient(input.damping_ratio, c.kt, input.grains[c.i].mass,
                                 input.grains[c.j].mass);
    }
    return contacts;
  }

  PulseOptions pulse_options(const GatheredPulseInput &input)
  {
    PulseOptions o;
    o.initial = pulse_initial_from_name(input.initial);
    if (input.method != "auto") o.method = pulse_method_from_name(input.method);
    o.duration = input.duration;
    o.samples = input.samples;
    o.time_step = input.time_step;
    o.snapshot_time = input.snapshot_time;
    o.max_steps = input.max_steps;
    if (input.progress) {
      void (*report)(long, long, void *) = input.progress;
      void *data = input.progress_data;
      o.progress = [report, data](long done, long total) { report(done, total, data); };
    }
    return o;
  }

}    // namespace

bool solve_gathered_pulse(const GatheredPulseInput &input, GatheredPulseResult &result)
{
  result = GatheredPulseResult();
  try {
    const std::string where = WHERE;
    Gathered::require_mpi(where);
    const ContactModel model = Gathered::contact_model(where, input.dimension, input.model);
    if (input.method != "auto" && input.method != "modes" && input.method != "integrate")
      throw SolverError(where + "unknown method '" + input.method +
                        "': allowed are auto, modes, integrate");
    PulseOptions options = pulse_options(input);
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(input.direction[k]))
        throw SolverError(where + "the direction must be finite");

    std::vector<bool> wall;
    const ContactNetwork network = Gathered::build_network(
        input.dimension, model, Gathered::network_grains(where, input.grains, wall),
        damped_contacts(input));
    const int ndof = network.dofs_per_grain();
    std::vector<char> taken;
    Gathered::check_grain_list(where, "source", input.source, network.num_grains(), taken);
    Gathered::check_grain_list(where, "detector", input.detector, network.num_grains(), taken);
    Gathered::check_grain_list(where, "fixed", input.fixed, network.num_grains(), taken);
    if (input.source.empty()) throw SolverError(where + "the source has no grain");
    if (input.detector.empty()) throw SolverError(where + "the detector has no grain");

    // as ComputeVibrationPulse::pulse_problem
    PulseProblem p;
    p.stiffness = network.stiffness_matrix();
    if (network.has_damping()) p.damping = network.damping_matrix();
    p.mass = network.mass_diagonal();
    p.dofs_per_grain = ndof;
    p.dimension = input.dimension;
    p.direction = Eigen::Vector3d(input.direction[0], input.direction[1], input.direction[2]);
    p.source = Eigen::VectorXd::Zero(network.num_dofs());
    p.detector = Eigen::VectorXd::Zero(network.num_dofs());
    auto prescribe = [&](int g, Eigen::VectorXd *pattern) {
      for (int k = 0; k < ndof; k++) {
        p.prescribed_dofs.push_back(network.dof(g, k));
        if (pattern && k < p.dimension) (*pattern)[network.dof(g, k)] = input.direction[k];
      }
    };
    for (int g : input.source) prescribe(g, &p.source);
    for (int g : input.detector) prescribe(g, &p.detector);
    for (int g : input.fixed) prescribe(g, nullptr);
    for (int g = 0; g < network.num_grains(); ++g)
      if (wall[g] && !taken[g]) prescribe(g, nullptr);

    if (input.method == "auto") {
      const long free = p.mass.size() - static_cast<long>(p.prescribed_dofs.size());
      options.method = (network.has_damping() || free > AUTO_INTEGRATE_DOFS)
          ? PulseMethod::Integrate
          : PulseMethod::Modes;
    }
    const PulseResponse r = pulse_response(p, options);

    result.dofs_per_grain = ndof;
    result.method = (options.method == PulseMethod::Modes) ? "modes" : "integrate";
    result.times = values(r.times);
    result.signal = values(r.signal);
    result.snapshot = values(r.snapshot);
    result.snapshot_time = r.snapshot_time;
    result.time_step = r.time_step;
    result.steps = r.steps;
    result.num_free = r.num_free;
    return true;
  } catch (SolverError &e) {
    return fail(result, FacadeStatus::InvalidInput, e.what());
  } catch (std::bad_alloc &) {
    return fail(result, FacadeStatus::InternalError,
                "gathered pulse: out of memory (method modes holds n^2 numbers: use method "
                "integrate for large networks)");
  } catch (std::exception &e) {
    return fail(result, FacadeStatus::InternalError, e.what());
  } catch (...) {
    return fail(result, FacadeStatus::InternalError, "gathered pulse: unknown exception");
  }
}

}    // namespace Acoustic
