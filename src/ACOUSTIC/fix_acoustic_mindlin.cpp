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
   Contributing authors: the ACOUSTIC package developers.

   Two-time-scale coupling of an ultrasonic vibration to the DEM: at every
   step that is a multiple of N (before the forces of that step) the steady
   harmonic response of the contact network to a basal drive is solved
   (direct solvers: network gathered on rank 0; solver iterative: a Krylov
   method where the contacts are, ghost amplitudes through LAMMPS's forward
   and reverse communication), and each contact's friction factor is set
   from the tangential vibration it feels (Mindlin law).
------------------------------------------------------------------------- */

#include "fix_acoustic_mindlin.h"

#include "citations_acoustic.h"
#include "citeme.h"

#include "acoustic_contact_factor.h"
#include "acoustic_contact_network.h"
#include "acoustic_solver_error.h"
#include "collective_error.h"
#include "command_arguments.h"
#include "granular_contact_walker.h"
#include "granular_state.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

static const char CMD[] = "fix acoustic/mindlin";
// first word of the global restart state since it holds the settings'
// signature (-2: 14 statistics, -3: NVECTOR); before, the first word was the
// step of the last update (>= -1) and 14 statistics followed
static constexpr double RESTART_WITH_SIGNATURE = -2.0;
static constexpr double RESTART_WITH_ITERATIONS = -3.0;
static constexpr int NVECTOR_BEFORE_ITERATIONS = 14;

/* ---------------------------------------------------------------------- */

FixAcousticMindlin::FixAcousticMindlin(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), source_groupbit(0), source_wall(-1), direction_axis(-1),
    direction_given(false), source_mode(ALL), solver_choice(Acoustic::LinearSolverChoice::Auto),
    reuse(false), ordering_given(false), ndof(0), damped(0), last_update(-1),
    factors_committed(true), atoms_at_end(0), settings_signature(0), restart_settings_differ(false),
    q_atom(nullptr), q_restored(false), amplitude_atom(nullptr), contact_array(nullptr),
    ncontact_rows(0), maxcontact_rows(0), last_solution_valid(false), warned_idle_source(false),
    solved_network(0), unchanged_networks(0), comm_mode(COMM_AMPLITUDES), halo_width(0)
{
  if (lmp->citeme) lmp->citeme->add(AcousticCitations::two_time_scale_model);
  if (narg < 10)
    error->all(FLERR,
               "{}: expected fix ID group-ID acoustic/mindlin N "
               "frequency f amplitude U0 source group-ID [keyword value ...]",
               CMD);

  // the words after the fix ID, as given: a restart file written with other
  // ones holds factors of another drive
  Fingerprint signature;
  for (int k = 1; k < narg; k++) {
    for (const char *c = arg[k]; *c; c++)
      signature.mix(static_cast<std::uint64_t>(static_cast<unsigned char>(*c)));
    signature.mix(static_cast<std::uint64_t>(0));
  }
  settings_signature = signature.value();

  nevery = utils::inumeric(FLERR, arg[3], false, lmp);
  if (nevery <= 0) error->all(FLERR, 3, "{}: N must be > 0, got {}", CMD, nevery);
  CommandArguments args(lmp, CMD, narg, arg, 4);
  args.expect("frequency", 1);
  frequency = args.number(1);
  if (frequency < 0.0)
    args.reject(FLERR, 1, "frequency must be >= 0 (1/time units), got {}", frequency);
  args.next();
  args.expect("amplitude", 1);
  amplitude = args.number(1);
  if (amplitude < 0.0)
    args.reject(FLERR, 1, "amplitude must be >= 0 (distance units), got {}", amplitude);
  args.next();
  args.expect("source", 1);
  if (strcmp(args.word(1), "wall") == 0) {
    args.expect("source", 2);
    source_wall_fix = args.wall_fix(2);
  } else {
    source_group = args.group_name(1);
  }
  args.next();

  const int dim = domain->dimension;
  direction[0] = direction[1] = direction[2] = 0.0;
  direction[dim == 3 ? 2 : 1] = 1.0;
  parse_keywords(args);
  normalise_direction();

  damped = (settings.damping_ratio > 0.0);
  if (damped && solver_choice == Acoustic::LinearSolverChoice::Ldlt)
    error->all(FLERR,
               "{}: solver ldlt handles undamped (real symmetric) problems "
               "only; use solver lu or auto with damping",
               CMD);

  ndof = Acoustic::dofs_per_grain(dim, settings.model);
  const bool iterative = (solver_choice == Acoustic::LinearSolverChoice::Iterative);
  // the amplitudes of a grain; the distributed solve also sends the
  // ndof x ndof diagonal block of a grain (complex) in both directions
  comm_forward = iterative ? 2 * ndof * ndof : 2 * ndof;
  comm_reverse = iterative ? 2 * ndof * ndof : 0;

  // outputs
  vector_flag = 1;
  size_vector = NVECTOR;
  global_freq = nevery;
  extvector = 0;
  peratom_flag = 1;
  size_peratom_cols = damped ? 6 : 3;
  peratom_freq = nevery;
  local_flag = 1;
  size_local_cols = 6;
  size_local_rows = 0;
  local_freq = nevery;
  for (double &s : stats) s = 0.0;
  for (double &c : counts_before) c = 0.0;

  // the step of the last update and the statistics, and the per-atom
  // amplitudes, continue in a run restarted from a restart file
  restart_global = 1;
  restart_peratom = 1;
  // an atom moving to another processor takes its amplitudes along
  maxexchange = size_peratom_cols + 2 * ndof;

  network.reset(new VibrationNetwork(lmp, settings, CMD));
  // collective.  auto, lu, ldlt: the network gathered on rank 0, factorised
  // there (the same answer every run); mumps: every rank its own contacts,
  // MUMPS on all ranks from distributed input (it sums in the order messages
  // arrive: not bitwise reproducible); iterative: every rank its own
  // contacts, a Krylov method
  try {
    if (iterative) {
      krylov.reset(new Acoustic::KrylovHelmholtzSolver(world, krylov_settings));
    } else if (solver_choice == Acoustic::LinearSolverChoice::Mumps) {
      if (mumps_settings.ordering == Acoustic::MumpsOrdering::Metis)
        error->all(FLERR,
                   "{}: ordering metis needs the network on one rank; solver "
                   "mumps orders with MUMPS's own choice: use solver auto for METIS",
                   CMD);
      mumps.reset(new Acoustic::DistributedMumpsSolver(world, mumps_settings, 1e-6));
    } else {
      // nested dissection by METIS: 30 % fewer operations in 3D (bench/README.md);
      // 2D layers keep MUMPS's own choice
      if (!ordering_given && dim == 3 && Acoustic::metis_available())
        mumps_settings.ordering = Acoustic::MumpsOrdering::Metis;
      solver.reset(
          new Acoustic::HelmholtzSolver(solver_choice, 1e-6, MPI_COMM_SELF, mumps_settings));
      // reuse yes: between two updates few contacts change, precondition with the
      // last factors (faster, but the factors then depend on the earlier updates)
      solver->set_reuse_factorisation(reuse);
    }
  } catch (Acoustic::SolverError &e) {
    error->all(FLERR, "{}: {}", CMD, e.what());
  }

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) {
    for (int k = 0; k < 2 * ndof; k++) q_atom[i][k] = 0.0;
    for (int k = 0; k < size_peratom_cols; k++) amplitude_atom[i][k] = 0.0;
  }
}

/* ----------------------------------------------------------------------
   deleted between runs (unfix): full friction again on the contacts the
   fix acted on
------------------------------------------------------------------------- */

FixAcousticMindlin::~FixAcousticMindlin()
{
  // update and force are gone when LAMMPS itself is deleted (clear, end of input)
  if (update && force && update->whichflag == 0 && last_update >= 0) {
    const bool same_atoms = same_on_every_rank(lmp, atom_order_fingerprint(lmp), atoms_at_end);
    GranularContactWalker walker(lmp, CMD);
    if (!same_atoms || !walker.reset_factors_between_runs(groupbit))
      error->warning(FLERR,
                     "{} {}: the friction factors it set stay in the contact histories: "
                     "atoms moved between processors since the last run. Use 'run 0' "
                     "before 'unfix {}' to restore full friction",
                     CMD, id, id);
  }
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(q_atom);
  memory->destroy(amplitude_atom);
  memory->destroy(contact_array);
}

/* ---------------------------------------------------------------------- */

void FixAcousticMindlin::parse_keywords(CommandArguments &args)
{
  while (args.more()) {
    if (settings.parse(args, true)) continue;
    if (args.take("direction", 3)) {
      for (int k = 0; k < 3; k++) direction[k] = args.number(1 + k);
      direction_given = true;
    } else if (args.take("mode", 1)) {
      if (strcmp(args.word(1), "all") == 0)
        source_mode = ALL;
      else if (strcmp(args.word(1), "normal") == 0)
        source_mode = NORMAL;
      else
        args.reject(FLERR, 1, "mode must be 'all' or 'normal', got '{}'", args.word(1));
    } else if (args.take("cmu", 1)) {
      law.cmu = args.number(1);
      if (law.cmu < 0.0) args.reject(FLERR, 1, "cmu must be >= 0, got {}", law.cmu);
    } else if (args.take("mu_min", 1)) {
      law.mu_min = args.number(1);
      if (law.mu_min < 0.0 || law.mu_min > 1.0)
        args.reject(FLERR, 1, "mu_min must be in [0, 1], got {}", law.mu_min);
    } else if (args.take("reuse", 1)) {
      reuse = args.logical(1);
    } else if (args.take("solver", 1)) {
      try {
        solver_choice = Acoustic::linear_solver_from_name(args.word(1));
      } catch (Acoustic::SolverError &e) {
        args.reject(FLERR, 1, "{}", e.what());
      }
      if (solver_choice == Acoustic::LinearSolverChoice::Mumps && !Acoustic::mumps_available())
        args.reject(FLERR, 1,
                    "solver mumps needs an ACOUSTIC package built with MUMPS (Debian: "
                    "libmumps-dev; CMake: ACOUSTIC_WITH_MUMPS=on); use solver auto (lu "
                    "without MUMPS) or iterative");
      if (solver_choice == Acoustic::LinearSolverChoice::Iterative &&
          !Acoustic::KrylovHelmholtzSolver::available())
        args.reject(FLERR, 1,
                    "solver iterative needs an ACOUSTIC package built with PETSc "
                    "(complex scalars; Debian: libpetsc-complex-dev); use solver auto, "
                    "or rebuild LAMMPS with PETSc");
    } else if (args.take("tolerance", 1)) {
      krylov_settings.tolerance = args.number(1);
      if (!(krylov_settings.tolerance > 0.0 && krylov_settings.tolerance < 1.0))
        args.reject(FLERR, 1, "tolerance must be in (0, 1), got {}", krylov_settings.tolerance);
    } else if (args.take("max_iterations", 1)) {
      krylov_settings.max_iterations = args.integer(1);
      if (krylov_settings.max_iterations < 1)
        args.reject(FLERR, 1, "max_iterations must be >= 1, got {}",
                    krylov_settings.max_iterations);
    } else if (args.take("ordering", 1)) {
      const std::string name = args.word(1);
      if (name == "mumps")
        mumps_settings.ordering = Acoustic::MumpsOrdering::Auto;
      else if (name == "metis")
        mumps_settings.ordering = Acoustic::MumpsOrdering::Metis;
      else
        args.reject(FLERR, 1, "ordering must be 'mumps' or 'metis', got '{}'", name);
      if (mumps_settings.ordering == Acoustic::MumpsOrdering::Metis && !Acoustic::metis_available())
        args.reject(FLERR, 1,
                    "ordering metis needs an ACOUSTIC package built with METIS "
                    "(Debian: libmetis-dev); use ordering mumps");
      ordering_given = true;
    } else if (args.take("low_rank", 1)) {
      const double tolerance = args.number(1);
      if (!(tolerance >= 0.0 && tolerance < 1.0))
        args.reject(FLERR, 1, "low_rank tolerance must be in [0, 1) (0: full rank), got {}",
                    tolerance);
      mumps_settings.low_rank = tolerance > 0.0;
      mumps_settings.low_rank_tolerance = tolerance > 0.0 ? tolerance
                                                          : mumps_settings.low_rank_tolerance;
    } else if (args.take("shift", 1)) {
      krylov_settings.shift = args.number(1);
      if (krylov_settings.shift < 0.0)
        args.reject(FLERR, 1, "shift must be >= 0, got {}", krylov_settings.shift);
    } else if (args.take("preconditioner", 1)) {
      try {
        krylov_settings.preconditioner = Acoustic::krylov_preconditioner_from_name(args.word(1));
      } catch (Acoustic::SolverError &e) {
        args.reject(FLERR, 1, "{}", e.what());
      }
    } else {
      args.unknown("direction, mode, stiffness, kappa_scale, ratio, cmu, mu_min, model, damping, "
                   "solver, reuse, tolerance, max_iterations, preconditioner, shift, ordering, "
                   "low_rank, region_walls");
    }
    args.next();
  }
}

/* ----------------------------------------------------------------------
   unit drive direction, without overflow or underflow for any finite input
------------------------------------------------------------------------- */

void FixAcousticMindlin::normalise_direction()
{
  const int dim = domain->dimension;
  if (dim == 2 && direction[2] != 0.0)
    error->all(FLERR,
               "{}: in 2D the direction must lie in the xy plane "
               "(dz = 0)",
               CMD);
  const double largest = MAX(fabs(direction[0]), MAX(fabs(direction[1]), fabs(direction[2])));
  if (largest == 0.0) error->all(FLERR, "{}: direction must not be the zero vector", CMD);
  for (double &d : direction) d /= largest;
  const double norm =
      sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  for (double &d : direction) d /= norm;
  for (int k = 0; k < dim; k++)
    if (fabs(direction[k]) == 1.0) direction_axis = k;
  if (source_mode == NORMAL && direction_axis < 0)
    error->all(FLERR,
               "{}: mode normal prescribes one Cartesian component of the "
               "source grains; give a direction along x, y or z",
               CMD);
}

/* ---------------------------------------------------------------------- */

int FixAcousticMindlin::setmask()
{
  return PRE_FORCE | POST_RUN;
}

/* ---------------------------------------------------------------------- */

void FixAcousticMindlin::init()
{
  network->init();
  init_source();
  init_other_fixes();
}

/* ----------------------------------------------------------------------
   the source: a wall plane in the network, or atoms all inside the fix group
------------------------------------------------------------------------- */

void FixAcousticMindlin::init_source()
{
  if (!source_wall_fix.empty()) {
    source_groupbit = 0;
    source_wall = network->wall_of_fix(source_wall_fix);
    if (source_wall < 0)
      error->all(FLERR,
                 "{}: source wall {} is not a wall of the vibration network (it must be "
                 "a fix wall/gran xplane, yplane or zplane, or a fix wall/gran/region)",
                 CMD, source_wall_fix);
    if (!direction_given) {
      // the default drive of a wall: along its normal
      network->wall_normal(source_wall, direction);
      direction_axis = network->walls()[source_wall].axis;
    }
    return;
  }
  const int igroup_source = group->find(source_group);
  if (igroup_source < 0)
    error->all(FLERR, "{}: source group {} no longer exists", CMD, source_group);
  source_groupbit = group->bitmask[igroup_source];

  // the source atoms: at least one, all of them in the fix group
  bigint counts_local[2] = {0, 0}, counts[2];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & source_groupbit)) continue;
    if (atom->mask[i] & groupbit)
      counts_local[0]++;
    else
      counts_local[1]++;
  }
  MPI_Allreduce(counts_local, counts, 2, MPI_LMP_BIGINT, MPI_SUM, world);
  if (counts[0] == 0)
    error->all(FLERR,
               "{}: source group {} has no atom in the fix group {}; the source grains "
               "must belong to the fix group",
               CMD, source_group, group->names[igroup]);
  if (counts[1] > 0)
    error->all(FLERR,
               "{}: {} atoms of the source group {} are not in the fix group {}; the "
               "source grains must all belong to the fix group",
               CMD, counts[1], source_group, group->names[igroup]);
}

/* ----------------------------------------------------------------------
   one fix acoustic/mindlin per contact: the factors of two would overwrite
   each other
------------------------------------------------------------------------- */

void FixAcousticMindlin::init_other_fixes()
{
  for (auto *other : modify->get_fix_by_style("^acoustic/mindlin$")) {
    if (other == this) continue;
    bigint common_local = 0, common = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & groupbit) && (atom->mask[i] & other->groupbit)) common_local++;
    MPI_Allreduce(&common_local, &common, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    if (common > 0)
      error->all(FLERR,
                 "{} {} and fix {} both act on the contacts of the {} atoms their groups "
                 "share, and would overwrite each other's friction factors; use one fix "
                 "acoustic/mindlin, or groups without common atoms",
                 CMD, id, other->id, common);
  }
}

/* ----------------------------------------------------------------------
   factors of the last multiple of N: those of the uninterrupted run
------------------------------------------------------------------------- */

bool FixAcousticMindlin::factors_are_current() const
{
  const bigint step = update->ntimestep;
  return last_update >= 0 && last_update <= step && last_update >= step - step % nevery;
}

/* ----------------------------------------------------------------------
   before the forces of the setup: update only if the factors are not those
   an uninterrupted run would have now (a new fix, a changed timestep, a
   restart file written by this fix with other settings)
------------------------------------------------------------------------- */

void FixAcousticMindlin::setup_pre_force(int /*vflag*/)
{
  // the DOF amplitudes and the settings of a restart file serve the first
  // setup after it only
  int restored = q_restored ? 1 : 0, any_restored = 0;
  q_restored = false;
  const bool other_settings = restart_settings_differ;
  restart_settings_differ = false;
  // an update whose factors never reached the end of a run (an error in a
  // setup after it) may have left them in neighbor lists that are gone
  if (!factors_are_current() || other_settings || !factors_committed) {
    update_factors();
    return;
  }
  network->collect(groupbit);
  // restarted at the step of its last update: the local rows of that update,
  // from the DOF amplitudes of the restart file (the factors stay as they are)
  MPI_Allreduce(&restored, &any_restored, 1, MPI_INT, MPI_MAX, world);
  if (any_restored && last_update == update->ntimestep) {
    comm->forward_comm(this);
    evaluate_contacts(false);
  }
  factor_statistics(network->local_contacts());
}

void FixAcousticMindlin::pre_force(int /*vflag*/)
{
  if (update->ntimestep % nevery == 0) update_factors();
}

void FixAcousticMindlin::post_run()
{
  atoms_at_end = atom_order_fingerprint(lmp);
  // the factors are in the contact histories that pair granular's history
  // fix keeps with the atoms after a run
  factors_committed = true;
}

/* ----------------------------------------------------------------------
   the prescribed DOFs of a network (gathered or one processor's part) and
   their amplitudes: the source grains, the source wall moving with the
   drive, every other wall clamped
------------------------------------------------------------------------- */

void FixAcousticMindlin::drive_dofs(const Acoustic::ContactNetwork &net,
                                    const std::vector<int> &source_grains,
                                    const std::vector<int> &wall_nodes, std::vector<int> &dofs,
                                    Eigen::VectorXcd &values) const
{
  const int dim = domain->dimension;
  std::vector<std::complex<double>> amplitudes;
  dofs.clear();
  for (std::size_t k = 0; k < wall_nodes.size(); k++) {
    const bool source = static_cast<int>(k) == source_wall;
    for (int d = 0; d < ndof; d++) {
      dofs.push_back(net.dof(wall_nodes[k], d));
      amplitudes.push_back((source && d < dim) ? direction[d] : 0.0);
    }
  }
  for (int g : source_grains) {
    if (source_mode == ALL) {
      for (int k = 0; k < dim; k++) {
        dofs.push_back(net.dof(g, k));
        amplitudes.push_back(direction[k]);
      }
      for (int k = dim; k < ndof; k++) {    // rotations of a rigid vibrating base: none
        dofs.push_back(net.dof(g, k));
        amplitudes.push_back(0.0);
      }
    } else {
      dofs.push_back(net.dof(g, direction_axis));
      amplitudes.push_back(direction[direction_axis]);
    }
  }
  values.resize(static_cast<Eigen::Index>(amplitudes.size()));
  for (std::size_t k = 0; k < amplitudes.size(); k++) values[k] = amplitudes[k];
}

/* ----------------------------------------------------------------------
   the statistics of a solve; false with a WARNING (rank 0) if it failed
------------------------------------------------------------------------- */

bool FixAcousticMindlin::report_solve(const Acoustic::HelmholtzSolution &sol,
                                      const Acoustic::SolverTimings &timing, double assembly_time,
                                      double total_time)
{
  stats[RESIDUAL] = sol.relative_residual;
  stats[TIME_ASSEMBLY] = assembly_time;
  stats[TIME_FACTORISATION] = timing.analysis + timing.factorisation;
  stats[TIME_SOLVE] = total_time - assembly_time - stats[TIME_FACTORISATION];
  stats[NITERATIONS] = sol.iterations;
  if (solver) {
    stats[NANALYSES] = counts_before[0] + static_cast<double>(solver->num_analyses());
    stats[NFACTORISATIONS] = counts_before[1] + static_cast<double>(solver->num_factorisations());
    stats[NREUSES] =
        counts_before[2] + static_cast<double>(solver->num_reuses() + unchanged_networks);
  } else if (mumps) {
    stats[NANALYSES] = counts_before[0] + static_cast<double>(mumps->num_analyses());
    stats[NFACTORISATIONS] = counts_before[1] + static_cast<double>(mumps->num_factorisations());
    stats[NREUSES] =
        counts_before[2] + static_cast<double>(mumps->num_reuses() + unchanged_networks);
  } else {
    stats[NREUSES] =
        counts_before[2] + static_cast<double>(krylov->num_reuses() + unchanged_networks);
  }
  if (sol.ok()) return true;
  if (comm->me != 0) return false;
  if (krylov)
    error->warning(FLERR,
                   "{}: the iterative Helmholtz solve at f = {} failed ({}; relative "
                   "residual {:.3g} after {} iterations); keeping the previous friction "
                   "factors. The Krylov method needs damping (damping 0.01 or more) or a "
                   "drive below the band; an undamped network driven inside its band is "
                   "the direct solvers' job: use solver auto",
                   CMD, frequency, sol.message, sol.relative_residual, sol.iterations);
  else
    error->warning(FLERR,
                   "{}: the Helmholtz solve at f = {} failed ({}: {}; relative residual "
                   "{:.3g}); keeping the previous friction factors. A frequency on a "
                   "resonance of an undamped network is singular: add damping or move f",
                   CMD, frequency, Acoustic::solve_status_name(sol.status), sol.message,
                   sol.relative_residual);
  return false;
}

/* ----------------------------------------------------------------------
   rank 0: the Helmholtz solve of the gathered network; false if the solve
   failed (singular, inaccurate: a WARNING) or the input is invalid
   (failure holds the ERROR message)
------------------------------------------------------------------------- */

bool FixAcousticMindlin::solve_drive(std::string &failure)
{
  const double t0 = MPI_Wtime();
  const Acoustic::ContactNetwork &net = network->network();
  std::vector<int> prescribed;
  Eigen::VectorXcd qp;
  drive_dofs(net, network->marked_grains(0), network->wall_nodes(), prescribed, qp);

  Acoustic::HelmholtzSolution sol;
  double t1 = t0;
  try {
    const Eigen::SparseMatrix<double> K = net.stiffness_matrix();
    const Eigen::SparseMatrix<double> C = net.has_damping() ? net.damping_matrix()
                                                            : Eigen::SparseMatrix<double>(0, 0);
    const Eigen::VectorXd M = net.mass_diagonal();
    t1 = MPI_Wtime();
    sol = solver->solve(K, C, M, 2.0 * M_PI * frequency, prescribed, qp);
  } catch (Acoustic::SolverError &e) {
    failure = fmt::format("{}: {}", CMD, e.what());
    return false;
  }
  if (!report_solve(sol, solver->last_timings(), t1 - t0, MPI_Wtime() - t0)) return false;
  solution = sol.q;
  return true;
}

/* ----------------------------------------------------------------------
   the Halo of the distributed solve: LAMMPS's forward and reverse
   communication of this fix, between the grains of this processor's part
   of the network and its atoms
------------------------------------------------------------------------- */

class FixAcousticMindlin::Halo : public Acoustic::HaloExchange {
 public:
  Halo(FixAcousticMindlin *fix, const LocalNetworkPart &part) : fix(fix), part(part) {}

  void forward(std::complex<double> *values, int width) override
  {
    fix->begin_halo(2 * width);
    for (int g = 0; g < part.num_owned; g++) copy_in(g, values, width);
    fix->comm->forward_comm(fix, 2 * width);
    for (int g = part.num_owned; g < static_cast<int>(part.atoms.size()); g++)
      copy_out(g, values, width, false);
    fix->comm_mode = COMM_AMPLITUDES;
  }

  void reverse(std::complex<double> *values, int width) override
  {
    fix->begin_halo(2 * width);
    for (int g = part.num_owned; g < static_cast<int>(part.atoms.size()); g++)
      copy_in(g, values, width);
    fix->comm->reverse_comm(fix, 2 * width);
    for (int g = 0; g < part.num_owned; g++) copy_out(g, values, width, true);
    fix->comm_mode = COMM_AMPLITUDES;
  }

 private:
  FixAcousticMindlin *fix;
  const LocalNetworkPart &part;

  void copy_in(int g, const std::complex<double> *values, int width)
  {
    double *to = &fix->halo_values[static_cast<std::size_t>(part.atoms[g]) * 2 * width];
    for (int k = 0; k < width; k++) {
      to[2 * k] = values[g * width + k].real();
      to[2 * k + 1] = values[g * width + k].imag();
    }
  }
  void copy_out(int g, std::complex<double> *values, int width, bool add)
  {
    const double *from = &fix->halo_values[static_cast<std::size_t>(part.atoms[g]) * 2 * width];
    for (int k = 0; k < width; k++) {
      const std::complex<double> v(from[2 * k], from[2 * k + 1]);
      values[g * width + k] = add ? values[g * width + k] + v : v;
    }
  }
};

void FixAcousticMindlin::begin_halo(int width)
{
  comm_mode = COMM_HALO;
  halo_width = width;
  halo_values.assign(static_cast<std::size_t>(atom->nlocal + atom->nghost) * width, 0.0);
}

/* ----------------------------------------------------------------------
   every rank: the solve of this processor's part of the network (Krylov
   or MUMPS from distributed input); false (a WARNING) if it failed
------------------------------------------------------------------------- */

bool FixAcousticMindlin::solve_distributed()
{
  const double t0 = MPI_Wtime();
  const LocalNetworkPart &part = network->local_part();
  Acoustic::DistributedHelmholtzProblem problem;
  problem.network = part.network.get();
  problem.num_owned = part.num_owned;
  problem.omega = 2.0 * M_PI * frequency;
  drive_dofs(*part.network, part.marked[0], part.wall_nodes, problem.prescribed_dofs,
             problem.prescribed_values);

  // reuse yes: the amplitudes of the last update, which the atoms carry, as a
  // start (Krylov) or as the answer if they still solve the system
  Eigen::VectorXcd guess;
  if (reuse && last_solution_valid) {
    guess = Eigen::VectorXcd::Zero(part.network->num_dofs());
    for (int g = 0; g < part.num_owned; g++)
      for (int k = 0; k < ndof; k++)
        guess[g * ndof + k] =
            std::complex<double>(q_atom[part.atoms[g]][2 * k], q_atom[part.atoms[g]][2 * k + 1]);
  }
  Halo halo(this, part);
  Acoustic::HelmholtzSolution sol;
  CollectiveError errors(lmp);
  try {
    sol = krylov ? krylov->solve(problem, halo, guess.size() ? &guess : nullptr)
                 : mumps->solve(problem, halo, guess.size() ? &guess : nullptr);
  } catch (Acoustic::SolverErrorElsewhere &) {
  } catch (Acoustic::SolverError &e) {
    errors.report(fmt::format("{}: {}", CMD, e.what()));
  }
  errors.raise(FLERR);
  const Acoustic::SolverTimings &timings = krylov ? krylov->last_timings() : mumps->last_timings();
  if (!report_solve(sol, timings, 0.0, MPI_Wtime() - t0)) return false;
  solution = sol.q;
  return true;
}

/* ----------------------------------------------------------------------
   build the network, solve, set every contact's friction factor
------------------------------------------------------------------------- */

void FixAcousticMindlin::update_factors()
{
  const double t0 = MPI_Wtime();
  if (reuse && frequency > 0.0 && last_solution_valid && network_unchanged()) {
    // the network of the last solve, bit for bit: its solution, which the
    // atoms carry, is this one; only the factors go to the histories again
    // (a contact that opened and closed since has a new history)
    stats[NCONTACTS] = static_cast<double>(network->ncontacts_total());
    stats[TIME_GATHER] = MPI_Wtime() - t0;
    stats[TIME_ASSEMBLY] = stats[TIME_FACTORISATION] = stats[TIME_SOLVE] = 0.0;
    stats[NITERATIONS] = 0.0;
    stats[NREUSES] += 1.0;
    unchanged_networks++;
    factors_committed = false;
    const double t1 = MPI_Wtime();
    comm->forward_comm(this);
    evaluate_contacts(true);
    factor_statistics(network->local_contacts());
    const double t2 = MPI_Wtime();
    stats[TIME_UPDATE] = t2 - t1;
    stats[TIME_TOTAL] += t2 - t0;
    last_update = update->ntimestep;
    return;
  }
  if (distributed())
    network->build_local(groupbit, {source_groupbit});
  else
    network->build(groupbit, {source_groupbit});
  stats[NCONTACTS] = static_cast<double>(network->ncontacts_total());
  stats[TIME_GATHER] = MPI_Wtime() - t0;
  stats[TIME_ASSEMBLY] = stats[TIME_FACTORISATION] = stats[TIME_SOLVE] = stats[TIME_UPDATE] = 0.0;
  factors_committed = false;

  int solved = 1;
  if (frequency > 0.0 && distributed()) {
    solved = solve_distributed() ? 1 : 0;
  } else if (frequency > 0.0) {
    std::string failure;
    if (comm->me == 0) solved = solve_drive(failure) ? 1 : 0;
    CollectiveError errors(lmp);
    if (!failure.empty()) errors.report(failure);
    errors.raise(FLERR);
    MPI_Bcast(&solved, 1, MPI_INT, 0, world);
    MPI_Bcast(stats + RESIDUAL, NREUSES - RESIDUAL + 1, MPI_DOUBLE, 0, world);
  }

  const double t1 = MPI_Wtime();
  if (solved) {
    set_amplitudes();
    evaluate_contacts(true);
  }
  last_solution_valid = solved != 0 || last_solution_valid;
  // the network this solution belongs to (reuse: an unchanged network needs no solve)
  if (reuse) solved_network = solved ? network_fingerprint() : 0;
  factor_statistics(network->local_contacts());
  warn_idle_source_wall();
  const double t2 = MPI_Wtime();
  stats[TIME_UPDATE] = t2 - t1;
  stats[TIME_TOTAL] += t2 - t0;
  // only now: an update stopped by an ERROR is not current
  last_update = update->ntimestep;
}

/* ----------------------------------------------------------------------
   DOF amplitudes of the owned atoms and their ghosts, per-atom output
------------------------------------------------------------------------- */

void FixAcousticMindlin::set_amplitudes()
{
  const int nlocal = atom->nlocal;
  if (frequency > 0.0 && distributed()) {
    const LocalNetworkPart &part = network->local_part();
    for (int i = 0; i < nlocal; i++)
      for (int k = 0; k < 2 * ndof; k++) q_atom[i][k] = 0.0;
    for (int g = 0; g < part.num_owned; g++)
      for (int k = 0; k < ndof; k++) {
        q_atom[part.atoms[g]][2 * k] = solution[g * ndof + k].real();
        q_atom[part.atoms[g]][2 * k + 1] = solution[g * ndof + k].imag();
      }
    comm->forward_comm(this);
  } else if (frequency > 0.0) {
    network->scatter(solution, q_atom, groupbit);
    comm->forward_comm(this);
  } else {
    for (int i = 0; i < nlocal; i++)
      for (int k = 0; k < 2 * ndof; k++) q_atom[i][k] = 0.0;
  }
  const int dim = domain->dimension;
  for (int i = 0; i < nlocal; i++) {
    for (int k = 0; k < size_peratom_cols; k++) amplitude_atom[i][k] = 0.0;
    for (int k = 0; k < dim; k++) {
      const std::complex<double> qk(q_atom[i][2 * k], q_atom[i][2 * k + 1]);
      if (damped) {
        amplitude_atom[i][2 * k] = amplitude * qk.real();
        amplitude_atom[i][2 * k + 1] = amplitude * qk.imag();
      } else {
        amplitude_atom[i][k] = amplitude * qk.real();    // the undamped solution is real
      }
    }
  }
}

/* ----------------------------------------------------------------------
   the tangential amplitude of each contact from the DOF amplitudes
   (q_atom, owned and ghost atoms) and one local output row per contact;
   set_factors: the friction factor from that amplitude, into the contact
   history; else the rows show the factors already in the histories
------------------------------------------------------------------------- */

void FixAcousticMindlin::evaluate_contacts(bool set_factors)
{
  const auto &contacts = network->local_contacts();
  tagint *tag = atom->tag;
  if (static_cast<int>(contacts.size()) > maxcontact_rows) {
    maxcontact_rows = static_cast<int>(contacts.size());
    memory->destroy(contact_array);
    memory->create(contact_array, maxcontact_rows, size_local_cols, "acoustic/mindlin:contacts");
  }
  ncontact_rows = 0;
  const int dim = domain->dimension;
  CollectiveError errors(lmp);
  // U_t and s of a contact as the LIGGGHTS styles compute them (acoustic_contact_factor.h)
  Acoustic::ContactFactorInput in;
  in.dimension = dim;
  in.model = (settings.model == Acoustic::ContactModel::Full)
      ? Acoustic::FacadeContactModel::Full
      : Acoustic::FacadeContactModel::Normal;
  in.amplitude = amplitude;
  in.compute_factor = set_factors;
  in.cmu = law.cmu;
  in.mu_min = law.mu_min;
  Acoustic::ContactFactorResult out;
  // the prescribed motion of a wall: the drive (source wall), or none
  double q_source_wall[12] = {0.0}, q_still_wall[12] = {0.0};
  for (int k = 0; k < dim; k++) q_source_wall[2 * k] = direction[k];
  for (const auto &c : contacts) {
    double s = 1.0, ut = 0.0;
    if (frequency > 0.0) {
      // evaluate every contact from its lower to its higher atom ID, so that the
      // two copies of a contact (newton off) get the same factor to the last bit
      // a wall comes second, with its prescribed motion
      const bool flip = (c.wall < 0) && tag[c.i] > tag[c.j];
      const int a = flip ? c.j : c.i, b = flip ? c.i : c.j;
      const double sign = flip ? -1.0 : 1.0;
      in.q_i = q_atom[a];
      in.q_j = (c.wall < 0) ? q_atom[b] : (c.wall == source_wall ? q_source_wall : q_still_wall);
      for (int k = 0; k < 3; k++) in.normal[k] = sign * c.n[k];
      in.radius_i = flip ? c.radj : c.radi;
      in.radius_j = flip ? c.radi : c.radj;
      in.tangential_stiffness = c.kt;
      in.friction_coefficient = c.mu;
      in.normal_force = c.fncrit;
      if (!Acoustic::contact_mindlin_factor(in, out)) {
        errors.report(fmt::format("{}: contact of atoms {} and {}: {}", CMD, tag[c.i], tag[c.j],
                                  out.message));
        continue;    // the factor stays as it was
      }
      ut = out.tangential_amplitude;
      if (set_factors) s = out.factor;
    }
    // a wall contact whose tangential model has no /acoustic variant keeps its friction
    if (!c.factor)
      s = 1.0;
    else if (set_factors)
      GranularContactWalker::set_friction_factor(c.factor, s);
    else
      s = GranularContactWalker::friction_factor(c.factor);
    if (!c.owned) continue;
    double *row = contact_array[ncontact_rows++];
    row[0] = static_cast<double>(tag[c.i]);
    row[1] = (c.wall >= 0) ? 0.0 : static_cast<double>(tag[c.j]);
    row[2] = c.fn;
    row[3] = c.kn;
    row[4] = ut;
    row[5] = s;
  }
  size_local_rows = ncontact_rows;
  array_local = contact_array;
  errors.raise(FLERR);
}

/* ----------------------------------------------------------------------
   everything the solution depends on, on this processor: the contacts of
   the network (atom IDs, normal, stiffnesses) and the grains of the group
   (ID, mass, radius, source or not)
------------------------------------------------------------------------- */

std::uint64_t FixAcousticMindlin::network_fingerprint() const
{
  Fingerprint f;
  const tagint *tag = atom->tag;
  for (const auto &c : network->local_contacts()) {
    if (!c.owned || !(c.kn > 0.0)) continue;
    f.mix(static_cast<std::uint64_t>(tag[c.i]));
    f.mix(static_cast<std::uint64_t>(c.wall >= 0 ? -1 - c.wall : tag[c.j]));
    for (double n : c.n) f.mix(n);
    f.mix(c.kn);
    f.mix(c.kt);
  }
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    f.mix(static_cast<std::uint64_t>(tag[i]));
    f.mix(atom->rmass[i]);
    f.mix(atom->radius[i]);
    f.mix(static_cast<std::uint64_t>((atom->mask[i] & source_groupbit) ? 1 : 0));
  }
  return f.value();
}

// collective: walk the contacts and compare with the network of the last solve
bool FixAcousticMindlin::network_unchanged()
{
  network->collect(groupbit);
  return solved_network != 0 && same_on_every_rank(lmp, network_fingerprint(), solved_network);
}

/* ----------------------------------------------------------------------
   a source wall that touches no grain of the group drives nothing: say so
   (once per fix)
------------------------------------------------------------------------- */

void FixAcousticMindlin::warn_idle_source_wall()
{
  if (source_wall < 0 || frequency == 0.0 || warned_idle_source) return;
  bigint touching = 0, all = 0;
  for (const auto &c : network->local_contacts())
    if (c.owned && c.wall == source_wall && c.kn > 0.0) touching++;
  MPI_Allreduce(&touching, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all > 0) return;
  warned_idle_source = true;
  if (comm->me == 0)
    error->warning(FLERR,
                   "{} {}: the source wall {} touches no grain of group {}: nothing vibrates "
                   "and every friction factor stays 1; bring the grains onto the wall or "
                   "check its position",
                   CMD, id, source_wall_fix, group->names[igroup]);
}

/* ----------------------------------------------------------------------
   statistics of the factors in the contact histories (each contact once)
------------------------------------------------------------------------- */

void FixAcousticMindlin::factor_statistics(const std::vector<GranularContact> &contacts)
{
  double sum = 0.0, minimum = 1.0, nweak = 0.0, ncounted = 0.0;
  for (const auto &c : contacts) {
    if (!c.owned || !c.factor) continue;
    const double s = GranularContactWalker::friction_factor(c.factor);
    sum += s;
    minimum = MIN(minimum, s);
    if (s < 0.5) nweak += 1.0;
    ncounted += 1.0;
  }
  double local[3] = {sum, nweak, ncounted}, global[3];
  MPI_Allreduce(local, global, 3, MPI_DOUBLE, MPI_SUM, world);
  double global_min = 1.0;
  MPI_Allreduce(&minimum, &global_min, 1, MPI_DOUBLE, MPI_MIN, world);
  stats[MEAN_FACTOR] = (global[2] > 0.0) ? global[0] / global[2] : 1.0;
  stats[MIN_FACTOR] = global_min;
  stats[WEAK_FRACTION] = (global[2] > 0.0) ? global[1] / global[2] : 0.0;
}

/* ---------------------------------------------------------------------- */

double FixAcousticMindlin::compute_vector(int n)
{
  // an index from outside (the library interface) may be anything
  if (n < 0 || n >= NVECTOR) return 0.0;
  return stats[n];
}

/* ----------------------------------------------------------------------
   global restart state: a format tag, the step of the last update, the
   statistics and the signature of the settings (two 32-bit halves, exact
   in doubles); files of earlier versions start with the step and hold no
   signature
------------------------------------------------------------------------- */

void FixAcousticMindlin::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  double list[NVECTOR + 4];
  list[0] = RESTART_WITH_ITERATIONS;
  list[1] = static_cast<double>(last_update);
  for (int k = 0; k < NVECTOR; k++) list[k + 2] = stats[k];
  list[NVECTOR + 2] = static_cast<double>(settings_signature >> 32);
  list[NVECTOR + 3] = static_cast<double>(settings_signature & 0xffffffffULL);
  const int size = (NVECTOR + 4) * sizeof(double);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(double), NVECTOR + 4, fp);
}

void FixAcousticMindlin::restart(char *buf)
{
  const auto *list = reinterpret_cast<double *>(buf);
  // the number of statistics in the file: NVECTOR, or those of earlier versions
  int nstats = NVECTOR_BEFORE_ITERATIONS;
  if (list[0] == RESTART_WITH_SIGNATURE || list[0] == RESTART_WITH_ITERATIONS) {
    if (list[0] == RESTART_WITH_ITERATIONS) nstats = NVECTOR;
    list++;
    const std::uint64_t written = (static_cast<std::uint64_t>(list[nstats + 1]) << 32) |
        static_cast<std::uint64_t>(list[nstats + 2]);
    restart_settings_differ = (written != settings_signature);
  }
  last_update = static_cast<bigint>(list[0]);
  factors_committed = true;    // the file's contact histories hold them
  for (int k = 0; k < NVECTOR; k++) stats[k] = (k < nstats) ? list[k + 1] : 0.0;
  // the solver of this process counts from 0: its counts add to those of the writer
  counts_before[0] = stats[NANALYSES];
  counts_before[1] = stats[NFACTORISATIONS];
  counts_before[2] = stats[NREUSES];
}

/* ---------------------------------------------------------------------- */

void FixAcousticMindlin::grow_arrays(int nmax)
{
  memory->grow(q_atom, nmax, 2 * ndof, "acoustic/mindlin:q_atom");
  memory->grow(amplitude_atom, nmax, size_peratom_cols, "acoustic/mindlin:amplitude_atom");
  array_atom = amplitude_atom;
}

void FixAcousticMindlin::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < 2 * ndof; k++) q_atom[j][k] = q_atom[i][k];
  for (int k = 0; k < size_peratom_cols; k++) amplitude_atom[j][k] = amplitude_atom[i][k];
}

int FixAcousticMindlin::pack_exchange(int i, double *buf)
{
  int m = 0;
  for (int k = 0; k < size_peratom_cols; k++) buf[m++] = amplitude_atom[i][k];
  for (int k = 0; k < 2 * ndof; k++) buf[m++] = q_atom[i][k];
  return m;
}

int FixAcousticMindlin::unpack_exchange(int nlocal, double *buf)
{
  int m = 0;
  for (int k = 0; k < size_peratom_cols; k++) amplitude_atom[nlocal][k] = buf[m++];
  for (int k = 0; k < 2 * ndof; k++) q_atom[nlocal][k] = buf[m++];
  return m;
}

/* ----------------------------------------------------------------------
   per-atom restart state: the output amplitudes and the DOF amplitudes
   of the last update
------------------------------------------------------------------------- */

int FixAcousticMindlin::pack_restart(int i, double *buf)
{
  int m = 1;
  for (int k = 0; k < size_peratom_cols; k++) buf[m++] = amplitude_atom[i][k];
  for (int k = 0; k < 2 * ndof; k++) buf[m++] = q_atom[i][k];
  // pack buf[0] this way because other fixes unpack it
  buf[0] = m;
  return m;
}

void FixAcousticMindlin::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  // skip to the nth set of extra values; unpack the nth first values this way
  // because other fixes pack them
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  const int count = static_cast<int>(extra[nlocal][m++]);
  for (int k = 0; k < size_peratom_cols; k++) amplitude_atom[nlocal][k] = extra[nlocal][m++];
  // restart files written before the DOF amplitudes were stored hold none
  const bool with_q = (count == size_restart(nlocal));
  for (int k = 0; k < 2 * ndof; k++) q_atom[nlocal][k] = with_q ? extra[nlocal][m++] : 0.0;
  if (with_q) q_restored = last_solution_valid = true;
}

int FixAcousticMindlin::size_restart(int /*nlocal*/)
{
  return 1 + size_peratom_cols + 2 * ndof;
}

int FixAcousticMindlin::maxsize_restart()
{
  return 1 + size_peratom_cols + 2 * ndof;
}

/* ---------------------------------------------------------------------- */

int FixAcousticMindlin::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/,
                                          int * /*pbc*/)
{
  int m = 0;
  if (comm_mode == COMM_HALO) {
    for (int ii = 0; ii < n; ii++)
      for (int k = 0; k < halo_width; k++)
        buf[m++] = halo_values[static_cast<std::size_t>(list[ii]) * halo_width + k];
    return m;
  }
  for (int ii = 0; ii < n; ii++)
    for (int k = 0; k < 2 * ndof; k++) buf[m++] = q_atom[list[ii]][k];
  return m;
}

void FixAcousticMindlin::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  if (comm_mode == COMM_HALO) {
    for (int i = first; i < first + n; i++)
      for (int k = 0; k < halo_width; k++)
        halo_values[static_cast<std::size_t>(i) * halo_width + k] = buf[m++];
    return;
  }
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < 2 * ndof; k++) q_atom[i][k] = buf[m++];
}

/* ----------------------------------------------------------------------
   reverse communication: only the halo exchanges of the distributed solve
------------------------------------------------------------------------- */

int FixAcousticMindlin::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < halo_width; k++)
      buf[m++] = halo_values[static_cast<std::size_t>(i) * halo_width + k];
  return m;
}

void FixAcousticMindlin::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int ii = 0; ii < n; ii++)
    for (int k = 0; k < halo_width; k++)
      halo_values[static_cast<std::size_t>(list[ii]) * halo_width + k] += buf[m++];
}

double FixAcousticMindlin::memory_usage()
{
  double bytes = (double) atom->nmax * (2 * ndof + size_peratom_cols) * sizeof(double);
  bytes += (double) maxcontact_rows * size_local_cols * sizeof(double);
  return bytes;
}
