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
   ACOUSTIC package numerics: the engine-neutral interface (facade) that
   C++98 callers use, the LIGGGHTS styles of ACOUSTIC among them: what its
   headers share.

     acoustic_gathered_drive.h   the steady response of a whole network,
                                 gathered on one process, to a harmonic drive
     acoustic_gathered_modes.h   the vibration modes of such a network
     acoustic_gathered_pulse.h   its response to a delta pulse of a source
     acoustic_contact_factor.h   the tangential amplitude and the Mindlin
                                 friction factor of one contact

   The facade headers compile as C++98 (-std=gnu++98: LIGGGHTS's tree) and
   include nothing but <string> and <vector>: no Eigen, no MPI.  Their
   functions are implemented in C++17 on the classes of this library (the
   same calls as the LAMMPS styles make, so the same numbers), and never
   throw: invalid input and failed solves come back as a status and a
   message (the message of the library's SolverError, unchanged).  The
   LIGGGHTS build links them as the shared library acoustic_liggghts, which
   exports these functions only.

   Types are in namespace Acoustic; the enumerations are wrapped in structs
   (FacadeStatus::Success), C++98's way of scoped enumerations.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_FACADE_H
#define ACOUSTIC_FACADE_H

#include <string>

// std::string crosses the facade: the caller and the library must use the
// same libstdc++ string (the library is built with the default, C++11 one)
#if defined(_GLIBCXX_USE_CXX11_ABI) && !_GLIBCXX_USE_CXX11_ABI
#error "the ACOUSTIC facade needs the default std::string: no -D_GLIBCXX_USE_CXX11_ABI=0"
#endif

// the functions the shared library acoustic_liggghts exports (the rest of
// it is hidden)
#if defined(__GNUC__)
#define ACOUSTIC_FACADE_API __attribute__((visibility("default")))
#else
#define ACOUSTIC_FACADE_API
#endif

namespace Acoustic {

struct FacadeStatus {
  enum Value {
    Success = 0,
    InvalidInput,           // the message names the offending value; no result
    FactorisationFailed,    // singular system (a resonance of an undamped network, or a part
                            // held by nothing at omega = 0): free DOFs returned as 0
    InaccurateSolution,     // residual above the tolerance: the solution is returned, finite
    InternalError           // out of memory or a library failure (the message says which)
  };
};

// the contact models of acoustic_contact_network.h (ContactModel)
struct FacadeContactModel {
  enum Value {
    Normal = 0,    // translations: 2 (2D) or 3 (3D) DOFs per grain
    Full = 1       // translations and rotations: 3 (2D) or 6 (3D) DOFs per grain
  };
};

// "success", "invalid input", "factorisation failed", "inaccurate solution", "internal error"
inline const char *facade_status_name(FacadeStatus::Value status)
{
  switch (status) {
    case FacadeStatus::Success:
      return "success";
    case FacadeStatus::InvalidInput:
      return "invalid input";
    case FacadeStatus::FactorisationFailed:
      return "factorisation failed";
    case FacadeStatus::InaccurateSolution:
      return "inaccurate solution";
    case FacadeStatus::InternalError:
      return "internal error";
  }
  return "unknown status";
}

// DOFs per grain, as dofs_per_grain() of acoustic_contact_network.h; 0 for a
// dimension other than 2 and 3
inline int facade_dofs_per_grain(int dimension, FacadeContactModel::Value model)
{
  if (dimension != 2 && dimension != 3) return 0;
  if (model == FacadeContactModel::Full) return dimension == 2 ? 3 : 6;
  return dimension;
}

}    // namespace Acoustic

#endif
