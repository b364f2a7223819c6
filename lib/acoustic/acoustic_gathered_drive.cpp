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
   ACOUSTIC package numerics, C++98 facade: the steady response of a
   gathered network to a harmonic drive.
------------------------------------------------------------------------- */

#include "acoustic_gathered_drive.h"

#include "acoustic_contact_network.h"
#include "acoustic_gathered_network.h"
#include "acoustic_helmholtz_solver.h"
#include "acoustic_mumps_ldlt.h"
#include "acoustic_solver_error.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <exception>
#include <new>
#include <utility>

namespace Acoustic {

namespace {

  using Gathered::number;

  const char WHERE[] = "gathered drive: ";

  // the status, its message and no result; never throws (an unallocatable
  // message is left empty)
  bool fail(GatheredDriveResult &result, FacadeStatus::Value status, const char *message)
  {
    result.status = status;
    result.q.clear();
    result.relative_residual = 0.0;
    result.factorisation.clear();
    try {
      result.message = message;
    } catch (...) {
      result.message.clear();
    }
    return false;
  }

  // omega from the frequency or the angular frequency (one of the two)
  double angular_frequency(const GatheredDriveInput &input)
  {
    const bool f_given = !(input.frequency < 0.0), omega_given = !(input.angular_frequency < 0.0);
    if (f_given == omega_given)
      throw SolverError(std::string(WHERE) +
                        "give the frequency or the angular frequency, one of the two (the other "
                        "< 0); got frequency " +
                        number(input.frequency) + ", angular_frequency " +
                        number(input.angular_frequency));
    const double given = f_given ? input.frequency : input.angular_frequency;
    if (!std::isfinite(given))
      throw SolverError(std::string(WHERE) + (f_given ? "the frequency" : "the angular frequency") +
                        " must be finite, got " + number(given));
    // as fix acoustic/mindlin: 2.0 * M_PI * frequency
    return f_given ? 2.0 * M_PI * input.frequency : input.angular_frequency;
  }

  LinearSolverChoice solver_choice(const GatheredDriveInput &input)
  {
    if (input.solver == "iterative")
      throw SolverError(std::string(WHERE) +
                        "solver iterative works on the network distributed over the ranks "
                        "(fix acoustic/mindlin); the gathered network takes auto, lu, ldlt "
                        "or mumps");
    if (input.solver != "auto" && input.solver != "lu" && input.solver != "ldlt" &&
        input.solver != "mumps")
      throw SolverError(std::string(WHERE) + "unknown solver '" + input.solver +
                        "': allowed are auto, lu, ldlt, mumps");
    return linear_solver_from_name(input.solver);
  }

  MumpsSettings mumps_settings(const GatheredDriveInput &input)
  {
    MumpsSettings settings;
    if (input.ordering.empty()) {
      // the default of fix acoustic/mindlin: nested dissection by METIS in 3D,
      // MUMPS's own choice in 2D
      if (input.dimension == 3 && metis_available()) settings.ordering = MumpsOrdering::Metis;
    } else {
      settings.ordering = mumps_ordering_from_name(input.ordering);
    }
    return settings;
  }

  // the prescribed DOFs: the caller's, then the DOFs of the walls it left out (clamped)
  void prescribed_dofs(const GatheredDriveInput &input, const ContactNetwork &network,
                       const std::vector<bool> &wall, std::vector<int> &dofs,
                       Eigen::VectorXcd &values)
  {
    const int ndof = network.dofs_per_grain();
    const int ngrains = network.num_grains();
    std::vector<char> given(static_cast<std::size_t>(network.num_dofs()), 0);
    std::vector<std::complex<double>> amplitudes;
    dofs.clear();
    for (std::size_t k = 0; k < input.prescribed.size(); ++k) {
      const PrescribedDof &p = input.prescribed[k];
      auto which = [&]() {
        return std::string(WHERE) + "prescribed DOF " + std::to_string(k) + " (grain " +
            std::to_string(p.grain) + ", component " + std::to_string(p.component) + ") ";
      };
      if (p.grain < 0 || p.grain >= ngrains)
        throw SolverError(which() + "names a grain outside 0.." + std::to_string(ngrains - 1));
      if (p.component < 0 || p.component >= ndof)
        throw SolverError(which() + "names a component outside 0.." + std::to_string(ndof - 1) +
                          " (" + std::to_string(ndof) + " DOFs per grain)");
      if (!std::isfinite(p.amplitude))
        throw SolverError(which() + "has an amplitude that is not finite: " + number(p.amplitude));
      const int dof = network.dof(p.grain, p.component);
      if (given[dof]) throw SolverError(which() + "is prescribed twice");
      given[dof] = 1;
      dofs.push_back(dof);
      amplitudes.push_back(p.amplitude);
    }
    for (int g = 0; g < ngrains; ++g) {
      if (!wall[g]) continue;
      for (int d = 0; d < ndof; ++d) {
        const int dof = network.dof(g, d);
        if (given[dof]) continue;
        dofs.push_back(dof);
        amplitudes.push_back(0.0);
      }
    }
    values.resize(static_cast<Eigen::Index>(amplitudes.size()));
    for (std::size_t k = 0; k < amplitudes.size(); ++k) values[k] = amplitudes[k];
  }

  FacadeStatus::Value facade_status(SolveStatus status)
  {
    switch (status) {
      case SolveStatus::Success:
        return FacadeStatus::Success;
      case SolveStatus::FactorisationFailed:
        return FacadeStatus::FactorisationFailed;
      case SolveStatus::InaccurateSolution:
        return FacadeStatus::InaccurateSolution;
    }
    return FacadeStatus::InternalError;
  }

}    // namespace

bool solve_gathered_drive(const GatheredDriveInput &input, GatheredDriveResult &result)
{
  result.status = FacadeStatus::Success;
  result.message.clear();
  result.dofs_per_grain = 0;
  result.q.clear();
  result.relative_residual = 0.0;
  result.factorisation.clear();
  try {
    Gathered::require_mpi(WHERE);
    const ContactModel model = Gathered::contact_model(WHERE, input.dimension, input.model);
    const double omega = angular_frequency(input);
    const LinearSolverChoice choice = solver_choice(input);
    const MumpsSettings settings = mumps_settings(input);

    std::vector<bool> wall;
    const ContactNetwork network = Gathered::build_network(
        input.dimension, model, Gathered::network_grains(WHERE, input.grains, wall),
        input.contacts);
    std::vector<int> dofs;
    Eigen::VectorXcd values;
    prescribed_dofs(input, network, wall, dofs, values);

    // as FixAcousticMindlin::solve_drive
    const Eigen::SparseMatrix<double> K = network.stiffness_matrix();
    const Eigen::SparseMatrix<double> C = network.has_damping() ? network.damping_matrix()
                                                                : Eigen::SparseMatrix<double>(0, 0);
    const Eigen::VectorXd M = network.mass_diagonal();
    HelmholtzSolver solver(choice, input.residual_tolerance, MPI_COMM_SELF, settings);
    const HelmholtzSolution sol = solver.solve(K, C, M, omega, dofs, values);

    result.dofs_per_grain = network.dofs_per_grain();
    result.q.resize(2 * static_cast<std::size_t>(sol.q.size()));
    for (Eigen::Index k = 0; k < sol.q.size(); ++k) {
      result.q[2 * k] = sol.q[k].real();
      result.q[2 * k + 1] = sol.q[k].imag();
    }
    result.relative_residual = sol.relative_residual;
    result.factorisation = sol.factorisation;
    result.status = facade_status(sol.status);
    if (sol.ok()) return true;
    result.message = solve_status_name(sol.status) + " at omega = " + number(omega) + ": " +
        (sol.message.empty() ? std::string("no detail") : sol.message);
    return false;
  } catch (SolverError &e) {
    return fail(result, FacadeStatus::InvalidInput, e.what());
  } catch (std::bad_alloc &) {
    return fail(result, FacadeStatus::InternalError, "gathered drive: out of memory");
  } catch (std::exception &e) {
    return fail(result, FacadeStatus::InternalError, e.what());
  } catch (...) {
    return fail(result, FacadeStatus::InternalError, "gathered drive: unknown exception");
  }
}

}    // namespace Acoustic
