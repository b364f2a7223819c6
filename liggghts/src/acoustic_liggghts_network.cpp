/* ----------------------------------------------------------------------
    ACOUSTIC for LIGGGHTS-PUBLIC 3.8: the contact network of a group (see
    the header).

    LIGGGHTS is open-source, distributed under the terms of the GNU Public
    License, version 2 or later.  This file is part of the ACOUSTIC
    package and distributed under the same terms.
------------------------------------------------------------------------- */

#include "acoustic_liggghts_network.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "fix_contact_history_mesh.h"
#include "fix_mesh_surface.h"
#include "fix_neighlist_mesh.h"
#include "fix_property_atom.h"
#include "fix_wall_gran.h"
#include "force.h"
#include "modify.h"
#include "neighbor.h"
#include "primitive_wall.h"
#include "tri_mesh.h"
#include "neigh_list.h"
#include "pair_gran.h"
#include "pair_gran_proxy.h"
#include "properties.h"
#include "property_registry.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>

using namespace LAMMPS_NS;

namespace {
const int GRAIN_WORDS = 4;      // tag, mass, radius, flag
// tag lo, tag hi (-1 - w for wall w), normal (3, from hi to lo), k_n, k_t
const int CONTACT_WORDS = 7;
const char *const FACTOR_NAME = "acousticFrictionReduction";
}    // namespace

AcousticLiggghtsNetwork::AcousticLiggghtsNetwork(LAMMPS *lmp, const std::string &caller) :
    Pointers(lmp), caller_(caller), youngs_modulus_(-1.0), poisson_ratio_(0.0), kappa_scale_(1.0),
    ratio_(2.0 / 7.0), pair_(NULL), factor_offset_(-1), need_factor_(false)
{
}

void AcousticLiggghtsNetwork::error_all(const char *fmt, ...)
{
  char message[1024];
  int n = snprintf(message, sizeof(message), "%s: ", caller_.c_str());
  if (n < 0 || n >= static_cast<int>(sizeof(message))) n = 0;
  va_list args;
  va_start(args, fmt);
  vsnprintf(message + n, sizeof(message) - n, fmt, args);
  va_end(args);
  error->all(FLERR, message);
}

void AcousticLiggghtsNetwork::set_stiffness(double youngs_modulus, double poisson_ratio,
                                            double kappa_scale, double ratio)
{
  youngs_modulus_ = youngs_modulus;
  poisson_ratio_ = poisson_ratio;
  kappa_scale_ = kappa_scale;
  ratio_ = ratio;
}

/* ---------------------------------------------------------------------- */

void AcousticLiggghtsNetwork::init(bool need_factor, int caller_fix)
{
  need_factor_ = need_factor;
  if (!atom->radius_flag || !atom->rmass_flag)
    error_all("needs atoms with radius and per-atom mass (atom_style granular)");
  pair_ = dynamic_cast<PairGran *>(force->pair_match("gran", 0));
  if (!pair_) error_all("needs pair_style gran (model hertz tangential history/acoustic)");
  factor_offset_ = -1;
  if (need_factor) {
    if (!pair_->contact_match("tangential", "history/acoustic"))
      error_all("the tangential model of pair_style gran has no acoustic history value "
                "\"acousticFrictionReduction\": use tangential history/acoustic");
  }
  if (!pair_->contact_match("normal", "hertz"))
    error_all("keyword stiffness hertz needs pair_style gran model hertz (hooke and the "
              "other normal models are not available yet)");
  if (need_factor) {
    factor_offset_ =
        static_cast<PairGranProxy *>(pair_)->get_history_offset("acousticFrictionReduction");
    if (factor_offset_ < 0)
      error_all("pair_style gran has no history value \"acousticFrictionReduction\" "
                "(tangential history/acoustic)");
  }
  if (force->newton_pair) error_all("needs newton off (pair_style gran with a history model)");
  if (!(youngs_modulus_ > 0.0))
    error_all("the stiffness constants were not set (stiffness hertz E nu)");
  init_walls(caller_fix);
}

/* ----------------------------------------------------------------------
   the walls: every fix wall/gran, a primitive wall or each of its meshes
------------------------------------------------------------------------- */

void AcousticLiggghtsNetwork::init_walls(int caller_fix)
{
  walls_.clear();
  for (int ifix = 0; ifix < modify->nfix; ifix++) {
    FixWallGran *fix = dynamic_cast<FixWallGran *>(modify->fix[ifix]);
    if (!fix || strcmp(modify->fix[ifix]->style, "wall/gran") != 0) continue;
    if (!fix->contact_match("normal", "hertz"))
      error_all("fix %s (wall/gran) is not model hertz: the walls' contacts are Hertz springs "
                "of the network (hooke and the other normal models are not available yet)",
                fix->id);
    const bool acoustic = fix->contact_match("tangential", "history/acoustic");
    const int offset = acoustic ? fix->get_history_offset(FACTOR_NAME) : -1;
    if (acoustic && offset < 0)
      error_all("fix %s (wall/gran) has no history value \"%s\"", fix->id, FACTOR_NAME);
    if (!fix->is_mesh_wall()) {
      Wall w;
      w.id = fix->id;
      w.fix = fix;
      w.mesh = NULL;
      w.factor_offset = offset;
      w.plane_axis = -1;
      // a plane: resolveContact's delta has the plane's axis only, the same
      // at two points that differ off that axis
      PrimitiveWall *prim = fix->primitiveWall();
      if (!prim) error_all("fix %s (wall/gran) has no primitive wall", fix->id);
      for (int axis = 0; axis < 3 && w.plane_axis < 0; axis++) {
        double p1[3] = {0.25, 0.5, 0.75}, p2[3] = {0.25, 0.5, 0.75};
        double d1[3] = {0.0, 0.0, 0.0}, d2[3] = {0.0, 0.0, 0.0};
        p2[(axis + 1) % 3] += 1.0;
        p2[(axis + 2) % 3] -= 1.0;
        prim->resolveContact(p1, 0.0, d1);
        prim->resolveContact(p2, 0.0, d2);
        bool plane = d1[axis] != 0.0 && d1[axis] == d2[axis];
        for (int k = 0; k < 3; k++)
          if (k != axis && (d1[k] != 0.0 || d2[k] != 0.0)) plane = false;
        if (plane) w.plane_axis = axis;
      }
      walls_.push_back(w);
      continue;
    }
    for (int m = 0; m < fix->n_meshes(); m++) {
      FixMeshSurface *mesh = fix->mesh_list()[m];
      Wall w;
      w.id = mesh->id;
      w.fix = fix;
      w.mesh = mesh;
      w.factor_offset = offset;
      w.plane_axis = -1;
      for (size_t k = 0; k < walls_.size(); k++)
        if (walls_[k].id == w.id)
          error_all("mesh %s is used by two fix wall/gran (%s and %s): give each wall fix a mesh "
                    "of its own",
                    mesh->id, walls_[k].fix->id, fix->id);
      // the walk calls the mesh's neighbor list and contact tracker as the
      // wall fix does: their pre_force must have run before the caller's
      if (caller_fix >= 0 && need_factor_) {
        const int nl = mesh->meshNeighlist() ? modify->find_fix(mesh->meshNeighlist()->id) : -1;
        const int tr = mesh->contactHistory() ? modify->find_fix(mesh->contactHistory()->id) : -1;
        if (nl < 0 || nl > caller_fix || tr > caller_fix)
          error_all("define it after fix %s (wall/gran with mesh %s): the mesh's neighbor list "
                    "and contact tracker must be updated before it",
                    fix->id, mesh->id);
      }
      walls_.push_back(w);
    }
  }
}

int AcousticLiggghtsNetwork::wall_index(const std::string &id) const
{
  for (size_t k = 0; k < walls_.size(); k++)
    if (walls_[k].id == id) return static_cast<int>(k);
  return -1;
}

/* ----------------------------------------------------------------------
   the contacts of this processor's neighbor list between atoms of the
   group, with their Hertz stiffnesses (the overlap as pair gran sees it)
------------------------------------------------------------------------- */

void AcousticLiggghtsNetwork::collect(int groupbit)
{
  contacts_.clear();
  NeighList *list = pair_->list;
  NeighList *hlist = pair_->listgranhistory;
  if (factor_offset_ >= 0 && (!list || !hlist || !hlist->firstdouble))
    error_all("pair_style gran has no contact history list");
  if (!list) error_all("pair_style gran has no neighbor list");
  const char *who = caller_.c_str();
  double **Yeff = force->registry.getMatrixProperty("Yeff", who)->data;
  double **coeffFrict = force->registry.getMatrixProperty("coeffFrict", who)->data;
  const int dnum = pair_->dnum();
  double **x = atom->x;
  double *radius = atom->radius;
  int *mask = atom->mask;
  int *type = atom->type;
  int *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const double estar = youngs_modulus_ / (2.0 * (1.0 - poisson_ratio_ * poisson_ratio_));
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    const int *jlist = list->firstneigh[i];
    double *hist = factor_offset_ >= 0 ? hlist->firstdouble[i] : NULL;
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
      Contact c;
      c.i = i;
      c.j = j;
      c.wall = -1;
      // divided by r, as the LAMMPS walker (GranularContactWalker::linearise):
      // multiplied by 1/r, a normal differs in its last bit, and the softest
      // modes of a network amplify that by (f_max / f)^2
      c.n[0] = delx / r;
      c.n[1] = dely / r;
      c.n[2] = delz / r;
      // the elastic normal force of LIGGGHTS's hertz (normal_model_hertz.h)
      const double deltan = radsum - r;
      const double reff = radius[i] * radius[j] / (radius[i] + radius[j]);
      const double kn_pair = 4. / 3. * Yeff[type[i]][type[j]] * sqrt(reff * deltan);
      c.fn = kn_pair * deltan;
      // the Hertz stiffness at that force (the LAMMPS fix's hertz_kappa, hertz_normal_stiffness)
      const double rstar = 1.0 / (1.0 / radius[i] + 1.0 / radius[j]);
      const double kappa = kappa_scale_ * (4.0 / 3.0 * estar * sqrt(rstar));
      c.kn = (c.fn > 0.0) ? 1.5 * pow(kappa, 2.0 / 3.0) * cbrt(c.fn) : 0.0;
      c.kt = ratio_ * c.kn;
      c.mu = coeffFrict[type[i]][type[j]];
      c.slot = hist ? &hist[dnum * jj + factor_offset_] : NULL;
      c.counted = j < nlocal || tag[i] < tag[j];
      if (!(std::isfinite(c.fn) && std::isfinite(c.kn))) {
        char message[512];
        snprintf(message, sizeof(message),
                 "%s: a contact has a non-finite Hertz force or stiffness; check "
                 "youngsModulus, poissonsRatio and the keywords stiffness, kappa_scale",
                 who);
        error->one(FLERR, message);
      }
      contacts_.push_back(c);
    }
  }
  for (size_t w = 0; w < walls_.size(); w++) {
    if (walls_[w].mesh)
      collect_mesh(groupbit, static_cast<int>(w));
    else
      collect_primitive(groupbit, static_cast<int>(w));
  }
}

/* ----------------------------------------------------------------------
   the contact of owned atom i with wall w: delta from the grain's centre
   to the wall's closest point (as the wall fix's geometry gives it),
   overlap > 0
------------------------------------------------------------------------- */

void AcousticLiggghtsNetwork::add_wall_contact(int i, int w, const double *delta, double overlap,
                                               int wall_type, double *history)
{
  const char *who = caller_.c_str();
  double **Yeff = force->registry.getMatrixProperty("Yeff", who)->data;
  double **coeffFrict = force->registry.getMatrixProperty("coeffFrict", who)->data;
  const double r = atom->radius[i];
  const int itype = atom->type[i];
  const double dist = sqrt(delta[0] * delta[0] + delta[1] * delta[1] + delta[2] * delta[2]);
  Contact c;
  c.i = i;
  c.j = -1;
  c.wall = w;
  for (int k = 0; k < 3; k++) c.n[k] = -delta[k] / dist;
  // LIGGGHTS's hertz of a wall contact: R_eff = r_i (normal_model_hertz.h)
  const double kn_wall = 4. / 3. * Yeff[itype][wall_type] * sqrt(r * overlap);
  c.fn = kn_wall * overlap;
  // the Hertz stiffness of a grain on a flat body of infinite radius: R* = r_i
  const double estar = youngs_modulus_ / (2.0 * (1.0 - poisson_ratio_ * poisson_ratio_));
  const double rstar = 1.0 / (1.0 / r + 0.0);
  const double kappa = kappa_scale_ * (4.0 / 3.0 * estar * sqrt(rstar));
  c.kn = (c.fn > 0.0) ? 1.5 * pow(kappa, 2.0 / 3.0) * cbrt(c.fn) : 0.0;
  c.kt = ratio_ * c.kn;
  c.mu = coeffFrict[itype][wall_type];
  const int offset = walls_[w].factor_offset;
  c.slot = (need_factor_ && history && offset >= 0) ? history + offset : NULL;
  c.counted = true;
  if (!(dist > 0.0) || !(std::isfinite(c.fn) && std::isfinite(c.kn))) {
    char message[512];
    snprintf(message, sizeof(message),
             "%s: the contact of atom %d with %s %s has no normal or a non-finite Hertz force "
             "or stiffness (its centre on the wall?); check the wall and youngsModulus",
             who, atom->tag[i], walls_[w].mesh ? "mesh" : "wall", walls_[w].id.c_str());
    error->one(FLERR, message);
  }
  contacts_.push_back(c);
}

/* ----------------------------------------------------------------------
   On the first run after a wall fix was defined, Modify::setup sets every
   just-created per-atom fix to its defaults (FixPropertyAtom: the initial
   values, zero; FixContactHistory: no partner), after the setup_pre_force
   in which the walk writes into them: a primitive wall's factors would be
   lost, a mesh tracker's partner counts zeroed under its partners (which
   LIGGGHTS's own compute wall/gran/local then trips over).  Do that
   initialisation now instead, under the same condition: Modify::setup then
   finds nothing left to do but clear the flags, as it would have, and the
   arrays hold what they would have held before any contact was written.
------------------------------------------------------------------------- */

void AcousticLiggghtsNetwork::settle_just_created(Fix *fix)
{
  if (fix->recent_restart || !fix->just_created || !fix->create_attribute) return;
  fix->just_created = 0;
  fix->pre_set_arrays();
  int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & fix->groupbit) fix->set_arrays(i);
}

// a primitive wall: FixWallGran::post_force_primitive's contacts
void AcousticLiggghtsNetwork::collect_primitive(int groupbit, int w)
{
  FixWallGran *fix = walls_[w].fix;
  PrimitiveWall *prim = fix->primitiveWall();
  double **history = NULL;
  if (need_factor_ && walls_[w].factor_offset >= 0) {
    const std::string name = std::string("history_") + fix->id;
    const int ifix = modify->find_fix(name.c_str());
    FixPropertyAtom *hist = ifix >= 0 ? dynamic_cast<FixPropertyAtom *>(modify->fix[ifix]) : NULL;
    if (!hist || !hist->array_atom)
      error_all("fix %s (wall/gran) has no per-atom contact history (fix %s)", fix->id,
                name.c_str());
    settle_just_created(hist);
    history = hist->array_atom;
  }
  double **x = atom->x;
  double *radius = atom->radius;
  int *mask = atom->mask;
  const int wall_type = fix->atom_type_wall();
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit) || !(mask[i] & fix->groupbit)) continue;
    double delta[3] = {0.0, 0.0, 0.0};
    const double deltan = prim->resolveContact(x[i], radius[i], delta);
    if (!(deltan < 0.0)) continue;
    add_wall_contact(i, w, delta, -deltan, wall_type, history ? history[i] : NULL);
  }
}

// a mesh: FixWallGran::post_force_mesh's contacts (see the header)
void AcousticLiggghtsNetwork::collect_mesh(int groupbit, int w)
{
  FixMeshSurface *fmesh = walls_[w].mesh;
  TriMesh *mesh = fmesh->triMesh();
  FixNeighlistMesh *nlist = fmesh->meshNeighlist();
  FixContactHistoryMesh *tracker = fmesh->contactHistory();
  if (!nlist) error_all("mesh %s has no neighbor list (is it used by fix wall/gran?)", fmesh->id);
  const bool with_history = need_factor_ && walls_[w].factor_offset >= 0;
  if (with_history && !tracker)
    error_all("mesh %s has no contact tracker for its history", fmesh->id);
  double **x = atom->x;
  double *radius = atom->radius;
  int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const int wall_type = fmesh->atomTypeWall();
  const double contact_distance = neighbor->contactDistanceFactor - 1.0;
  // read-only: the triangles taken so far for each atom, and whether by a face
  std::vector<std::vector<std::pair<int, bool> > > taken;
  if (!with_history && tracker) taken.resize(nlocal);
  if (with_history) {
    settle_just_created(tracker);
    tracker->markAllContacts();
  }
  const int ntri = mesh->sizeLocal() + mesh->sizeGhost();
  for (int iTri = 0; iTri < ntri; iTri++) {
    const std::vector<int> &neighbors = nlist->get_contact_list(iTri);
    const int idTri = mesh->id(iTri);
    for (size_t k = 0; k < neighbors.size(); k++) {
      const int i = neighbors[k];
      if (i >= nlocal) continue;
      double delta[3] = {0.0, 0.0, 0.0}, bary[3];
      int barysign = -1;
      const double deltan =
          mesh->resolveTriSphereContactBary(i, iTri, radius[i], x[i], delta, bary, barysign, true);
      if (!(deltan <= 0.0 || deltan < contact_distance * radius[i])) continue;
      const bool face = (7 == barysign);
      double *history = NULL;
      if (with_history) {
        if (!tracker->handleContact(i, idTri, history, deltan <= 0.0, face)) continue;
      } else if (tracker) {
        // the tracker's rule, read only: known, or no coplanar one taken by now
        bool known = false;
        for (int p = 0; p < tracker->nneighs(i) && !known; p++)
          known = tracker->get_partner_idTri(i, p) == idTri;
        if (!known && face) {
          bool coplanar = false;
          for (size_t t = 0; t < taken[i].size() && !coplanar; t++)
            coplanar = taken[i][t].first != idTri &&
                mesh->areCoplanarNodeNeighs(taken[i][t].first, idTri);
          if (coplanar) continue;
        }
        taken[i].push_back(std::make_pair(idTri, face));
      }
      if (!(mask[i] & groupbit) || !(deltan < 0.0)) continue;
      add_wall_contact(i, w, delta, -deltan, wall_type, history);
    }
  }
}

/* ---------------------------------------------------------------------- */

void AcousticLiggghtsNetwork::gather_words(const std::vector<double> &mine,
                                           std::vector<double> &all)
{
  const int me = comm->me, nprocs = comm->nprocs;
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

void AcousticLiggghtsNetwork::gather(int groupbit, int flagbit,
                                     Acoustic::FacadeContactModel::Value model, Gathered &out)
{
  gather(groupbit, std::vector<int>(1, flagbit), model, out);
}

void AcousticLiggghtsNetwork::gather(int groupbit, const std::vector<int> &flagbits,
                                     Acoustic::FacadeContactModel::Value model, Gathered &out)
{
  if (flagbits.size() > 8) error_all("at most 8 flag groups");
  int *tag = atom->tag;
  int *mask = atom->mask;
  std::vector<double> grain_words, contact_words;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    grain_words.push_back(tag[i]);
    grain_words.push_back(atom->rmass[i]);
    grain_words.push_back(atom->radius[i]);
    int flags = 0;
    for (size_t k = 0; k < flagbits.size(); k++)
      if (mask[i] & flagbits[k]) flags |= 1 << k;
    grain_words.push_back(flags);
  }
  for (size_t k = 0; k < contacts_.size(); k++) {
    const Contact &c = contacts_[k];
    if (!c.counted || !(c.kn > 0.0)) continue;
    if (c.wall >= 0) {
      // the grain first, the wall second (its normal from the wall to the grain)
      contact_words.push_back(tag[c.i]);
      contact_words.push_back(-1.0 - c.wall);
      for (int d = 0; d < 3; d++) contact_words.push_back(c.n[d]);
      contact_words.push_back(c.kn);
      contact_words.push_back(c.kt);
      continue;
    }
    const bool flip = tag[c.i] > tag[c.j];
    const double sign = flip ? -1.0 : 1.0;
    contact_words.push_back(flip ? tag[c.j] : tag[c.i]);
    contact_words.push_back(flip ? tag[c.i] : tag[c.j]);
    for (int d = 0; d < 3; d++) contact_words.push_back(sign * c.n[d]);
    contact_words.push_back(c.kn);
    contact_words.push_back(c.kt);
  }
  std::vector<double> all_grains, all_contacts;
  gather_words(grain_words, all_grains);
  gather_words(contact_words, all_contacts);

  out.tags.clear();
  out.flag.clear();
  out.input = Acoustic::GatheredDriveInput();
  out.input.dimension = domain->dimension;
  out.input.model = model;
  if (comm->me != 0) return;

  const int ng = static_cast<int>(all_grains.size()) / GRAIN_WORDS;
  std::vector<std::pair<double, int> > order(ng);
  for (int g = 0; g < ng; g++) order[g] = std::make_pair(all_grains[GRAIN_WORDS * g], g);
  std::sort(order.begin(), order.end());
  out.tags.resize(ng);
  out.flag.resize(ng);
  for (int g = 0; g < ng; g++) {
    const double *w = &all_grains[GRAIN_WORDS * order[g].second];
    out.tags[g] = w[0];
    out.flag[g] = static_cast<char>(static_cast<int>(w[3]));
    out.input.grains.push_back(Acoustic::GatheredGrain(w[1], w[2]));
  }
  // the walls: nodes of infinite mass after every atom
  for (size_t k = 0; k < walls_.size(); k++)
    out.input.grains.push_back(Acoustic::GatheredGrain(HUGE_VAL, 1.0));
  const int nc = static_cast<int>(all_contacts.size()) / CONTACT_WORDS;
  for (int k = 0; k < nc; k++) {
    const double *w = &all_contacts[CONTACT_WORDS * k];
    Acoustic::GatheredContact c;
    c.i = static_cast<int>(std::lower_bound(out.tags.begin(), out.tags.end(), w[0]) -
                           out.tags.begin());
    c.j = (w[1] < 0.0) ? ng + static_cast<int>(-1.0 - w[1])
                       : static_cast<int>(std::lower_bound(out.tags.begin(), out.tags.end(), w[1]) -
                                          out.tags.begin());
    for (int d = 0; d < 3; d++) c.normal[d] = w[2 + d];
    c.kn = w[5];
    c.kt = w[6];
    out.input.contacts.push_back(c);
  }
}

/* ---------------------------------------------------------------------- */

void AcousticLiggghtsNetwork::broadcast(std::vector<double> &tags, std::vector<double> &q)
{
  int sizes[2] = {static_cast<int>(tags.size()), static_cast<int>(q.size())};
  MPI_Bcast(sizes, 2, MPI_INT, 0, world);
  tags.resize(sizes[0]);
  q.resize(sizes[1]);
  if (sizes[0] > 0) MPI_Bcast(&tags[0], sizes[0], MPI_DOUBLE, 0, world);
  if (sizes[1] > 0) MPI_Bcast(&q[0], sizes[1], MPI_DOUBLE, 0, world);
}

int AcousticLiggghtsNetwork::grain_index(const std::vector<double> &tags, double tag)
{
  const std::vector<double>::const_iterator it = std::lower_bound(tags.begin(), tags.end(), tag);
  if (it == tags.end() || *it != tag) return -1;
  return static_cast<int>(it - tags.begin());
}
