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
   ACOUSTIC package numerics, C++98 facade: the tangential amplitude and
   the friction factor of one contact.
------------------------------------------------------------------------- */

#include "acoustic_contact_factor.h"

#include "acoustic_contact_network.h"
#include "acoustic_mindlin_law.h"
#include "acoustic_solver_error.h"

#include <complex>
#include <exception>
#include <new>

namespace Acoustic {

namespace {

  // the status and its message; never throws (an unallocatable message is left empty)
  bool fail(ContactFactorResult &result, FacadeStatus::Value status, const char *message)
  {
    result.status = status;
    try {
      result.message = message;
    } catch (...) {
      result.message.clear();
    }
    return false;
  }

}    // namespace

bool contact_mindlin_factor(const ContactFactorInput &input, ContactFactorResult &result)
{
  result.tangential_amplitude = 0.0;
  result.factor = 1.0;
  result.status = FacadeStatus::Success;
  result.message.clear();
  try {
    // what the library functions take for granted (the LAMMPS fix always passes valid ones)
    if (input.dimension != 2 && input.dimension != 3)
      throw SolverError("contact factor: dimension must be 2 or 3, got " +
                        std::to_string(input.dimension));
    if (input.model != FacadeContactModel::Normal && input.model != FacadeContactModel::Full)
      throw SolverError("contact factor: unknown contact model " +
                        std::to_string(static_cast<int>(input.model)) +
                        " (FacadeContactModel::Normal or Full)");
    if (!input.q_i || !input.q_j)
      throw SolverError("contact factor: the DOF values of grain i or j are missing (q_i or q_j "
                        "is a null pointer)");
    const ContactModel model = (input.model == FacadeContactModel::Full) ? ContactModel::Full
                                                                         : ContactModel::Normal;
    const int ndof = dofs_per_grain(input.dimension, model);
    Eigen::VectorXcd qi(ndof), qj(ndof);
    for (int k = 0; k < ndof; k++) {
      qi[k] = std::complex<double>(input.q_i[2 * k], input.q_i[2 * k + 1]);
      qj[k] = std::complex<double>(input.q_j[2 * k], input.q_j[2 * k + 1]);
    }
    // the calls of fix acoustic/mindlin before this function (same operations, same order)
    const Eigen::Vector3d n(input.normal[0], input.normal[1], input.normal[2]);
    const Eigen::Vector3cd delta = contact_point_displacement(
        input.dimension, model, n, input.radius_i, input.radius_j, qi, qj);
    const double ut = tangential_amplitude(delta, n, input.amplitude);
    double s = 1.0;
    if (input.compute_factor) {
      MindlinFrictionLaw law;
      law.cmu = input.cmu;
      law.mu_min = input.mu_min;
      s = friction_factor(law, input.tangential_stiffness, ut, input.friction_coefficient,
                          input.normal_force);
    }
    result.tangential_amplitude = ut;
    result.factor = s;
    return true;
  } catch (SolverError &e) {
    return fail(result, FacadeStatus::InvalidInput, e.what());
  } catch (std::bad_alloc &) {
    return fail(result, FacadeStatus::InternalError, "contact factor: out of memory");
  } catch (std::exception &e) {
    return fail(result, FacadeStatus::InternalError, e.what());
  } catch (...) {
    return fail(result, FacadeStatus::InternalError, "contact factor: unknown exception");
  }
}

}    // namespace Acoustic
