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
   ACOUSTIC package numerics: response of the frozen network to a delta
   pulse of its source.
------------------------------------------------------------------------- */

#include "acoustic_pulse_response.h"

#include "acoustic_dynamical_matrix.h"
#include "acoustic_solver_error.h"
#include "acoustic_vibration_modes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace Acoustic {

namespace {

  // a number in messages: %g
  std::string number(double value)
  {
    char text[32];
    std::snprintf(text, sizeof(text), "%g", value);
    return text;
  }

  // the automatic step of method integrate: STEP_FRACTION / w_bound (error of the
  // chain's coherent peak below 1e-3 of it over 40 periods of its lowest mode)
  constexpr double STEP_FRACTION = 0.03;
  constexpr int MAX_MODES_DOFS = 20000;    // as dense_vibration_modes

  // the free DOFs (not prescribed), ascending
  std::vector<int> free_dofs(int num_dofs, const std::vector<int> &prescribed)
  {
    std::vector<char> is_prescribed(num_dofs, 0);
    for (int d : prescribed) {
      if (d < 0 || d >= num_dofs)
        throw SolverError("pulse response: prescribed DOF " + std::to_string(d) +
                          " is outside 0.." + std::to_string(num_dofs - 1));
      is_prescribed[d] = 1;
    }
    std::vector<int> result;
    for (int d = 0; d < num_dofs; d++)
      if (!is_prescribed[d]) result.push_back(d);
    return result;
  }

  Eigen::VectorXd restrict_to(const Eigen::VectorXd &v, const std::vector<int> &dofs)
  {
    Eigen::VectorXd result(dofs.size());
    for (std::size_t k = 0; k < dofs.size(); k++) result[k] = v[dofs[k]];
    return result;
  }

  // the free-free block of a sparse matrix
  Eigen::SparseMatrix<double> free_block(const Eigen::SparseMatrix<double> &a,
                                         const std::vector<int> &free)
  {
    std::vector<int> position(a.rows(), -1);
    for (std::size_t k = 0; k < free.size(); k++) position[free[k]] = static_cast<int>(k);
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(a.nonZeros());
    for (int col = 0; col < a.outerSize(); ++col)
      for (Eigen::SparseMatrix<double>::InnerIterator it(a, col); it; ++it)
        if (position[it.row()] >= 0 && position[it.col()] >= 0)
          entries.emplace_back(position[it.row()], position[it.col()], it.value());
    const int n = static_cast<int>(free.size());
    Eigen::SparseMatrix<double> block(n, n);
    block.setFromTriplets(entries.begin(), entries.end());
    return block;
  }

  void check(const PulseProblem &p, const PulseOptions &o)
  {
    const Eigen::Index n = p.stiffness.rows();
    if (p.stiffness.cols() != n)
      throw SolverError("pulse response: the stiffness matrix is not square");
    if (p.damping.size() != 0 && (p.damping.rows() != n || p.damping.cols() != n))
      throw SolverError("pulse response: the damping matrix must be empty or have the size of K");
    if (p.mass.size() != n || !(p.mass.array() > 0.0).all() || !p.mass.allFinite())
      throw SolverError("pulse response: need one positive, finite mass per DOF");
    if (p.source.size() != n || p.detector.size() != n)
      throw SolverError("pulse response: the source and detector patterns need one value per DOF");
    if (p.dofs_per_grain < 1 || n % p.dofs_per_grain != 0 || (p.dimension != 2 && p.dimension != 3))
      throw SolverError(
          "pulse response: DOFs must be stored grain by grain, 2 or 3 translations first");
    if (!(std::isfinite(o.duration) && o.duration > 0.0))
      throw SolverError("pulse response: the duration must be positive and finite");
    if (o.samples < 2) throw SolverError("pulse response: need at least 2 samples");
    if (!(std::isfinite(o.time_step) && o.time_step >= 0.0))
      throw SolverError("pulse response: the time step must be >= 0 (0: automatic)");
  }

  bool has_damping(const Eigen::SparseMatrix<double> &c)
  {
    for (Eigen::Index k = 0; k < c.nonZeros(); ++k)
      if (c.valuePtr()[k] != 0.0) return true;
    return false;
  }

  // upper bound of w_max^2: Gershgorin's bound of M^-1/2 K_FF M^-1/2
  double omega_squared_bound(const Eigen::SparseMatrix<double> &kff,
                             const Eigen::VectorXd &mass_free)
  {
    Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(kff.rows());
    for (int col = 0; col < kff.outerSize(); ++col)
      for (Eigen::SparseMatrix<double>::InnerIterator it(kff, col); it; ++it)
        row_sums[it.row()] +=
            std::abs(it.value()) / std::sqrt(mass_free[it.row()] * mass_free[it.col()]);
    return row_sums.size() ? row_sums.maxCoeff() : 0.0;
  }

  struct InitialState {
    Eigen::VectorXd displacement, velocity;    // on the free DOFs
  };

  InitialState initial_state(const PulseProblem &p, PulseInitial initial,
                             const std::vector<int> &free)
  {
    const Eigen::VectorXd impulse = restrict_to(-(p.stiffness * p.source), free);
    if (impulse.cwiseAbs().maxCoeff() == 0.0)
      throw SolverError(
          "pulse response: the source touches no free grain (no contact couples it to "
          "the network)");
    InitialState state;
    state.displacement = Eigen::VectorXd::Zero(free.size());
    state.velocity = Eigen::VectorXd::Zero(free.size());
    if (initial == PulseInitial::Velocity) {
      state.velocity = impulse.cwiseQuotient(restrict_to(p.mass, free));
      return state;
    }
    // B: every grain with a free DOF that the impulse reaches moves by the direction
    std::vector<int> position(p.stiffness.rows(), -1);
    for (std::size_t k = 0; k < free.size(); k++) position[free[k]] = static_cast<int>(k);
    const int ngrains = static_cast<int>(p.stiffness.rows()) / p.dofs_per_grain;
    for (int g = 0; g < ngrains; g++) {
      bool touched = false;
      for (int d = 0; d < p.dofs_per_grain; d++) {
        const int k = position[g * p.dofs_per_grain + d];
        if (k >= 0 && impulse[k] != 0.0) touched = true;
      }
      if (!touched) continue;
      for (int d = 0; d < p.dimension; d++) {
        const int k = position[g * p.dofs_per_grain + d];
        if (k >= 0) state.displacement[k] = p.direction[d];
      }
    }
    return state;
  }

  PulseResponse by_modes(const PulseProblem &p, const PulseOptions &o, const std::vector<int> &free,
                         const InitialState &start, const Eigen::VectorXd &coupling)
  {
    if (static_cast<int>(free.size()) > MAX_MODES_DOFS)
      throw SolverError("pulse response: method modes is limited to " +
                        std::to_string(MAX_MODES_DOFS) +
                        " free DOFs (dense eigenmodes); use method integrate");
    const DynamicalMatrix dynamical(p.stiffness, p.mass, p.prescribed_dofs, p.dofs_per_grain);
    const VibrationModes modes = dense_vibration_modes(dynamical, true);
    const Eigen::Index nmodes = modes.eigenvalues.size();

    // projections on the mass-normalised modes, in DOF space restricted to the free DOFs
    Eigen::MatrixXd shapes(free.size(), nmodes);
    for (Eigen::Index n = 0; n < nmodes; ++n)
      shapes.col(n) = restrict_to(modes.shapes.col(n), free);
    const Eigen::VectorXd mass_free = restrict_to(p.mass, free);
    const Eigen::VectorXd a = shapes.transpose() * mass_free.cwiseProduct(start.displacement);
    const Eigen::VectorXd c = shapes.transpose() * mass_free.cwiseProduct(start.velocity);
    const Eigen::VectorXd h = shapes.transpose() * coupling;
    Eigen::VectorXd omega(nmodes);
    for (Eigen::Index n = 0; n < nmodes; ++n)
      omega[n] = (n < modes.zero_modes) ? 0.0 : std::sqrt(std::max(modes.eigenvalues[n], 0.0));

    // modal coordinate n at time t
    auto coordinates = [&](double t) {
      Eigen::VectorXd x(nmodes);
      for (Eigen::Index n = 0; n < nmodes; ++n)
        x[n] = (omega[n] == 0.0)
            ? a[n] + c[n] * t
            : a[n] * std::cos(omega[n] * t) + c[n] * std::sin(omega[n] * t) / omega[n];
      return x;
    };

    PulseResponse result;
    result.num_free = static_cast<int>(free.size());
    result.times.resize(o.samples);
    result.signal.resize(o.samples);
    for (int k = 0; k < o.samples; k++) {
      const double t = o.duration * k / (o.samples - 1);
      result.times[k] = t;
      result.signal[k] = h.dot(coordinates(t));
    }
    if (o.snapshot_time >= 0.0) {
      const Eigen::VectorXd u = shapes * coordinates(o.snapshot_time);
      result.snapshot = Eigen::VectorXd::Zero(p.stiffness.rows());
      for (std::size_t k = 0; k < free.size(); k++) result.snapshot[free[k]] = u[k];
      result.snapshot_time = o.snapshot_time;
    }
    return result;
  }

  PulseResponse by_integration(const PulseProblem &p, const PulseOptions &o,
                               const std::vector<int> &free, const InitialState &start,
                               const Eigen::VectorXd &coupling)
  {
    const Eigen::SparseMatrix<double> kff = free_block(p.stiffness, free);
    const bool damped = p.damping.size() != 0 && has_damping(p.damping);
    const Eigen::SparseMatrix<double> cff = damped ? free_block(p.damping, free)
                                                   : Eigen::SparseMatrix<double>();
    const Eigen::VectorXd inverse_mass = restrict_to(p.mass, free).cwiseInverse();

    // a step that divides the sampling interval
    const double interval = o.duration / (o.samples - 1);
    const double omega_max = std::sqrt(omega_squared_bound(kff, restrict_to(p.mass, free)));
    if (!(omega_max > 0.0)) throw SolverError("pulse response: the network has no stiffness");
    // velocity Verlet is stable for dt < 2 / w_max; omega_max bounds w_max from above
    if (o.time_step > 0.0 && o.time_step * omega_max >= 2.0)
      throw SolverError("pulse response: the time step " + std::to_string(o.time_step) +
                        " is not below 2/w_bound = " + std::to_string(2.0 / omega_max) +
                        " (w_bound >= the highest angular frequency): the integration could be "
                        "unstable; give a smaller timestep or leave it automatic");
    const double target = (o.time_step > 0.0) ? o.time_step : STEP_FRACTION / omega_max;
    // the number of steps, counted in doubles first: it may exceed any integer
    const double per_sample_steps = std::max(1.0, std::ceil(interval / target - 1e-9));
    const double needed = per_sample_steps * (o.samples - 1);
    if (!std::isfinite(needed) || needed > static_cast<double>(o.max_steps))
      throw SolverError("pulse response: method integrate would take " + number(needed) +
                        " steps of " + number(target) + " (the duration " + number(o.duration) +
                        " in steps below the " +
                        "stability limit), more than max_steps = " + std::to_string(o.max_steps) +
                        "; shorten the duration, give a larger timestep, or raise max_steps");
    const long per_sample = static_cast<long>(per_sample_steps);
    const double dt = interval / per_sample;

    auto acceleration = [&](const Eigen::VectorXd &u, const Eigen::VectorXd &v) {
      Eigen::VectorXd force = -(kff * u);
      if (damped) force -= cff * v;
      return Eigen::VectorXd(inverse_mass.cwiseProduct(force));
    };

    PulseResponse result;
    result.num_free = static_cast<int>(free.size());
    result.time_step = dt;
    result.times.resize(o.samples);
    result.signal.resize(o.samples);
    const long snapshot_step = (o.snapshot_time >= 0.0) ? std::lround(o.snapshot_time / dt) : -1;
    Eigen::VectorXd u = start.displacement, v = start.velocity;
    Eigen::VectorXd acc = acceleration(u, v);
    const long total = per_sample * (o.samples - 1);
    const long report_every = (o.progress && total > 1000000) ? total / 10 : 0;
    for (long step = 0;; ++step) {
      if (report_every > 0 && step > 0 && step % report_every == 0) o.progress(step, total);
      if (step % per_sample == 0) {
        const int k = static_cast<int>(step / per_sample);
        result.times[k] = k * interval;
        result.signal[k] = coupling.dot(u);
      }
      if (step == snapshot_step) {
        result.snapshot = Eigen::VectorXd::Zero(p.stiffness.rows());
        for (std::size_t k = 0; k < free.size(); k++) result.snapshot[free[k]] = u[k];
        result.snapshot_time = step * dt;
      }
      if (step == total && step >= snapshot_step) break;
      v += 0.5 * dt * acc;
      u += dt * v;
      acc = acceleration(u, v);
      v += 0.5 * dt * acc;
    }
    result.steps = std::max(total, snapshot_step);
    return result;
  }

}    // namespace

PulseInitial pulse_initial_from_name(const std::string &name)
{
  if (name == "velocity") return PulseInitial::Velocity;
  if (name == "displacement") return PulseInitial::Displacement;
  throw SolverError("unknown initial condition '" + name + "': use velocity or displacement");
}

PulseMethod pulse_method_from_name(const std::string &name)
{
  if (name == "modes") return PulseMethod::Modes;
  if (name == "integrate") return PulseMethod::Integrate;
  throw SolverError("unknown pulse method '" + name + "': use modes or integrate");
}

PulseResponse pulse_response(const PulseProblem &problem, const PulseOptions &options)
{
  check(problem, options);
  const std::vector<int> free =
      free_dofs(static_cast<int>(problem.stiffness.rows()), problem.prescribed_dofs);
  if (free.empty()) throw SolverError("pulse response: no free DOF");
  for (int d : free)
    if (problem.source[d] != 0.0 || problem.detector[d] != 0.0)
      throw SolverError("pulse response: the source and detector patterns must vanish on the free "
                        "DOFs (free DOF " +
                        std::to_string(d) + ")");
  const InitialState start = initial_state(problem, options.initial, free);
  const Eigen::VectorXd coupling = restrict_to(-(problem.stiffness * problem.detector), free);
  if (coupling.cwiseAbs().maxCoeff() == 0.0)
    throw SolverError("pulse response: the detector touches no free grain (no contact couples it "
                      "to the network): its signal would be zero");
  PulseResponse response;
  if (options.method == PulseMethod::Modes) {
    if (problem.damping.size() != 0 && has_damping(problem.damping))
      throw SolverError("pulse response: method modes needs an undamped network; use method "
                        "integrate with damping");
    response = by_modes(problem, options, free, start, coupling);
  } else {
    response = by_integration(problem, options, free, start, coupling);
  }
  if (!response.signal.allFinite() || !response.times.allFinite())
    throw SolverError(
        "pulse response: the signal is not finite (an overflow: check the duration, the "
        "time step and the stiffnesses)");
  return response;
}

}    // namespace Acoustic
