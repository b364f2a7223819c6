/* ----------------------------------------------------------------------
    ACOUSTIC for LIGGGHTS-PUBLIC 3.8: fix acoustic/mindlin (see the header).

    LIGGGHTS is open-source, distributed under the terms of the GNU Public
    License, version 2 or later.  This file is part of the ACOUSTIC
    package and distributed under the same terms.
------------------------------------------------------------------------- */

#include "fix_acoustic_mindlin.h"

#include "acoustic_liggghts_network.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "memory.h"
#include "update.h"

#include "acoustic_contact_factor.h"
#include "acoustic_gathered_drive.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

const char *const CMD = "fix acoustic/mindlin";
bool parse_number(const char *s, double &value)
{
  char *end = NULL;
  value = strtod(s, &end);
  return end != s && *end == '\0' && std::isfinite(value);
}

}    // namespace

/* ---------------------------------------------------------------------- */

FixAcousticMindlin::FixAcousticMindlin(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), source_group(-1), source_groupbit(0), source_wall(-1),
    source_is_mesh(false), frequency(-1.0), amplitude(-1.0),
    direction_given(false), direction_axis(-1), mode_normal(false), youngs_modulus(-1.0),
    poisson_ratio(0.0), kappa_scale(1.0), ratio(2.0 / 7.0), cmu(1.0), mu_min(0.0),
    model_full(false), network(NULL), rows(NULL), maxrows(0)
{
  direction[0] = direction[1] = direction[2] = 0.0;
  stats[0] = 0.0;
  stats[1] = stats[2] = 1.0;
  parse(narg, arg);
  network = new AcousticLiggghtsNetwork(lmp, std::string(CMD) + " " + id);
  network->set_stiffness(youngs_modulus, poisson_ratio, kappa_scale, ratio);

  vector_flag = 1;
  size_vector = 3;
  global_freq = 1;
  extvector = 0;
  local_flag = 1;
  size_local_cols = 6;
  size_local_rows = 0;
  local_freq = nevery;
  array_local = NULL;
}

FixAcousticMindlin::~FixAcousticMindlin()
{
  memory->destroy(rows);
  delete network;
}

/* ---------------------------------------------------------------------- */

void FixAcousticMindlin::error_all(const char *fmt, ...)
{
  char message[1024];
  va_list args;
  va_start(args, fmt);
  vsnprintf(message, sizeof(message), fmt, args);
  va_end(args);
  error->all(FLERR, message);
}

void FixAcousticMindlin::parse(int narg, char **arg)
{
  const char *usage = "N frequency f amplitude U0 source group-ID [keyword value ...]";
  if (narg < 10)
    error_all("%s %s: too few arguments; expected: fix ID group acoustic/mindlin %s", CMD, id,
              usage);
  double value;
  if (!parse_number(arg[3], value) || value < 1.0 || value != floor(value) || value > 2e9)
    error_all("%s %s: N must be a positive integer, got '%s'", CMD, id, arg[3]);
  nevery = static_cast<int>(value);
  if (strcmp(arg[4], "frequency") != 0 || strcmp(arg[6], "amplitude") != 0 ||
      strcmp(arg[8], "source") != 0)
    error_all("%s %s: the arguments after N must be %s", CMD, id, usage + 2);
  if (!parse_number(arg[5], frequency) || frequency < 0.0)
    error_all("%s %s: keyword frequency: f must be a number >= 0, got '%s'", CMD, id, arg[5]);
  if (!parse_number(arg[7], amplitude) || amplitude < 0.0)
    error_all("%s %s: keyword amplitude: U0 must be a number >= 0, got '%s'", CMD, id, arg[7]);
  int iarg = 10;
  if (strcmp(arg[9], "wall") == 0 || strcmp(arg[9], "mesh") == 0) {
    source_is_mesh = strcmp(arg[9], "mesh") == 0;
    if (narg < 11)
      error_all("%s %s: keyword source %s needs the ID of a fix %s", CMD, id, arg[9],
                source_is_mesh ? "mesh/surface used by fix wall/gran" : "wall/gran (primitive)");
    source_wall_id = arg[10];
    iarg = 11;
  } else {
    source_group = group->find(arg[9]);
    if (source_group < 0)
      error_all("%s %s: keyword source: no group '%s' (give a group of grains, 'wall "
                "<fix-ID>' of a fix wall/gran primitive wall, or 'mesh <fix-ID>' of a fix "
                "mesh/surface)",
                CMD, id, arg[9]);
    source_groupbit = group->bitmask[source_group];
  }

  bool stiffness_given = false;
  while (iarg < narg) {
    const char *key = arg[iarg];
    int nvalues = 1;
    if (strcmp(key, "direction") == 0) nvalues = 3;
    if (strcmp(key, "stiffness") == 0) nvalues = (iarg + 1 < narg && strcmp(arg[iarg + 1], "hertz") == 0) ? 3 : 1;
    if (iarg + nvalues >= narg)
      error_all("%s %s: keyword %s needs %d value(s)", CMD, id, key, nvalues);
    const char *v = arg[iarg + 1];
    if (strcmp(key, "direction") == 0) {
      for (int k = 0; k < 3; k++)
        if (!parse_number(arg[iarg + 1 + k], direction[k]))
          error_all("%s %s: keyword direction: '%s' is not a number", CMD, id, arg[iarg + 1 + k]);
      direction_given = true;
    } else if (strcmp(key, "mode") == 0) {
      if (strcmp(v, "all") == 0)
        mode_normal = false;
      else if (strcmp(v, "normal") == 0)
        mode_normal = true;
      else
        error_all("%s %s: keyword mode must be 'all' or 'normal', got '%s'", CMD, id, v);
    } else if (strcmp(key, "stiffness") == 0) {
      if (strcmp(v, "hertz") != 0)
        error_all("%s %s: keyword stiffness: only 'hertz E nu' is available in LIGGGHTS, got "
                  "'%s' (stiffness pair is not yet)",
                  CMD, id, v);
      if (!parse_number(arg[iarg + 2], youngs_modulus) || !(youngs_modulus > 0.0))
        error_all("%s %s: keyword stiffness hertz needs Young's modulus E > 0, got '%s'", CMD, id,
                  arg[iarg + 2]);
      if (!parse_number(arg[iarg + 3], poisson_ratio) ||
          !(poisson_ratio > -1.0 && poisson_ratio < 0.5))
        error_all("%s %s: keyword stiffness hertz needs -1 < nu < 0.5, got '%s'", CMD, id,
                  arg[iarg + 3]);
      stiffness_given = true;
    } else if (strcmp(key, "kappa_scale") == 0) {
      if (!parse_number(v, kappa_scale) || !(kappa_scale > 0.0))
        error_all("%s %s: keyword kappa_scale must be > 0, got '%s'", CMD, id, v);
    } else if (strcmp(key, "ratio") == 0) {
      if (!parse_number(v, ratio) || ratio < 0.0)
        error_all("%s %s: keyword ratio k_t/k_n must be >= 0, got '%s'", CMD, id, v);
    } else if (strcmp(key, "cmu") == 0) {
      if (!parse_number(v, cmu) || cmu < 0.0)
        error_all("%s %s: keyword cmu must be >= 0, got '%s'", CMD, id, v);
    } else if (strcmp(key, "mu_min") == 0) {
      if (!parse_number(v, mu_min) || mu_min < 0.0 || mu_min > 1.0)
        error_all("%s %s: keyword mu_min must be in [0, 1], got '%s'", CMD, id, v);
    } else if (strcmp(key, "model") == 0) {
      if (strcmp(v, "normal") == 0)
        model_full = false;
      else if (strcmp(v, "full") == 0)
        model_full = true;
      else
        error_all("%s %s: keyword model must be 'normal' or 'full', got '%s'", CMD, id, v);
    } else {
      error_all("%s %s: unknown keyword '%s' (LIGGGHTS knows direction, mode, stiffness, "
                "kappa_scale, ratio, cmu, mu_min, model)",
                CMD, id, key);
    }
    iarg += 1 + nvalues;
  }
  if (!stiffness_given)
    error_all("%s %s: keyword stiffness hertz E nu is required in LIGGGHTS (stiffness pair is "
              "not available yet)",
              CMD, id);
  // a wall's default direction is its normal, known at init
  if (direction_given || source_wall_id.empty()) normalise_direction();
}

// the unit drive direction as the LAMMPS fix computes it
void FixAcousticMindlin::normalise_direction()
{
  const int dim = domain->dimension;
  if (!direction_given) direction[dim == 2 ? 1 : 2] = 1.0;
  if (dim == 2 && direction[2] != 0.0)
    error_all("%s %s: keyword direction: in 2D the direction must lie in the xy plane (dz = 0)",
              CMD, id);
  const double largest =
      std::max(fabs(direction[0]), std::max(fabs(direction[1]), fabs(direction[2])));
  if (largest == 0.0)
    error_all("%s %s: keyword direction must not be the zero vector", CMD, id);
  for (int k = 0; k < 3; k++) direction[k] /= largest;
  const double norm =
      sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  for (int k = 0; k < 3; k++) direction[k] /= norm;
  for (int k = 0; k < dim; k++)
    if (fabs(direction[k]) == 1.0) direction_axis = k;
  if (mode_normal && direction_axis < 0)
    error_all("%s %s: keyword mode normal prescribes one Cartesian component of the source "
              "grains; give a direction along x, y or z",
              CMD, id);
}

/* ---------------------------------------------------------------------- */

int FixAcousticMindlin::setmask()
{
  return PRE_FORCE;
}

void FixAcousticMindlin::init()
{
  network->init(true, modify->find_fix(id));
  if (source_wall_id.empty()) {
    if (group->count(source_group) == 0)
      error_all("%s %s: keyword source: group %s has no atoms; nothing would vibrate", CMD, id,
                group->names[source_group]);
    return;
  }
  const char *kind = source_is_mesh ? "mesh" : "wall";
  source_wall = network->wall_index(source_wall_id);
  if (source_wall < 0)
    error_all("%s %s: keyword source %s: no %s '%s' (it must be the ID of a %s)", CMD, id, kind,
              source_is_mesh ? "mesh" : "wall", source_wall_id.c_str(),
              source_is_mesh ? "fix mesh/surface used by a fix wall/gran ... mesh"
                             : "fix wall/gran ... primitive");
  const AcousticLiggghtsNetwork::Wall &w = network->walls()[source_wall];
  if (source_is_mesh != (w.mesh != NULL))
    error_all("%s %s: keyword source %s %s: %s is a %s; write 'source %s %s'", CMD, id, kind,
              source_wall_id.c_str(), source_wall_id.c_str(),
              w.mesh ? "mesh (fix mesh/surface)" : "primitive wall (fix wall/gran)",
              w.mesh ? "mesh" : "wall", source_wall_id.c_str());
  if (!direction_given) {
    if (w.plane_axis < 0)
      error_all("%s %s: keyword source %s %s has no single normal (%s): give the drive with "
                "keyword direction dx dy dz",
                CMD, id, kind, source_wall_id.c_str(),
                w.mesh ? "a mesh" : "not a plane");
    // the default drive of a plane wall: along its axis, as in LAMMPS
    direction[0] = direction[1] = direction[2] = 0.0;
    direction[w.plane_axis] = 1.0;
    direction_given = true;
    normalise_direction();
  }
}

/* ---------------------------------------------------------------------- */

void FixAcousticMindlin::setup_pre_force(int)
{
  update_factors();
}

void FixAcousticMindlin::pre_force(int)
{
  if (update->ntimestep % nevery == 0) update_factors();
}

/* ----------------------------------------------------------------------
   the contacts, the drive's response (f > 0), every contact's factor
------------------------------------------------------------------------- */

void FixAcousticMindlin::update_factors()
{
  network->collect(groupbit);
  std::vector<double> tags_sorted;    // every grain of the group, by atom ID
  std::vector<double> q;              // their DOF values, then the walls'
  if (frequency > 0.0 && !solve_drive(tags_sorted, q)) {
    statistics();    // the solve failed: the previous factors stay
    return;
  }
  set_factors(tags_sorted, q);
  statistics();
}

/* ----------------------------------------------------------------------
   gather, solve on rank 0, broadcast; false (after a WARNING) if the solve
   failed numerically, an ERROR if the input is invalid
------------------------------------------------------------------------- */

bool FixAcousticMindlin::solve_drive(std::vector<double> &tags_sorted, std::vector<double> &q)
{
  const int dim = domain->dimension;
  const Acoustic::FacadeContactModel::Value model =
      model_full ? Acoustic::FacadeContactModel::Full : Acoustic::FacadeContactModel::Normal;
  const int ndof = Acoustic::facade_dofs_per_grain(dim, model);
  const int me = comm->me;
  int solved = 1;
  {
    AcousticLiggghtsNetwork::Gathered net;
    network->gather(groupbit, source_groupbit, model, net);
    std::string failure;
    if (me == 0) {
      Acoustic::GatheredDriveInput &in = net.input;
      in.frequency = frequency;
      const int ng = static_cast<int>(net.tags.size());
      // the walls: the source wall moves with the drive, the others are clamped
      // (a node of infinite mass: every DOF not named is 0)
      if (source_wall >= 0)
        for (int d = 0; d < dim; d++)
          in.prescribed.push_back(Acoustic::PrescribedDof(ng + source_wall, d, direction[d]));
      for (int g = 0; g < ng; g++) {
        if (!net.flag[g]) continue;
        if (mode_normal) {
          in.prescribed.push_back(Acoustic::PrescribedDof(g, direction_axis, direction[direction_axis]));
        } else {
          for (int d = 0; d < dim; d++) in.prescribed.push_back(Acoustic::PrescribedDof(g, d, direction[d]));
          for (int d = dim; d < ndof; d++) in.prescribed.push_back(Acoustic::PrescribedDof(g, d, 0.0));
        }
      }
      Acoustic::GatheredDriveResult out;
      Acoustic::solve_gathered_drive(in, out);
      if (out.status == Acoustic::FacadeStatus::Success) {
        q.swap(out.q);
        tags_sorted.swap(net.tags);
      } else if (out.status == Acoustic::FacadeStatus::InvalidInput ||
                 out.status == Acoustic::FacadeStatus::InternalError) {
        failure = out.message;
        solved = -1;
      } else {
        char message[1024];
        snprintf(message, sizeof(message),
                 "%s %s: the Helmholtz solve at f = %g failed (%s: %s; relative residual "
                 "%.3g); keeping the previous friction factors. A frequency on a resonance "
                 "of an undamped network is singular: move f",
                 CMD, id, frequency, Acoustic::facade_status_name(out.status),
                 out.message.c_str(), out.relative_residual);
        error->warning(FLERR, message);
        solved = 0;
      }
    }
    MPI_Bcast(&solved, 1, MPI_INT, 0, world);
    if (solved < 0) {
      int length = static_cast<int>(failure.size());
      MPI_Bcast(&length, 1, MPI_INT, 0, world);
      std::vector<char> text(length + 1, '\0');
      if (me == 0 && length) std::copy(failure.begin(), failure.end(), text.begin());
      MPI_Bcast(&text[0], length + 1, MPI_CHAR, 0, world);
      error_all("%s %s: cannot solve the drive: %s", CMD, id, &text[0]);
    }
    if (!solved) return false;
    network->broadcast(tags_sorted, q);
  }
  return true;
}

/* ----------------------------------------------------------------------
   every copy of every contact, from its lower to its higher atom ID (a
   wall second): U_t and s, 1 - s into its history, the local rows
------------------------------------------------------------------------- */

void FixAcousticMindlin::set_factors(const std::vector<double> &tags_sorted,
                                     const std::vector<double> &q)
{
  const std::vector<AcousticLiggghtsNetwork::Contact> &contacts = network->contacts();
  const int dim = domain->dimension;
  const Acoustic::FacadeContactModel::Value model =
      model_full ? Acoustic::FacadeContactModel::Full : Acoustic::FacadeContactModel::Normal;
  const int ndof = Acoustic::facade_dofs_per_grain(dim, model);
  int *tag = atom->tag;
  Acoustic::ContactFactorInput in;
  in.dimension = dim;
  in.model = model;
  in.amplitude = amplitude;
  in.cmu = cmu;
  in.mu_min = mu_min;
  Acoustic::ContactFactorResult out;
  if (static_cast<int>(contacts.size()) > maxrows) {
    maxrows = static_cast<int>(contacts.size());
    memory->destroy(rows);
    memory->create(rows, maxrows, size_local_cols, "acoustic/mindlin:rows");
  }
  int nrows = 0;
  int bad = 0;
  std::string bad_message;
  for (size_t k = 0; k < contacts.size(); k++) {
    const AcousticLiggghtsNetwork::Contact &c = contacts[k];
    // from the lower to the higher atom ID; a wall comes second
    const bool wall = c.wall >= 0;
    const bool flip = !wall && tag[c.i] > tag[c.j];
    const int a = flip ? c.j : c.i, b = flip ? c.i : c.j;
    double s = 1.0, ut = 0.0;
    if (frequency > 0.0 && c.kn > 0.0) {
      const int ga = AcousticLiggghtsNetwork::grain_index(tags_sorted, tag[a]);
      const int gb = wall ? static_cast<int>(tags_sorted.size()) + c.wall
                          : AcousticLiggghtsNetwork::grain_index(tags_sorted, tag[b]);
      if (ga < 0 || gb < 0) {
        bad++;
        continue;
      }
      const double sign = flip ? -1.0 : 1.0;
      for (int d = 0; d < 3; d++) in.normal[d] = sign * c.n[d];
      in.radius_i = atom->radius[a];
      in.radius_j = wall ? 0.0 : atom->radius[b];    // a flat wall's (its rotation is 0)
      in.q_i = &q[static_cast<size_t>(ga) * 2 * ndof];
      in.q_j = &q[static_cast<size_t>(gb) * 2 * ndof];
      in.tangential_stiffness = c.kt;
      in.friction_coefficient = c.mu;
      in.normal_force = c.fn;
      if (!Acoustic::contact_mindlin_factor(in, out) || !std::isfinite(out.factor)) {
        if (!bad) bad_message = out.message;
        bad++;
        continue;    // the factor stays as it was
      }
      ut = out.tangential_amplitude;
      s = out.factor;
    }
    // a wall whose tangential model has no /acoustic variant keeps its friction
    if (c.slot)
      *c.slot = 1.0 - s;
    else
      s = 1.0;
    if (!c.counted) continue;
    double *row = rows[nrows++];
    row[0] = tag[a];
    row[1] = wall ? 0.0 : tag[b];    // 0: a wall, as in LAMMPS
    row[2] = c.fn;
    row[3] = c.kn;
    row[4] = ut;
    row[5] = s;
  }
  size_local_rows = nrows;
  array_local = rows;
  int bad_all = 0;
  MPI_Allreduce(&bad, &bad_all, 1, MPI_INT, MPI_SUM, world);
  if (bad_all)
    error_all("%s %s: %d contact(s) got no friction factor (%s)", CMD, id, bad_all,
              bad ? (bad_message.empty() ? "a grain missing from the network" : bad_message.c_str())
                  : "see the other ranks");
}

/* ---------------------------------------------------------------------- */

void FixAcousticMindlin::statistics()
{
  const std::vector<AcousticLiggghtsNetwork::Contact> &contacts = network->contacts();
  double sum = 0.0, count = 0.0, minimum = 1.0;
  for (size_t k = 0; k < contacts.size(); k++) {
    if (!contacts[k].counted) continue;
    const double s = contacts[k].slot ? 1.0 - *contacts[k].slot : 1.0;
    sum += s;
    count += 1.0;
    minimum = std::min(minimum, s);
  }
  double local[2] = {sum, count}, global[2];
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, world);
  double global_min = 1.0;
  MPI_Allreduce(&minimum, &global_min, 1, MPI_DOUBLE, MPI_MIN, world);
  stats[0] = global[1];
  stats[1] = global[1] > 0.0 ? global[0] / global[1] : 1.0;
  stats[2] = global_min;
}

double FixAcousticMindlin::compute_vector(int n)
{
  if (n < 0 || n >= 3) return 0.0;
  return stats[n];
}

double FixAcousticMindlin::memory_usage()
{
  return network->contacts().capacity() * sizeof(AcousticLiggghtsNetwork::Contact) +
      maxrows * size_local_cols * sizeof(double);
}
