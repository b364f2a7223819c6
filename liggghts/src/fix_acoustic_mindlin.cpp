/* ----------------------------------------------------------------------
    ACOUSTIC for LIGGGHTS-PUBLIC 3.8: fix acoustic/mindlin (see the header).

    LIGGGHTS is open-source, distributed under the terms of the GNU Public
    License, version 2 or later.  This file is part of the ACOUSTIC
    package and distributed under the same terms.
------------------------------------------------------------------------- */

#include "fix_acoustic_mindlin.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "neigh_list.h"
#include "pair_gran.h"
#include "pair_gran_proxy.h"
#include "properties.h"
#include "property_registry.h"
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
const int GRAIN_WORDS = 4;      // tag, mass, radius, source
const int CONTACT_WORDS = 7;    // tag lo, tag hi, normal (3, from hi to lo), k_n, k_t

bool parse_number(const char *s, double &value)
{
  char *end = NULL;
  value = strtod(s, &end);
  return end != s && *end == '\0' && std::isfinite(value);
}

// rank 0 gets every processor's words, in rank order
void gather_words(MPI_Comm world, int me, int nprocs, const std::vector<double> &mine,
                  std::vector<double> &all)
{
  int n = static_cast<int>(mine.size());
  std::vector<int> counts(nprocs, 0), displs(nprocs, 0);
  MPI_Gather(&n, 1, MPI_INT, &counts[0], 1, MPI_INT, 0, world);
  int total = 0;
  if (me == 0)
    for (int p = 0; p < nprocs; p++) {
      displs[p] = total;
      total += counts[p];
    }
  all.assign(total > 0 ? total : 1, 0.0);
  all.resize(total);
  MPI_Gatherv(n ? const_cast<double *>(&mine[0]) : NULL, n, MPI_DOUBLE, total ? &all[0] : NULL,
              &counts[0], &displs[0], MPI_DOUBLE, 0, world);
}

}    // namespace

/* ---------------------------------------------------------------------- */

FixAcousticMindlin::FixAcousticMindlin(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), source_group(-1), source_groupbit(0), frequency(-1.0), amplitude(-1.0),
    direction_given(false), direction_axis(-1), mode_normal(false), youngs_modulus(-1.0),
    poisson_ratio(0.0), kappa_scale(1.0), ratio(2.0 / 7.0), cmu(1.0), mu_min(0.0),
    model_full(false), pair(NULL), factor_offset(-1), rows(NULL), maxrows(0)
{
  direction[0] = direction[1] = direction[2] = 0.0;
  stats[0] = 0.0;
  stats[1] = stats[2] = 1.0;
  parse(narg, arg);

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
  source_group = group->find(arg[9]);
  if (source_group < 0)
    error_all("%s %s: keyword source: no group '%s' (a source wall is not available in "
              "LIGGGHTS yet: give a group of grains)",
              CMD, id, arg[9]);
  source_groupbit = group->bitmask[source_group];

  bool stiffness_given = false;
  int iarg = 10;
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
  normalise_direction();
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
  if (!atom->radius_flag || !atom->rmass_flag)
    error_all("%s %s: needs atoms with radius and per-atom mass (atom_style granular)", CMD, id);
  pair = dynamic_cast<PairGran *>(force->pair_match("gran", 0));
  if (!pair)
    error_all("%s %s: needs pair_style gran (model hertz tangential history/acoustic)", CMD, id);
  if (!pair->contact_match("tangential", "history/acoustic"))
    error_all("%s %s: the tangential model of pair_style gran has no acoustic history value "
              "\"acousticFrictionReduction\": use tangential history/acoustic",
              CMD, id);
  if (!pair->contact_match("normal", "hertz"))
    error_all("%s %s: keyword stiffness hertz needs pair_style gran model hertz (hooke and the "
              "other normal models are not available yet)",
              CMD, id);
  factor_offset = static_cast<PairGranProxy *>(pair)->get_history_offset("acousticFrictionReduction");
  if (factor_offset < 0)
    error_all("%s %s: pair_style gran has no history value \"acousticFrictionReduction\" "
              "(tangential history/acoustic)",
              CMD, id);
  if (force->newton_pair)
    error_all("%s %s: needs newton off (pair_style gran with a history model)", CMD, id);
  if (group->count(source_group) == 0)
    error_all("%s %s: keyword source: group %s has no atoms; nothing would vibrate", CMD, id,
              group->names[source_group]);
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
   the contacts of this processor's neighbor list between atoms of the
   group, with their Hertz stiffnesses (the overlap as pair gran sees it)
------------------------------------------------------------------------- */

void FixAcousticMindlin::collect()
{
  contacts.clear();
  NeighList *list = pair->list;
  NeighList *hlist = pair->listgranhistory;
  if (!list || !hlist || !hlist->firstdouble)
    error_all("%s %s: pair_style gran has no contact history list", CMD, id);
  double **Yeff = force->registry.getMatrixProperty("Yeff", CMD)->data;
  double **coeffFrict = force->registry.getMatrixProperty("coeffFrict", CMD)->data;
  const int dnum = pair->dnum();
  double **x = atom->x;
  double *radius = atom->radius;
  int *mask = atom->mask;
  int *type = atom->type;
  int *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const double estar = youngs_modulus / (2.0 * (1.0 - poisson_ratio * poisson_ratio));
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    const int *jlist = list->firstneigh[i];
    double *hist = hlist->firstdouble[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!(mask[j] & groupbit)) continue;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const double radsum = radius[i] + radius[j];
      if (rsq >= radsum * radsum) continue;
      const double r = sqrt(rsq);
      const double rinv = 1.0 / r;
      LocalContact c;
      c.i = i;
      c.j = j;
      c.n[0] = delx * rinv;
      c.n[1] = dely * rinv;
      c.n[2] = delz * rinv;
      // the elastic normal force of LIGGGHTS's hertz (normal_model_hertz.h)
      const double deltan = radsum - r;
      const double reff = radius[i] * radius[j] / (radius[i] + radius[j]);
      const double kn_pair = 4. / 3. * Yeff[type[i]][type[j]] * sqrt(reff * deltan);
      c.fn = kn_pair * deltan;
      // the fix's Hertz stiffness at that force (the LAMMPS fix's hertz_kappa, hertz_normal_stiffness)
      const double rstar = 1.0 / (1.0 / radius[i] + 1.0 / radius[j]);
      const double kappa = kappa_scale * (4.0 / 3.0 * estar * sqrt(rstar));
      c.kn = (c.fn > 0.0) ? 1.5 * pow(kappa, 2.0 / 3.0) * cbrt(c.fn) : 0.0;
      c.kt = ratio * c.kn;
      c.mu = coeffFrict[type[i]][type[j]];
      c.slot = &hist[dnum * jj + factor_offset];
      c.counted = j < nlocal || tag[i] < tag[j];
      if (!(std::isfinite(c.fn) && std::isfinite(c.kn)))
        error->one(FLERR, "fix acoustic/mindlin: a contact has a non-finite Hertz force or "
                          "stiffness; check youngsModulus, poissonsRatio and the keywords "
                          "stiffness, kappa_scale");
      contacts.push_back(c);
    }
  }
}

/* ----------------------------------------------------------------------
   gather, solve on rank 0, broadcast, set every contact's factor
------------------------------------------------------------------------- */

void FixAcousticMindlin::update_factors()
{
  collect();
  const int dim = domain->dimension;
  const Acoustic::FacadeContactModel::Value model =
      model_full ? Acoustic::FacadeContactModel::Full : Acoustic::FacadeContactModel::Normal;
  const int ndof = Acoustic::facade_dofs_per_grain(dim, model);
  int *tag = atom->tag;
  int *mask = atom->mask;
  const int me = comm->me;

  std::vector<double> tags_sorted;    // every grain of the group, by atom ID
  std::vector<double> q;              // their DOF values, 2 ndof each
  int solved = 1;
  if (frequency > 0.0) {
    std::vector<double> grain_words, contact_words;
    for (int i = 0; i < atom->nlocal; i++) {
      if (!(mask[i] & groupbit)) continue;
      grain_words.push_back(tag[i]);
      grain_words.push_back(atom->rmass[i]);
      grain_words.push_back(atom->radius[i]);
      grain_words.push_back((mask[i] & source_groupbit) ? 1.0 : 0.0);
    }
    for (size_t k = 0; k < contacts.size(); k++) {
      const LocalContact &c = contacts[k];
      if (!c.counted || !(c.kn > 0.0)) continue;
      const bool flip = tag[c.i] > tag[c.j];
      const double sign = flip ? -1.0 : 1.0;
      contact_words.push_back(flip ? tag[c.j] : tag[c.i]);
      contact_words.push_back(flip ? tag[c.i] : tag[c.j]);
      for (int d = 0; d < 3; d++) contact_words.push_back(sign * c.n[d]);
      contact_words.push_back(c.kn);
      contact_words.push_back(c.kt);
    }
    std::vector<double> all_grains, all_contacts;
    gather_words(world, me, comm->nprocs, grain_words, all_grains);
    gather_words(world, me, comm->nprocs, contact_words, all_contacts);

    int ngrains = 0;
    std::string failure;
    if (me == 0) {
      const int ng = static_cast<int>(all_grains.size()) / GRAIN_WORDS;
      std::vector<std::pair<double, int> > order(ng);
      for (int g = 0; g < ng; g++) order[g] = std::make_pair(all_grains[GRAIN_WORDS * g], g);
      std::sort(order.begin(), order.end());
      Acoustic::GatheredDriveInput in;
      in.dimension = dim;
      in.model = model;
      in.frequency = frequency;
      tags_sorted.resize(ng);
      for (int g = 0; g < ng; g++) {
        const double *w = &all_grains[GRAIN_WORDS * order[g].second];
        tags_sorted[g] = w[0];
        in.grains.push_back(Acoustic::GatheredGrain(w[1], w[2]));
        if (w[3] == 0.0) continue;
        if (mode_normal) {
          in.prescribed.push_back(Acoustic::PrescribedDof(g, direction_axis, direction[direction_axis]));
        } else {
          for (int d = 0; d < dim; d++) in.prescribed.push_back(Acoustic::PrescribedDof(g, d, direction[d]));
          for (int d = dim; d < ndof; d++) in.prescribed.push_back(Acoustic::PrescribedDof(g, d, 0.0));
        }
      }
      const int nc = static_cast<int>(all_contacts.size()) / CONTACT_WORDS;
      for (int k = 0; k < nc; k++) {
        const double *w = &all_contacts[CONTACT_WORDS * k];
        Acoustic::GatheredContact c;
        c.i = static_cast<int>(std::lower_bound(tags_sorted.begin(), tags_sorted.end(), w[0]) -
                               tags_sorted.begin());
        c.j = static_cast<int>(std::lower_bound(tags_sorted.begin(), tags_sorted.end(), w[1]) -
                               tags_sorted.begin());
        for (int d = 0; d < 3; d++) c.normal[d] = w[2 + d];
        c.kn = w[5];
        c.kt = w[6];
        in.contacts.push_back(c);
      }
      Acoustic::GatheredDriveResult out;
      Acoustic::solve_gathered_drive(in, out);
      if (out.status == Acoustic::FacadeStatus::Success) {
        q.swap(out.q);
        ngrains = ng;
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
    if (!solved) {
      statistics();
      return;
    }
    MPI_Bcast(&ngrains, 1, MPI_INT, 0, world);
    tags_sorted.resize(ngrains);
    q.resize(static_cast<size_t>(ngrains) * 2 * ndof);
    if (ngrains > 0) {
      MPI_Bcast(&tags_sorted[0], ngrains, MPI_DOUBLE, 0, world);
      MPI_Bcast(&q[0], ngrains * 2 * ndof, MPI_DOUBLE, 0, world);
    }
  }

  // every copy of every contact, from its lower to its higher atom ID
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
    const LocalContact &c = contacts[k];
    const bool flip = tag[c.i] > tag[c.j];
    const int a = flip ? c.j : c.i, b = flip ? c.i : c.j;
    double s = 1.0, ut = 0.0;
    if (frequency > 0.0 && c.kn > 0.0) {
      const int ga = static_cast<int>(
          std::lower_bound(tags_sorted.begin(), tags_sorted.end(), double(tag[a])) - tags_sorted.begin());
      const int gb = static_cast<int>(
          std::lower_bound(tags_sorted.begin(), tags_sorted.end(), double(tag[b])) - tags_sorted.begin());
      if (ga >= static_cast<int>(tags_sorted.size()) || gb >= static_cast<int>(tags_sorted.size()) ||
          tags_sorted[ga] != tag[a] || tags_sorted[gb] != tag[b]) {
        bad++;
        continue;
      }
      const double sign = flip ? -1.0 : 1.0;
      for (int d = 0; d < 3; d++) in.normal[d] = sign * c.n[d];
      in.radius_i = atom->radius[a];
      in.radius_j = atom->radius[b];
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
    *c.slot = 1.0 - s;
    if (!c.counted) continue;
    double *row = rows[nrows++];
    row[0] = tag[a];
    row[1] = tag[b];
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
  statistics();
}

/* ---------------------------------------------------------------------- */

void FixAcousticMindlin::statistics()
{
  double sum = 0.0, count = 0.0, minimum = 1.0;
  for (size_t k = 0; k < contacts.size(); k++) {
    if (!contacts[k].counted) continue;
    const double s = 1.0 - *contacts[k].slot;
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
  return contacts.capacity() * sizeof(LocalContact) + maxrows * size_local_cols * sizeof(double);
}
