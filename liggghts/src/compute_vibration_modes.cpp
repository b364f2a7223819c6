/* ----------------------------------------------------------------------
    ACOUSTIC for LIGGGHTS-PUBLIC 3.8: compute vibration/modes (see the
    header).

    LIGGGHTS is open-source, distributed under the terms of the GNU Public
    License, version 2 or later.  This file is part of the ACOUSTIC
    package and distributed under the same terms.
------------------------------------------------------------------------- */

#include "compute_vibration_modes.h"

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

const int HISTOGRAM_COLUMNS = 3;    // bin centre, density, error of the density
const int MODE_COLUMNS = 3;         // mode index, frequency, participation ratio

// the string to every rank
void broadcast_text(MPI_Comm world, std::string &text)
{
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, world);
  std::vector<char> buffer(length + 1, '\0');
  if (length) std::copy(text.begin(), text.end(), buffer.begin());
  MPI_Bcast(&buffer[0], length + 1, MPI_CHAR, 0, world);
  text.assign(&buffer[0], length);
}

// a vector of doubles of rank 0 to every rank
void broadcast_values(MPI_Comm world, std::vector<double> &values)
{
  int n = static_cast<int>(values.size());
  MPI_Bcast(&n, 1, MPI_INT, 0, world);
  values.resize(n);
  if (n) MPI_Bcast(&values[0], n, MPI_DOUBLE, 0, world);
}

}    // namespace

/* ---------------------------------------------------------------------- */

ComputeVibrationModes::ComputeVibrationModes(LAMMPS *lmp, int &iarg, int narg, char **arg) :
    Compute(lmp, iarg, narg, arg), fixed_groupbit(0), selected_mode(0), ndof(0), nfree_defined(0),
    network(NULL), solved_step(-1), solved_with_shapes(false), nzero(0.0), histogram(NULL),
    mode_rows(NULL), nmode_rows_max(0), shape_atom(NULL), nmax(0)
{
  caller = std::string("compute vibration/modes ") + id;
  AcousticLiggghtsArguments args(lmp, caller, narg, arg, iarg);
  bool nmodes_set = false, kpm_set = false;
  while (args.more()) {
    if (args.network(settings, false)) continue;
    if (args.take("fixed", 1)) {
      args.group_bit(1);
      fixed_group = args.word(1);
    } else if (args.take("method", 1)) {
      const char *m = args.word(1);
      if (strcmp(m, "dense") != 0 && strcmp(m, "lanczos") != 0 && strcmp(m, "kpm") != 0)
        args.error_all("keyword method must be dense, lanczos or kpm, got '%s'", m);
      options.method = m;
    } else if (args.take("nmodes", 1)) {
      options.nmodes = args.integer(1);
      if (options.nmodes <= 0) args.error_all("nmodes must be > 0, got %d", options.nmodes);
      nmodes_set = true;
    } else if (args.take("bins", 3)) {
      options.bins = args.integer(1);
      options.fmin = args.number(2);
      options.fmax = args.number(3);
      if (options.bins < 1 || options.bins > 1000000 || !(options.fmin >= 0.0) ||
          !(options.fmin < options.fmax))
        args.error_all("bins Nb fmin fmax needs 1 <= Nb <= 1000000 and 0 <= fmin < fmax, got "
                       "%s %s %s", args.word(1), args.word(2), args.word(3));
    } else if (args.take("mode", 1)) {
      selected_mode = args.integer(1);
      if (selected_mode < 1)
        args.error_all("mode must be >= 1 (modes are numbered from 1 upwards in frequency), "
                       "got %d", selected_mode);
    } else if (args.take("moments", 1)) {
      options.kpm_moments = args.integer(1);
      if (options.kpm_moments < 2) args.error_all("moments must be >= 2, got %d", options.kpm_moments);
      kpm_set = true;
    } else if (args.take("vectors", 1)) {
      options.kpm_vectors = args.integer(1);
      if (options.kpm_vectors < 2)
        args.error_all("vectors must be >= 2 (the error estimate needs two), got %d",
                       options.kpm_vectors);
      kpm_set = true;
    } else if (args.take("seed", 1)) {
      const int seed = args.integer(1);
      if (seed <= 0) args.error_all("seed must be > 0, got %d", seed);
      options.kpm_seed = static_cast<unsigned long>(seed);
      kpm_set = true;
    } else {
      args.unknown("stiffness, kappa_scale, ratio, model, fixed, method, nmodes, bins, mode, "
                   "moments, vectors, seed");
    }
    args.next();
  }
  if (!settings.stiffness_given)
    args.error_all("keyword stiffness hertz E nu is required in LIGGGHTS (stiffness pair is not "
                   "available yet)");
  const bool kpm = options.method == "kpm", lanczos = options.method == "lanczos";
  if (nmodes_set && !lanczos)
    args.error_all("nmodes applies to method lanczos only (dense computes every mode); add "
                   "method lanczos or remove nmodes");
  if (kpm_set && !kpm) args.error_all("moments, vectors and seed apply to method kpm only");
  if (kpm && options.bins == 0)
    args.error_all("method kpm computes the density of states only; give its range with bins "
                   "Nb fmin fmax");
  if (kpm && selected_mode > 0)
    args.error_all("method kpm computes no individual mode; use method dense or lanczos with "
                   "keyword mode");
  if (lanczos && selected_mode > options.nmodes)
    args.error_all("mode %d is out of range: method lanczos computes nmodes = %d modes; raise "
                   "nmodes to at least %d",
                   selected_mode, options.nmodes, selected_mode);
  if (!fixed_group.empty()) fixed_groupbit = group->bitmask[group->find(fixed_group.c_str())];

  ndof = Acoustic::facade_dofs_per_grain(domain->dimension, settings.model);
  options.dimension = domain->dimension;
  options.model = settings.model;
  options.mode = selected_mode;
  network = new AcousticLiggghtsNetwork(lmp, caller);
  network->set_stiffness(settings.youngs_modulus, settings.poisson_ratio, settings.kappa_scale,
                         settings.ratio);

  // outputs; LIGGGHTS has no global vector of variable length: the
  // frequencies are every mode of the group's free DOFs now (dense) or nmodes
  scalar_flag = 1;
  extscalar = 0;
  if (!kpm) {
    nfree_defined = free_dofs_now(false);
    vector_flag = 1;
    size_vector = lanczos ? options.nmodes : nfree_defined;
    extvector = 0;
    frequencies.assign(size_vector, 0.0);
    vector = size_vector ? &frequencies[0] : NULL;
    local_flag = 1;
    size_local_rows = 0;
    size_local_cols = MODE_COLUMNS;
  }
  if (options.bins > 0) {
    array_flag = 1;
    size_array_rows = options.bins;
    size_array_cols = HISTOGRAM_COLUMNS;
    extarray = 0;
    memory->create(histogram, options.bins, HISTOGRAM_COLUMNS, "vibration/modes:histogram");
    for (int b = 0; b < options.bins; b++)
      for (int k = 0; k < HISTOGRAM_COLUMNS; k++) histogram[b][k] = 0.0;
    array = histogram;
  }
  if (selected_mode > 0) {
    peratom_flag = 1;
    size_peratom_cols = (settings.model == Acoustic::FacadeContactModel::Full) ? 6 : 3;
  }
}

ComputeVibrationModes::~ComputeVibrationModes()
{
  delete network;
  memory->destroy(histogram);
  memory->destroy(mode_rows);
  memory->destroy(shape_atom);
}

/* ----------------------------------------------------------------------
   free DOFs of the group (its atoms not in the fixed group); check: stop
   with an ERROR if the group is empty or the fixed group is not in it
   (not when the compute is defined: the grains may be inserted later)
------------------------------------------------------------------------- */

int ComputeVibrationModes::free_dofs_now(bool check)
{
  double counts_local[3] = {0.0, 0.0, 0.0}, counts[3];
  for (int i = 0; i < atom->nlocal; i++) {
    const bool in_group = atom->mask[i] & groupbit, fixed = atom->mask[i] & fixed_groupbit;
    if (in_group) counts_local[0] += 1.0;
    if (in_group && fixed) counts_local[1] += 1.0;
    if (fixed && !in_group) counts_local[2] += 1.0;
  }
  MPI_Allreduce(counts_local, counts, 3, MPI_DOUBLE, MPI_SUM, world);
  char what[512];
  if (!check) return static_cast<int>(std::min(2e9, ndof * (counts[0] - counts[1])));
  if (counts[0] == 0.0) {
    snprintf(what, sizeof(what), "%s: compute group %s has no atom", caller.c_str(),
             group->names[igroup]);
    error->all(FLERR, what);
  }
  if (fixed_groupbit && counts[1] == 0.0) {
    snprintf(what, sizeof(what),
             "%s: fixed group %s has no atom in the compute group %s; the clamped atoms must "
             "belong to the compute group",
             caller.c_str(), fixed_group.c_str(), group->names[igroup]);
    error->all(FLERR, what);
  }
  if (counts[2] > 0.0) {
    snprintf(what, sizeof(what),
             "%s: %.0f atoms of the fixed group %s are not in the compute group %s; the clamped "
             "atoms must all belong to the compute group",
             caller.c_str(), counts[2], fixed_group.c_str(), group->names[igroup]);
    error->all(FLERR, what);
  }
  const double nfree = ndof * (counts[0] - counts[1]);
  if (nfree > 2e9) error->all(FLERR, "compute vibration/modes: too many DOFs");
  return static_cast<int>(nfree);
}

/* ---------------------------------------------------------------------- */

void ComputeVibrationModes::init()
{
  network->init(false);
  if (!fixed_group.empty()) {
    const int ifixed = group->find(fixed_group.c_str());
    if (ifixed < 0) {
      std::string what = caller + ": fixed group " + fixed_group + " no longer exists";
      error->all(FLERR, what.c_str());
    }
    fixed_groupbit = group->bitmask[ifixed];
  }
  const int nfree = free_dofs_now(true);
  if (options.method == "dense" && nfree != nfree_defined) {
    char what[512];
    snprintf(what, sizeof(what),
             "%s: the group has %d free DOFs now, %d when the compute was defined; LIGGGHTS's "
             "global vectors have a fixed length: define the compute after the grains exist, "
             "or again (uncompute, compute) when their number changed",
             caller.c_str(), nfree, nfree_defined);
    error->all(FLERR, what);
  }
  solved_step = -1;    // the packing may have changed since the last run
}

/* ----------------------------------------------------------------------
   walk, gather, solve on rank 0, broadcast; once per timestep (twice if
   the shapes are needed after a solve without them)
------------------------------------------------------------------------- */

void ComputeVibrationModes::solve(bool need_shapes)
{
  if (solved_step == update->ntimestep && (solved_with_shapes || !need_shapes)) return;
  const bool with_shapes = need_shapes || selected_mode > 0;

  network->collect(groupbit);
  AcousticLiggghtsNetwork::Gathered g;
  network->gather(groupbit, std::vector<int>(1, fixed_groupbit), settings.model, g);
  std::string failure;
  Acoustic::GatheredModesResult r;
  if (comm->me == 0) {
    Acoustic::GatheredModesInput in = options;
    in.grains.swap(g.input.grains);
    in.contacts.swap(g.input.contacts);
    for (size_t k = 0; k < g.flag.size(); k++)
      if (g.flag[k] & 1) in.fixed.push_back(static_cast<int>(k));
    in.with_shapes = with_shapes;
    if (!Acoustic::solve_gathered_modes(in, r)) failure = r.message;
  }
  broadcast_text(world, failure);
  if (!failure.empty()) {
    std::string what = caller + ": " + failure;
    error->all(FLERR, what.c_str());
  }

  // the vector: its fixed length, zeros past the modes found
  found = r.frequencies;
  broadcast_values(world, found);
  for (size_t k = 0; k < frequencies.size(); k++)
    frequencies[k] = k < found.size() ? found[k] : 0.0;
  participation.swap(r.participation);
  double z = r.zero_modes;
  MPI_Bcast(&z, 1, MPI_DOUBLE, 0, world);
  nzero = z;
  if (options.bins > 0) {
    if (comm->me == 0)
      for (int b = 0; b < options.bins; b++) {
        histogram[b][0] = r.bin_centres[b];
        histogram[b][1] = r.density[b];
        histogram[b][2] = r.density_error[b];
      }
    MPI_Bcast(&histogram[0][0], options.bins * HISTOGRAM_COLUMNS, MPI_DOUBLE, 0, world);
  }
  if (selected_mode > 0) {
    shape.swap(r.shape);
    tags.swap(g.tags);
    broadcast_values(world, tags);
    broadcast_values(world, shape);
  }
  solved_step = update->ntimestep;
  solved_with_shapes = with_shapes;
}

/* ---------------------------------------------------------------------- */

double ComputeVibrationModes::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  solve(false);
  scalar = nzero;
  return scalar;
}

void ComputeVibrationModes::compute_vector()
{
  invoked_vector = update->ntimestep;
  solve(false);
}

void ComputeVibrationModes::compute_array()
{
  invoked_array = update->ntimestep;
  solve(false);
}

/* ----------------------------------------------------------------------
   one row per mode on rank 0: mode index, frequency, participation ratio
------------------------------------------------------------------------- */

void ComputeVibrationModes::compute_local()
{
  invoked_local = update->ntimestep;
  solve(true);
  const int nrows = (comm->me == 0) ? static_cast<int>(participation.size()) : 0;
  if (nrows > nmode_rows_max) {
    nmode_rows_max = nrows;
    memory->destroy(mode_rows);
    memory->create(mode_rows, nmode_rows_max, MODE_COLUMNS, "vibration/modes:mode_rows");
  }
  for (int m = 0; m < nrows; m++) {
    mode_rows[m][0] = m + 1;
    mode_rows[m][1] = found[m];
    mode_rows[m][2] = participation[m];
  }
  size_local_rows = nrows;
  array_local = mode_rows;
}

/* ----------------------------------------------------------------------
   shape of the selected mode: translations (x, y, z), then rotations
   (x, y, z) with model full (in 2D about z only); zero for fixed atoms and
   atoms not in the group
------------------------------------------------------------------------- */

void ComputeVibrationModes::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  solve(true);
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(shape_atom);
    memory->create(shape_atom, nmax, size_peratom_cols, "vibration/modes:shape_atom");
    array_atom = shape_atom;
  }
  const int dim = domain->dimension;
  for (int i = 0; i < atom->nlocal; i++) {
    for (int k = 0; k < size_peratom_cols; k++) shape_atom[i][k] = 0.0;
    if (!(atom->mask[i] & groupbit)) continue;
    const int g = AcousticLiggghtsNetwork::grain_index(tags, atom->tag[i]);
    if (g < 0) continue;
    const double *v = &shape[static_cast<size_t>(g) * ndof];
    for (int k = 0; k < dim; k++) shape_atom[i][k] = v[k];
    if (ndof > dim) {
      if (dim == 3)
        for (int k = 0; k < 3; k++) shape_atom[i][3 + k] = v[3 + k];
      else
        shape_atom[i][5] = v[2];
    }
  }
}

/* ---------------------------------------------------------------------- */

double ComputeVibrationModes::memory_usage()
{
  double bytes = 0.0;
  if (peratom_flag) bytes += static_cast<double>(nmax) * size_peratom_cols * sizeof(double);
  bytes += static_cast<double>(frequencies.size() + found.size() + participation.size() +
                               shape.size() + tags.size()) * sizeof(double);
  bytes += static_cast<double>(nmode_rows_max) * MODE_COLUMNS * sizeof(double);
  return bytes;
}
