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

#ifdef FIX_CLASS
// clang-format off
FixStyle(acoustic/mindlin,FixAcousticMindlin);
// clang-format on
#else

#ifndef LMP_FIX_ACOUSTIC_MINDLIN_H
#define LMP_FIX_ACOUSTIC_MINDLIN_H

#include "fix.h"

#include "acoustic_distributed_mumps.h"
#include "acoustic_helmholtz_solver.h"
#include "acoustic_krylov_solver.h"
#include "acoustic_mindlin_law.h"
#include "acoustic_mumps_ldlt.h"
#include "vibration_network.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace LAMMPS_NS {

class FixAcousticMindlin : public Fix {
 public:
  FixAcousticMindlin(class LAMMPS *, int, char **);
  ~FixAcousticMindlin() override;
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  void post_run() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

  enum SourceMode { ALL, NORMAL };
  // entries of the global vector (f_ID[k] is entry k-1)
  enum {
    NCONTACTS,             // contacts in the network
    MEAN_FACTOR,           // mean mu*/mu over the contacts
    MIN_FACTOR,            // smallest mu*/mu
    WEAK_FRACTION,         // fraction of contacts with mu*/mu < 0.5
    RESIDUAL,              // relative residual of the last solve
    TIME_GATHER,           // wall time of the last contact walk and gather
    TIME_ASSEMBLY,         // ... assembly of K, C, M on rank 0
    TIME_FACTORISATION,    // ... symbolic analysis and numeric factorisation
    TIME_SOLVE,            // ... rest of the solve (triangular solves, residual)
    TIME_UPDATE,           // ... scatter of the amplitudes and friction update
    // the counts and the total time go on from a restart file's values
    NANALYSES,          // symbolic analyses since the fix was first defined
    NFACTORISATIONS,    // numeric factorisations since then
    NREUSES,            // solves done with earlier factors (BiCGSTAB) since then
    TIME_TOTAL,         // wall time of all updates since then
    NITERATIONS,        // Krylov iterations of the last solve (solver iterative)
    NVECTOR
  };

 private:
  double frequency, amplitude;
  std::string source_group;       // source group-ID, or
  std::string source_wall_fix;    // source wall fix-ID (one of the two is empty)
  int source_groupbit;
  int source_wall;    // index of the source wall plane, -1 for a group
  double direction[3];
  int direction_axis;      // 0, 1, 2 if the direction is along x, y, z, else -1
  bool direction_given;    // false: the default, normal to a source wall
  SourceMode source_mode;
  VibrationNetworkSettings settings;
  Acoustic::MindlinFrictionLaw law;
  Acoustic::LinearSolverChoice solver_choice;
  bool reuse;    // solve by the last solution or earlier factors when they still fit
  Acoustic::KrylovSettings krylov_settings;
  Acoustic::MumpsSettings mumps_settings;
  bool ordering_given;    // false: METIS in 3D (when built with it), MUMPS's own in 2D

  std::unique_ptr<VibrationNetwork> network;
  std::unique_ptr<Acoustic::HelmholtzSolver> solver;          // auto, lu, ldlt: on rank 0
  std::unique_ptr<Acoustic::KrylovHelmholtzSolver> krylov;    // iterative: every rank
  std::unique_ptr<Acoustic::DistributedMumpsSolver> mumps;    // mumps: every rank
  bool distributed() const { return krylov || mumps; }
  int ndof;    // DOFs per grain of the network
  int damped;

  bigint last_update;                  // step of the last update of the factors, -1: none yet
  bool factors_committed;              // the factors of the last update reached the end of a run
  std::uint64_t atoms_at_end;          // fingerprint of the atoms at the end of the last run
  std::uint64_t settings_signature;    // hash of the words of the fix command after its ID
  bool restart_settings_differ;        // the restart file read was written with other settings

  double **q_atom;             // complex DOF amplitudes per atom, (re, im) pairs
  bool q_restored;             // q_atom of this process's atoms came from a restart file
  bool last_solution_valid;    // q_atom holds the solution of an update (a start for reuse yes)
  bool warned_idle_source;     // the WARNING of a source wall without contacts was printed
  std::uint64_t
      solved_network;         // fingerprint of the network of the last solve (reuse yes), 0: none
  long unchanged_networks;    // updates that found that network unchanged (no solve)
  double **amplitude_atom;    // per-atom output: translational amplitudes
  double **contact_array;     // local output: one row per contact
  int ncontact_rows, maxcontact_rows;
  double stats[NVECTOR];
  double counts_before[3];      // analyses, factorisations, reuses of earlier processes (restart)
  Eigen::VectorXcd solution;    // rank 0: DOF amplitudes of the last successful solve
                                // (solver iterative: of this processor's part)

  // forward and reverse communication: the DOF amplitudes q_atom, or the
  // values of a halo exchange of the distributed solve (halo_width doubles
  // per atom in halo_values, indexed by local atom)
  enum CommMode { COMM_AMPLITUDES, COMM_HALO };
  CommMode comm_mode;
  int halo_width;
  std::vector<double> halo_values;
  class Halo;
  void begin_halo(int width);

  void parse_keywords(class CommandArguments &);
  void init_source();
  void init_other_fixes();
  void normalise_direction();
  bool factors_are_current() const;
  void update_factors();
  bool solve_drive(std::string &failure);
  bool solve_distributed();
  void drive_dofs(const Acoustic::ContactNetwork &net, const std::vector<int> &source_grains,
                  const std::vector<int> &wall_nodes, std::vector<int> &dofs,
                  Eigen::VectorXcd &values) const;
  bool report_solve(const Acoustic::HelmholtzSolution &sol, const Acoustic::SolverTimings &timing,
                    double assembly_time, double total_time);
  void set_amplitudes();
  void evaluate_contacts(bool set_factors);
  void factor_statistics(const std::vector<GranularContact> &contacts);
  void warn_idle_source_wall();
  std::uint64_t network_fingerprint() const;
  bool network_unchanged();
};

}    // namespace LAMMPS_NS

#endif
#endif
