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

   Response of the frozen contact network to a delta pulse of a source (a
   group of atoms or a plane of fix wall/gran): the force the grains exert
   on a detector along the pulse's direction, as paper 003's F_sig(t).
   The network is the one fix acoustic/mindlin drives (VibrationNetwork),
   gathered to rank 0 and solved there by the ACOUSTIC numerics.
------------------------------------------------------------------------- */

#include "compute_vibration_pulse.h"

#include "citations_acoustic.h"
#include "citeme.h"

#include "acoustic_solver_error.h"
#include "command_arguments.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <new>

using namespace LAMMPS_NS;

static const char CMD[] = "compute vibration/pulse";
static constexpr int SIGNAL_COLUMNS = 2;             // time, F_sig
static constexpr int AUTO_INTEGRATE_DOFS = 10000;    // method auto: integrate above this

/* ---------------------------------------------------------------------- */

ComputeVibrationPulse::ComputeVibrationPulse(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), fixed_groupbit(0), direction_given(false), method_given(false),
    ndof(0), solved_step(-1), signal(nullptr), snapshot_atom(nullptr), nmax(0)
{
  if (lmp->citeme) lmp->citeme->add(AcousticCitations::confined_wave_propagation);
  CommandArguments args(lmp, CMD, narg, arg, 3);
  parse_endpoint(args, "source", source);
  parse_endpoint(args, "detector", detector);

  const int dim = domain->dimension;
  direction[0] = direction[1] = direction[2] = 0.0;
  direction[dim == 3 ? 2 : 1] = 1.0;
  options.duration = -1.0;
  while (args.more()) {
    if (settings.parse(args, true)) continue;
    if (args.take("direction", 3)) {
      for (int k = 0; k < 3; k++) direction[k] = args.number(1 + k);
      direction_given = true;
    } else if (args.take("initial", 1)) {
      try {
        options.initial = Acoustic::pulse_initial_from_name(args.word(1));
      } catch (Acoustic::SolverError &e) {
        args.reject(FLERR, 1, "{}", e.what());
      }
    } else if (args.take("method", 1)) {
      if (strcmp(args.word(1), "auto") != 0) {
        try {
          options.method = Acoustic::pulse_method_from_name(args.word(1));
        } catch (Acoustic::SolverError &e) {
          args.reject(FLERR, 1, "{} (or auto)", e.what());
        }
        method_given = true;
      }
    } else if (args.take("duration", 1)) {
      options.duration = args.number(1);
      if (options.duration <= 0.0)
        args.reject(FLERR, 1, "duration must be > 0 (time units), got {}", options.duration);
    } else if (args.take("samples", 1)) {
      options.samples = args.integer(1);
      if (options.samples < 2 || options.samples > 10000000)
        args.reject(FLERR, 1, "samples must be in [2, 1e7], got {}", options.samples);
    } else if (args.take("timestep", 1)) {
      options.time_step = args.number(1);
      if (options.time_step <= 0.0)
        args.reject(FLERR, 1, "timestep must be > 0, got {}", options.time_step);
    } else if (args.take("max_steps", 1)) {
      const double steps = args.number(1);
      if (!(steps >= 1.0 && steps <= 9e18))
        args.reject(FLERR, 1, "max_steps must be in [1, 9e18], got {}", args.word(1));
      options.max_steps = static_cast<long>(steps);
    } else if (args.take("snapshot", 1)) {
      options.snapshot_time = args.number(1);
      if (options.snapshot_time < 0.0)
        args.reject(FLERR, 1, "snapshot time must be >= 0, got {}", options.snapshot_time);
    } else if (args.take("fixed", 1)) {
      fixed_group = args.group_name(1);
    } else {
      args.unknown("direction, initial, method, duration, samples, timestep, max_steps, snapshot, "
                   "fixed, stiffness, kappa_scale, ratio, model, damping, region_walls");
    }
    args.next();
  }
  if (options.duration < 0.0)
    error->all(FLERR, "{}: give the time to follow the pulse with duration T", CMD);
  if (options.snapshot_time > options.duration)
    error->all(FLERR, "{}: the snapshot time {} is after the duration {}", CMD,
               options.snapshot_time, options.duration);
  if (dim == 2 && direction[2] != 0.0)
    error->all(FLERR, "{}: in 2D the direction must lie in the xy plane", CMD);
  const double largest = MAX(fabs(direction[0]), MAX(fabs(direction[1]), fabs(direction[2])));
  if (largest == 0.0) error->all(FLERR, "{}: direction must not be the zero vector", CMD);
  for (double &d : direction) d /= largest;
  const double norm =
      sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  for (double &d : direction) d /= norm;
  if (method_given && options.method == Acoustic::PulseMethod::Modes &&
      settings.damping_ratio > 0.0)
    error->all(FLERR,
               "{}: method modes needs an undamped network; use method "
               "integrate with damping",
               CMD);

  ndof = Acoustic::dofs_per_grain(dim, settings.model);
  network.reset(new VibrationNetwork(lmp, settings, CMD));
  // between runs the compute must know whether the system is still that of
  // the last run
  network->add_state_fix(id, group->names[igroup]);

  // outputs
  array_flag = 1;
  size_array_rows = options.samples;
  size_array_cols = SIGNAL_COLUMNS;
  extarray = 0;
  memory->create(signal, options.samples, SIGNAL_COLUMNS, "vibration/pulse:signal");
  for (int k = 0; k < options.samples; k++) signal[k][0] = signal[k][1] = 0.0;
  array = signal;
  vector_flag = 1;
  size_vector = NVECTOR;
  extvector = 0;
  vector = info;
  for (double &v : info) v = 0.0;
  size_peratom_cols = 0;
  if (options.snapshot_time >= 0.0) {
    peratom_flag = 1;
    size_peratom_cols = 3;
  }
}

/* ---------------------------------------------------------------------- */

ComputeVibrationPulse::~ComputeVibrationPulse()
{
  if (network) network->delete_state_fix();
  memory->destroy(signal);
  memory->destroy(snapshot_atom);
}

/* ----------------------------------------------------------------------
   source|detector group-ID | wall fix-ID
------------------------------------------------------------------------- */

void ComputeVibrationPulse::parse_endpoint(CommandArguments &args, const char *word, Endpoint &end)
{
  if (!args.more() || strcmp(args.keyword(), word) != 0)
    error->all(FLERR, args.more() ? args.index() : Error::NOPOINTER,
               "{}: expected compute ID group-ID vibration/pulse source "
               "group-ID|wall fix-ID detector group-ID|wall fix-ID [keyword "
               "value ...], got '{}' where '{}' belongs",
               CMD, args.more() ? args.keyword() : "", word);
  args.expect(word, 1);
  if (strcmp(args.word(1), "wall") == 0) {
    args.expect(word, 2);
    end.wall_fix = args.wall_fix(2);
  } else {
    end.group = args.group_name(1);
  }
  args.next();
}

/* ---------------------------------------------------------------------- */

void ComputeVibrationPulse::init_endpoint(Endpoint &end, const char *word)
{
  end.groupbit = 0;
  end.wall = -1;
  if (!end.wall_fix.empty()) {
    end.wall = network->wall_of_fix(end.wall_fix);
    if (end.wall < 0)
      error->all(FLERR,
                 "{}: {} wall {} is not a wall of the vibration network (it must be a fix "
                 "wall/gran xplane, yplane or zplane, or a fix wall/gran/region)",
                 CMD, word, end.wall_fix);
    return;
  }
  const int igroup_end = group->find(end.group);
  if (igroup_end < 0) error->all(FLERR, "{}: {} group {} no longer exists", CMD, word, end.group);
  end.groupbit = group->bitmask[igroup_end];
  bigint counts_local[2] = {0, 0}, counts[2];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & end.groupbit)) continue;
    if (atom->mask[i] & groupbit)
      counts_local[0]++;
    else
      counts_local[1]++;
  }
  MPI_Allreduce(counts_local, counts, 2, MPI_LMP_BIGINT, MPI_SUM, world);
  if (counts[0] == 0)
    error->all(FLERR, "{}: {} group {} has no atom in the compute group {}", CMD, word, end.group,
               group->names[igroup]);
  if (counts[1] > 0)
    error->all(FLERR,
               "{}: {} atoms of the {} group {} are not in the compute group {}; they must "
               "all belong to it",
               CMD, counts[1], word, end.group, group->names[igroup]);
}

/* ---------------------------------------------------------------------- */

void ComputeVibrationPulse::init()
{
  network->init();
  init_endpoint(source, "source");
  init_endpoint(detector, "detector");
  if (source.wall >= 0 && !direction_given) network->wall_normal(source.wall, direction);
  if (source.wall >= 0 && source.wall == detector.wall)
    error->all(FLERR, "{}: the source and the detector are the same wall {}", CMD, source.wall_fix);
  if (source.groupbit && detector.groupbit) {
    bigint common_local = 0, common = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & source.groupbit) && (atom->mask[i] & detector.groupbit)) common_local++;
    MPI_Allreduce(&common_local, &common, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    if (common > 0)
      error->all(FLERR, "{}: {} atoms are in both the source group {} and the detector group {}",
                 CMD, common, source.group, detector.group);
  }
  fixed_groupbit = 0;
  if (!fixed_group.empty()) {
    const int ifixed = group->find(fixed_group);
    if (ifixed < 0) error->all(FLERR, "{}: fixed group {} no longer exists", CMD, fixed_group);
    fixed_groupbit = group->bitmask[ifixed];
  }
  solved_step = -1;    // the packing may have changed since the last run
}

/* ----------------------------------------------------------------------
   rank 0: the network just built as a pulse problem; its walls and the
   source, detector and fixed atoms are prescribed
------------------------------------------------------------------------- */

Acoustic::PulseProblem ComputeVibrationPulse::pulse_problem() const
{
  const Acoustic::ContactNetwork &net = network->network();
  Acoustic::PulseProblem p;
  p.stiffness = net.stiffness_matrix();
  if (net.has_damping()) p.damping = net.damping_matrix();
  p.mass = net.mass_diagonal();
  p.dofs_per_grain = ndof;
  p.dimension = domain->dimension;
  p.direction = Eigen::Vector3d(direction[0], direction[1], direction[2]);
  p.source = Eigen::VectorXd::Zero(net.num_dofs());
  p.detector = Eigen::VectorXd::Zero(net.num_dofs());
  auto prescribe = [&](int g, Eigen::VectorXd *pattern) {
    for (int k = 0; k < ndof; k++) {
      p.prescribed_dofs.push_back(net.dof(g, k));
      if (pattern && k < p.dimension) (*pattern)[net.dof(g, k)] = direction[k];
    }
  };
  // markers 0, 1, 2: the source, detector and fixed groups
  for (int g : network->marked_grains(0)) prescribe(g, &p.source);
  for (int g : network->marked_grains(1)) prescribe(g, &p.detector);
  for (int g : network->marked_grains(2)) prescribe(g, nullptr);
  const std::vector<int> &walls = network->wall_nodes();
  for (std::size_t k = 0; k < walls.size(); k++) {
    Eigen::VectorXd *pattern = nullptr;
    if (static_cast<int>(k) == source.wall) pattern = &p.source;
    if (static_cast<int>(k) == detector.wall) pattern = &p.detector;
    prescribe(walls[k], pattern);
  }
  return p;
}

/* ----------------------------------------------------------------------
   rank 0: the pulse response; returns an error message, empty on success
------------------------------------------------------------------------- */

std::string ComputeVibrationPulse::solve_on_rank0()
{
  try {
    const Acoustic::PulseProblem p = pulse_problem();
    Acoustic::PulseOptions o = options;
    if (!method_given) {
      const long free = p.mass.size() - static_cast<long>(p.prescribed_dofs.size());
      o.method = (settings.damping_ratio > 0.0 || free > AUTO_INTEGRATE_DOFS)
          ? Acoustic::PulseMethod::Integrate
          : Acoustic::PulseMethod::Modes;
    }
    // a long integration reports its progress (rank 0 alone runs it)
    o.progress = [this](long done, long total) {
      utils::logmesg(lmp, "{} {}: {} of {} integration steps done\n", CMD, id, done, total);
    };
    const Acoustic::PulseResponse r = Acoustic::pulse_response(p, o);
    for (int k = 0; k < options.samples; k++) {
      signal[k][0] = r.times[k];
      signal[k][1] = r.signal[k];
    }
    info[TIME_STEP] = r.time_step;
    info[STEPS] = static_cast<double>(r.steps);
    info[FREE_DOFS] = r.num_free;
    snapshot = r.snapshot;
  } catch (Acoustic::SolverError &e) {
    return e.what();
  } catch (std::bad_alloc &) {
    return "out of memory; use method integrate for large networks";
  }
  return std::string();
}

/* ----------------------------------------------------------------------
   build the network and solve, once per timestep
------------------------------------------------------------------------- */

void ComputeVibrationPulse::solve()
{
  network->require_current_state(fmt::format("{} {}", CMD, id));
  if (solved_step == update->ntimestep) return;
  network->build(groupbit, {source.groupbit, detector.groupbit, fixed_groupbit});
  std::string failure;
  if (comm->me == 0) failure = solve_on_rank0();
  int length = static_cast<int>(failure.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, world);
  if (length > 0) {
    failure.resize(length);
    MPI_Bcast(&failure[0], length, MPI_CHAR, 0, world);
    error->all(FLERR, "{}: {}", CMD, failure);
  }
  MPI_Bcast(&signal[0][0], options.samples * SIGNAL_COLUMNS, MPI_DOUBLE, 0, world);
  MPI_Bcast(info, NVECTOR, MPI_DOUBLE, 0, world);
  solved_step = update->ntimestep;
}

/* ---------------------------------------------------------------------- */

void ComputeVibrationPulse::compute_vector()
{
  invoked_vector = update->ntimestep;
  solve();
}

void ComputeVibrationPulse::compute_array()
{
  invoked_array = update->ntimestep;
  solve();
}

/* ----------------------------------------------------------------------
   displacement of each atom at the snapshot time (0 outside the group and
   for prescribed atoms)
------------------------------------------------------------------------- */

void ComputeVibrationPulse::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  solve();
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(snapshot_atom);
    memory->create(snapshot_atom, nmax, size_peratom_cols, "vibration/pulse:snapshot_atom");
    array_atom = snapshot_atom;
  }
  Eigen::VectorXd values;
  if (comm->me == 0) values = snapshot;
  network->scatter_displacements(values, snapshot_atom, size_peratom_cols, groupbit);
}

/* ---------------------------------------------------------------------- */

double ComputeVibrationPulse::memory_usage()
{
  double bytes = static_cast<double>(options.samples) * SIGNAL_COLUMNS * sizeof(double);
  if (peratom_flag) bytes += static_cast<double>(nmax) * size_peratom_cols * sizeof(double);
  bytes += static_cast<double>(snapshot.size()) * sizeof(double);
  return bytes;
}
