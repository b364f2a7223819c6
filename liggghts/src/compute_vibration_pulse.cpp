/* ----------------------------------------------------------------------
    ACOUSTIC for LIGGGHTS-PUBLIC 3.8: compute vibration/pulse (see the
    header).

    LIGGGHTS is open-source, distributed under the terms of the GNU Public
    License, version 2 or later.  This file is part of the ACOUSTIC
    package and distributed under the same terms.
------------------------------------------------------------------------- */

#include "compute_vibration_pulse.h"

#include "acoustic_liggghts_network.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "memory.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;

namespace {

const int SIGNAL_COLUMNS = 2;    // time, F_sig
const char *const ENDPOINTS[3] = {"source", "detector", "fixed"};

// rank 0 reports the progress of a long integration
struct Progress {
  LAMMPS *lmp;
  const std::string *caller;
};

void report_progress(long done, long total, void *data)
{
  const Progress *p = static_cast<const Progress *>(data);
  if (p->lmp->screen)
    fprintf(p->lmp->screen, "%s: %ld of %ld integration steps done\n", p->caller->c_str(), done,
            total);
  if (p->lmp->logfile)
    fprintf(p->lmp->logfile, "%s: %ld of %ld integration steps done\n", p->caller->c_str(), done,
            total);
}

void broadcast_values(MPI_Comm world, std::vector<double> &values)
{
  int n = static_cast<int>(values.size());
  MPI_Bcast(&n, 1, MPI_INT, 0, world);
  values.resize(n);
  if (n) MPI_Bcast(&values[0], n, MPI_DOUBLE, 0, world);
}

}    // namespace

/* ---------------------------------------------------------------------- */

ComputeVibrationPulse::ComputeVibrationPulse(LAMMPS *lmp, int &iarg, int narg, char **arg) :
    Compute(lmp, iarg, narg, arg), direction_given(false), ndof(0), network(NULL),
    solved_step(-1), signal(NULL), snapshot_atom(NULL), nmax(0)
{
  caller = std::string("compute vibration/pulse ") + id;
  groupbits[0] = groupbits[1] = groupbits[2] = 0;
  walls[0] = walls[1] = -1;
  wall_is_mesh[0] = wall_is_mesh[1] = false;
  AcousticLiggghtsArguments args(lmp, caller, narg, arg, iarg);
  parse_endpoint(args, 0, "source");
  parse_endpoint(args, 1, "detector");

  const int dim = domain->dimension;
  double direction[3] = {0.0, 0.0, 0.0};
  direction[dim == 3 ? 2 : 1] = 1.0;
  options.duration = -1.0;
  while (args.more()) {
    if (args.network(settings, true)) continue;
    if (args.take("direction", 3)) {
      for (int k = 0; k < 3; k++) direction[k] = args.number(1 + k);
      direction_given = true;
    } else if (args.take("initial", 1)) {
      if (strcmp(args.word(1), "velocity") != 0 && strcmp(args.word(1), "displacement") != 0)
        args.error_all("keyword initial must be velocity or displacement, got '%s'", args.word(1));
      options.initial = args.word(1);
    } else if (args.take("method", 1)) {
      const char *m = args.word(1);
      if (strcmp(m, "auto") != 0 && strcmp(m, "modes") != 0 && strcmp(m, "integrate") != 0)
        args.error_all("keyword method must be auto, modes or integrate, got '%s'", m);
      options.method = m;
    } else if (args.take("duration", 1)) {
      options.duration = args.number(1);
      if (options.duration <= 0.0)
        args.error_all("duration must be > 0 (time units), got %s", args.word(1));
    } else if (args.take("samples", 1)) {
      options.samples = args.integer(1);
      if (options.samples < 2 || options.samples > 10000000)
        args.error_all("samples must be in [2, 1e7], got %d", options.samples);
    } else if (args.take("timestep", 1)) {
      options.time_step = args.number(1);
      if (options.time_step <= 0.0) args.error_all("timestep must be > 0, got %s", args.word(1));
    } else if (args.take("max_steps", 1)) {
      const double steps = args.number(1);
      if (!(steps >= 1.0 && steps <= 9e18))
        args.error_all("max_steps must be in [1, 9e18], got %s", args.word(1));
      options.max_steps = static_cast<long>(steps);
    } else if (args.take("snapshot", 1)) {
      options.snapshot_time = args.number(1);
      if (options.snapshot_time < 0.0)
        args.error_all("snapshot time must be >= 0, got %s", args.word(1));
    } else if (args.take("fixed", 1)) {
      groupbits[2] = args.group_bit(1);
      group_names[2] = args.word(1);
    } else {
      args.unknown("direction, initial, method, duration, samples, timestep, max_steps, "
                   "snapshot, fixed, stiffness, kappa_scale, ratio, model, damping");
    }
    args.next();
  }
  if (!settings.stiffness_given)
    args.error_all("keyword stiffness hertz E nu is required in LIGGGHTS (stiffness pair is not "
                   "available yet)");
  if (options.duration < 0.0) args.error_all("give the time to follow the pulse with duration T");
  if (options.snapshot_time > options.duration)
    args.error_all("the snapshot time %g is after the duration %g", options.snapshot_time,
                   options.duration);
  // the unit direction, as the LAMMPS compute computes it
  if (dim == 2 && direction[2] != 0.0) args.error_all("in 2D the direction must lie in the xy plane");
  const double largest =
      std::max(fabs(direction[0]), std::max(fabs(direction[1]), fabs(direction[2])));
  if (largest == 0.0) args.error_all("direction must not be the zero vector");
  for (int k = 0; k < 3; k++) direction[k] /= largest;
  const double norm =
      sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  for (int k = 0; k < 3; k++) options.direction[k] = direction[k] / norm;
  if (options.method == "modes" && settings.damping > 0.0)
    args.error_all("method modes needs an undamped network; use method integrate with damping");

  ndof = Acoustic::facade_dofs_per_grain(dim, settings.model);
  options.dimension = dim;
  options.model = settings.model;
  options.damping_ratio = settings.damping;
  network = new AcousticLiggghtsNetwork(lmp, caller);
  network->set_stiffness(settings.youngs_modulus, settings.poisson_ratio, settings.kappa_scale,
                         settings.ratio);

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
  for (int k = 0; k < NVECTOR; k++) info[k] = 0.0;
  if (options.snapshot_time >= 0.0) {
    peratom_flag = 1;
    size_peratom_cols = 3;
  }
}

ComputeVibrationPulse::~ComputeVibrationPulse()
{
  delete network;
  memory->destroy(signal);
  memory->destroy(snapshot_atom);
}

/* ----------------------------------------------------------------------
   source|detector group-ID | wall fix-ID | mesh fix-ID
------------------------------------------------------------------------- */

void ComputeVibrationPulse::parse_endpoint(AcousticLiggghtsArguments &args, int which,
                                           const char *word)
{
  if (!args.more() || strcmp(args.keyword(), word) != 0)
    args.error_all("expected compute ID group-ID vibration/pulse source group-ID|wall "
                   "fix-ID|mesh fix-ID detector group-ID|wall fix-ID|mesh fix-ID stiffness "
                   "hertz E nu duration T [keyword value ...], got '%s' where '%s' belongs",
                   args.more() ? args.keyword() : "", word);
  args.take(word, 1);
  if (strcmp(args.word(1), "wall") == 0 || strcmp(args.word(1), "mesh") == 0) {
    args.take(word, 2);
    wall_is_mesh[which] = strcmp(args.word(1), "mesh") == 0;
    wall_ids[which] = args.word(2);
    args.next();
    return;
  }
  groupbits[which] = args.group_bit(1);
  group_names[which] = args.word(1);
  args.next();
}

/* ----------------------------------------------------------------------
   the source, detector and fixed groups: atoms in the compute group, all
   of them, and no atom in two of them
------------------------------------------------------------------------- */

void ComputeVibrationPulse::check_groups()
{
  char what[1024];
  for (int e = 0; e < 3; e++) {
    if (group_names[e].empty()) continue;
    const int igroup_end = group->find(group_names[e].c_str());
    if (igroup_end < 0) {
      snprintf(what, sizeof(what), "%s: %s group %s no longer exists", caller.c_str(),
               ENDPOINTS[e], group_names[e].c_str());
      error->all(FLERR, what);
    }
    groupbits[e] = group->bitmask[igroup_end];
  }
  double local[9] = {0.0}, counts[9];
  for (int i = 0; i < atom->nlocal; i++) {
    const int m = atom->mask[i];
    for (int e = 0; e < 3; e++) {
      if (!(m & groupbits[e])) continue;
      local[(m & groupbit) ? e : 3 + e] += 1.0;
      for (int f = e + 1; f < 3; f++)
        if (m & groupbits[f]) local[6 + e + f - 1] += 1.0;
    }
  }
  MPI_Allreduce(local, counts, 9, MPI_DOUBLE, MPI_SUM, world);
  for (int e = 0; e < 3; e++) {
    if (group_names[e].empty()) continue;
    if (counts[e] == 0.0) {
      snprintf(what, sizeof(what), "%s: %s group %s has no atom in the compute group %s",
               caller.c_str(), ENDPOINTS[e], group_names[e].c_str(), group->names[igroup]);
      error->all(FLERR, what);
    }
    if (counts[3 + e] > 0.0) {
      snprintf(what, sizeof(what),
               "%s: %.0f atoms of the %s group %s are not in the compute group %s; they must "
               "all belong to it",
               caller.c_str(), counts[3 + e], ENDPOINTS[e], group_names[e].c_str(),
               group->names[igroup]);
      error->all(FLERR, what);
    }
  }
  for (int e = 0; e < 3; e++)
    for (int f = e + 1; f < 3; f++)
      if (counts[6 + e + f - 1] > 0.0) {
        snprintf(what, sizeof(what), "%s: %.0f atoms are in both the %s group %s and the %s group %s",
                 caller.c_str(), counts[6 + e + f - 1], ENDPOINTS[e], group_names[e].c_str(),
                 ENDPOINTS[f], group_names[f].c_str());
        error->all(FLERR, what);
      }
}

/* ---------------------------------------------------------------------- */

void ComputeVibrationPulse::init()
{
  network->init(false);
  check_groups();
  char what[1024];
  for (int e = 0; e < 2; e++) {
    walls[e] = -1;
    if (wall_ids[e].empty()) continue;
    const char *kind = wall_is_mesh[e] ? "mesh" : "wall";
    walls[e] = network->wall_index(wall_ids[e]);
    if (walls[e] < 0) {
      snprintf(what, sizeof(what),
               "%s: %s %s %s is not a wall of the vibration network (give 'wall <fix-ID>' of a "
               "fix wall/gran primitive wall, or 'mesh <fix-ID>' of a fix mesh/surface used by "
               "a fix wall/gran ... mesh)",
               caller.c_str(), ENDPOINTS[e], kind, wall_ids[e].c_str());
      error->all(FLERR, what);
    }
    const bool is_mesh = network->walls()[walls[e]].mesh != NULL;
    if (is_mesh != wall_is_mesh[e]) {
      snprintf(what, sizeof(what), "%s: %s %s %s is a %s: write '%s %s %s'", caller.c_str(),
               ENDPOINTS[e], kind, wall_ids[e].c_str(),
               is_mesh ? "mesh (fix mesh/surface)" : "primitive wall (fix wall/gran)",
               ENDPOINTS[e], is_mesh ? "mesh" : "wall", wall_ids[e].c_str());
      error->all(FLERR, what);
    }
  }
  if (walls[0] >= 0 && walls[0] == walls[1]) {
    snprintf(what, sizeof(what), "%s: the source and the detector are the same wall %s",
             caller.c_str(), wall_ids[0].c_str());
    error->all(FLERR, what);
  }
  // the default direction with a source wall: its normal, as in LAMMPS
  if (walls[0] >= 0 && !direction_given) {
    const int axis = network->walls()[walls[0]].plane_axis;
    if (axis < 0) {
      snprintf(what, sizeof(what),
               "%s: source mesh %s has no single normal; give the direction of the pulse "
               "with the keyword direction",
               caller.c_str(), wall_ids[0].c_str());
      error->all(FLERR, what);
    }
    for (int k = 0; k < 3; k++) options.direction[k] = (k == axis) ? 1.0 : 0.0;
  }
  solved_step = -1;    // the packing may have changed since the last run
}

/* ----------------------------------------------------------------------
   walk, gather, solve on rank 0, broadcast; once per timestep
------------------------------------------------------------------------- */

void ComputeVibrationPulse::solve()
{
  if (solved_step == update->ntimestep) return;
  network->collect(groupbit);
  AcousticLiggghtsNetwork::Gathered g;
  std::vector<int> flagbits(groupbits, groupbits + 3);
  network->gather(groupbit, flagbits, settings.model, g);
  std::string failure;
  Acoustic::GatheredPulseResult r;
  if (comm->me == 0) {
    Acoustic::GatheredPulseInput in = options;
    in.grains.swap(g.input.grains);
    in.contacts.swap(g.input.contacts);
    for (size_t k = 0; k < g.flag.size(); k++) {
      if (g.flag[k] & 1) in.source.push_back(static_cast<int>(k));
      if (g.flag[k] & 2) in.detector.push_back(static_cast<int>(k));
      if (g.flag[k] & 4) in.fixed.push_back(static_cast<int>(k));
    }
    // a wall is the node after every atom (the walker's order)
    const int natoms = static_cast<int>(g.tags.size());
    if (walls[0] >= 0) in.source.push_back(natoms + walls[0]);
    if (walls[1] >= 0) in.detector.push_back(natoms + walls[1]);
    Progress progress = {lmp, &caller};
    in.progress = report_progress;
    in.progress_data = &progress;
    if (Acoustic::solve_gathered_pulse(in, r)) {
      for (int k = 0; k < options.samples; k++) {
        signal[k][0] = r.times[k];
        signal[k][1] = r.signal[k];
      }
      info[TIME_STEP] = r.time_step;
      info[STEPS] = static_cast<double>(r.steps);
      info[FREE_DOFS] = r.num_free;
    } else {
      failure = r.message;
    }
  }
  int length = static_cast<int>(failure.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, world);
  if (length > 0) {
    std::vector<char> text(length + 1, '\0');
    if (comm->me == 0) std::copy(failure.begin(), failure.end(), text.begin());
    MPI_Bcast(&text[0], length + 1, MPI_CHAR, 0, world);
    std::string what = caller + ": " + &text[0];
    error->all(FLERR, what.c_str());
  }
  MPI_Bcast(&signal[0][0], options.samples * SIGNAL_COLUMNS, MPI_DOUBLE, 0, world);
  MPI_Bcast(info, NVECTOR, MPI_DOUBLE, 0, world);
  if (peratom_flag) {
    snapshot.swap(r.snapshot);
    tags.swap(g.tags);
    broadcast_values(world, snapshot);
    broadcast_values(world, tags);
  }
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
  const int dim = domain->dimension;
  for (int i = 0; i < atom->nlocal; i++) {
    for (int k = 0; k < size_peratom_cols; k++) snapshot_atom[i][k] = 0.0;
    if (!(atom->mask[i] & groupbit)) continue;
    const int g = AcousticLiggghtsNetwork::grain_index(tags, atom->tag[i]);
    if (g < 0) continue;
    for (int k = 0; k < dim; k++) snapshot_atom[i][k] = snapshot[static_cast<size_t>(g) * ndof + k];
  }
}

/* ---------------------------------------------------------------------- */

double ComputeVibrationPulse::memory_usage()
{
  double bytes = static_cast<double>(options.samples) * SIGNAL_COLUMNS * sizeof(double);
  if (peratom_flag) bytes += static_cast<double>(nmax) * size_peratom_cols * sizeof(double);
  bytes += static_cast<double>(snapshot.size() + tags.size()) * sizeof(double);
  return bytes;
}
