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
   ACOUSTIC package numerics, C++98 facade (acoustic_facade.h): the steady
   response of a whole contact network, gathered on one process, to a
   harmonic drive.

   What fix acoustic/mindlin does on rank 0 with its gathered network
   (solvers auto, lu, ldlt): a ContactNetwork of the grains and contacts,
   its K, C (when a dashpot is not 0) and the diagonal of M, and
   HelmholtzSolver::solve at omega with the prescribed DOFs
   (acoustic_contact_network.h, acoustic_helmholtz_solver.h): the same
   calls, so that the same network gives the fix's numbers to the last bit.
   For that, give the grains in the fix's order (by atom ID, the walls
   after every atom) and the same drive; the order of the contacts does not
   matter: each is taken from its lower to its higher grain index (i < j,
   the normal reversed, exactly) and they are sorted by (i, j), as the fix
   gathers them.

   Walls.  The fix makes each wall plane a node of the network whose DOFs
   are all prescribed: the source wall's translations move with the drive,
   everything else of the walls is clamped.  Here a wall is a grain of
   infinite mass (HUGE_VAL of <cmath>): every DOF of it that the
   prescribed list does not name is clamped (amplitude 0), and its mass and
   radius are replaced by the fix's placeholders (1, 1), which no result
   depends on.  A grain of finite mass may be prescribed as well (a source
   grain), in any of its DOFs.

   Units: the prescribed amplitudes are those of the drive relative to its
   amplitude U0 (the fix prescribes the unit drive direction), and so are
   the DOF values returned; omega in 1/time units of the masses and
   stiffnesses.

   Each call builds its solver anew (MUMPS, UMFPACK or CHOLMOD on
   MPI_COMM_SELF of the calling process): nothing is kept between calls.
   MPI must be initialised.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_GATHERED_DRIVE_H
#define ACOUSTIC_GATHERED_DRIVE_H

#include "acoustic_facade.h"

#include <string>
#include <vector>

namespace Acoustic {

struct GatheredGrain {
  double mass;      // > 0 and finite, or +infinity (HUGE_VAL): a wall, every DOF prescribed
  double radius;    // > 0 and finite with model full (rotations); not read for a wall

  GatheredGrain() : mass(1.0), radius(1.0) {}
  GatheredGrain(double m, double r) : mass(m), radius(r) {}
};

struct GatheredContact {
  int i, j;            // grain indices, i != j
  double normal[3];    // unit vector from j to i (z component 0 in 2D)
  double kn, kt;       // normal and tangential stiffness >= 0 (kt: model full only)
  double cn, ct;       // normal and tangential dashpot >= 0 (ct: model full only)

  GatheredContact() : i(0), j(0), kn(0.0), kt(0.0), cn(0.0), ct(0.0)
  {
    normal[0] = normal[1] = normal[2] = 0.0;
  }
};

struct PrescribedDof {
  int grain;
  int component;       // 0 .. dofs_per_grain - 1, translations first
  double amplitude;    // real amplitude (relative to U0)

  PrescribedDof() : grain(0), component(0), amplitude(0.0) {}
  PrescribedDof(int g, int k, double a) : grain(g), component(k), amplitude(a) {}
};

struct GatheredDriveInput {
  int dimension;                      // 2 or 3
  FacadeContactModel::Value model;    // normal or full
  std::vector<GatheredGrain> grains;
  std::vector<GatheredContact> contacts;
  std::vector<PrescribedDof> prescribed;    // each DOF once
  // the drive: give one of the two (the other stays < 0)
  double frequency;            // f >= 0: omega = 2 pi f, computed as the fix does
  double angular_frequency;    // omega >= 0
  // "auto" (default), "lu", "ldlt" (undamped only) or "mumps": the
  // factorisation, as the keyword solver of fix acoustic/mindlin (here every
  // one on the calling process; not "iterative", which needs the
  // distributed network)
  std::string solver;
  // MUMPS's fill-reducing ordering: "" (default: "metis" in 3D when built
  // with METIS, else "auto", as the fix's default), "auto" or "metis"
  std::string ordering;
  double residual_tolerance;    // relative residual above which the solve is inaccurate: 1e-6

  GatheredDriveInput() :
      dimension(3), model(FacadeContactModel::Normal), frequency(-1.0), angular_frequency(-1.0),
      solver("auto"), residual_tolerance(1e-6)
  {
  }
};

struct GatheredDriveResult {
  FacadeStatus::Value status;
  std::string message;    // why, when status is not Success
  int dofs_per_grain;
  // complex value of DOF k of grain g at (q[2 (g dofs_per_grain + k)],
  // q[2 (g dofs_per_grain + k) + 1]) (re, im): 2 dofs_per_grain
  // grains.size() numbers, prescribed DOFs included; finite.  Empty when the
  // input is invalid; with FactorisationFailed the free DOFs are 0.
  std::vector<double> q;
  double relative_residual;     // ||A q_F - b|| / ||b|| of the solve (0: nothing to solve)
  std::string factorisation;    // "mumps", "lu", "ldlt", or "none" (no free DOF, or b = 0)
  bool ok() const { return status == FacadeStatus::Success; }

  GatheredDriveResult() : status(FacadeStatus::Success), dofs_per_grain(0), relative_residual(0.0)
  {
  }
};

// The response into result; false (status and message set) if the input
// is invalid or the solve failed.  Never throws.
ACOUSTIC_FACADE_API bool solve_gathered_drive(const GatheredDriveInput &input,
                                              GatheredDriveResult &result);

}    // namespace Acoustic

#endif
