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
------------------------------------------------------------------------- */

#include "granular_contact_walker.h"

#include "atom.h"
#include "collective_error.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "fix_neigh_history.h"
#include "fix_wall_gran.h"
#include "fix_wall_gran_region.h"
#include "force.h"
#include "gran_sub_mod_normal.h"
#include "gran_sub_mod_tangential_acoustic.h"
#include "granular_model.h"
#include "modify.h"
#include "neigh_list.h"
#include "pair_granular.h"
#include "region.h"

#include <cmath>
#include <map>
#include <typeindex>
#include <typeinfo>

using namespace LAMMPS_NS;
using namespace Granular_NS;

// relative step of the centred difference dF_n/d(delta)
static constexpr double DIFFERENCE_STEP = 1.0e-4;
// fix wall/gran: its styles of plane, and the position of an absent plane (NULL)
enum { XPLANE = 0, YPLANE = 1, ZPLANE = 2 };
static constexpr double ABSENT_PLANE = 1.0e19;

namespace {

// the /acoustic interface of a model's tangential sub-model, nullptr if it has none
AcousticFrictionFactor *acoustic_tangential(GranularModel *model)
{
  return dynamic_cast<AcousticFrictionFactor *>(model->tangential_model);
}

// elastic normal force of the model at overlap delta, the rest of the
// contact geometry (Reff) being set; also sets the model's contact radius
double normal_force_at(GranularModel *model, double delta)
{
  model->delta = delta;
  model->dR = delta * model->Reff;
  model->contact_radius = model->normal_model->calculate_contact_radius();
  return model->normal_model->calculate_forces();
}

// The normal models whose force is a power of the overlap (plus a
// constant), keyed by their class (exactly: a class derived from one of
// them may change the force law), with the closed form of their stiffness.
enum class NormalLaw { LINEAR, HERTZ, DMT, OTHER };

NormalLaw normal_law(const GranSubModNormal *normal)
{
  static const std::map<std::type_index, NormalLaw> laws = {
      {typeid(GranSubModNormalHooke), NormalLaw::LINEAR},
      {typeid(GranSubModNormalHertz), NormalLaw::HERTZ},
      {typeid(GranSubModNormalHertzMaterial), NormalLaw::HERTZ},
      {typeid(GranSubModNormalDMT), NormalLaw::DMT}};
  const auto law = laws.find(typeid(*normal));
  return law == laws.end() ? NormalLaw::OTHER : law->second;
}

// dF_n/d(delta) at overlap delta where the force is fn: the closed form of
// the power laws, otherwise a centred difference of the model's own force
double normal_stiffness(GranularModel *model, double delta, double fn)
{
  switch (normal_law(model->normal_model)) {
    case NormalLaw::LINEAR:
      return model->normal_model->coeffs[0];
    case NormalLaw::HERTZ:
      return 1.5 * fn / delta;
    case NormalLaw::DMT: {
      // F = k a delta - 4 pi w Reff with a = sqrt(Reff delta)
      const double pulloff = 4.0 * M_PI * model->normal_model->coeffs[3] * model->Reff;
      return 1.5 * (fn + pulloff) / delta;
    }
    case NormalLaw::OTHER:
      break;
  }
  const double h = DIFFERENCE_STEP * fmax(fabs(delta), 1.0e-8 * model->Reff);
  const double fplus = normal_force_at(model, delta + h);
  const double fminus = normal_force_at(model, delta - h);
  return (fplus - fminus) / (2.0 * h);
}

}    // namespace

/* ---------------------------------------------------------------------- */

GranularContactWalker::GranularContactWalker(LAMMPS *lmp, const std::string &cmd) :
    Pointers(lmp), command(cmd), pair(nullptr), history(nullptr)
{
}

/* ---------------------------------------------------------------------- */

double GranularContactWalker::friction_factor(const double *factor)
{
  return AcousticFrictionFactor::friction_factor(factor);
}

void GranularContactWalker::set_friction_factor(double *factor, double s)
{
  AcousticFrictionFactor::set_friction_factor(factor, s);
}

/* ---------------------------------------------------------------------- */

void GranularContactWalker::locate()
{
  pair = dynamic_cast<PairGranular *>(force->pair_match("granular", 1));
  history = nullptr;
  if (!pair) return;
  for (auto *fix : modify->get_fix_by_style("^NEIGH_HISTORY$")) {
    auto *candidate = dynamic_cast<FixNeighHistory *>(fix);
    if (candidate && candidate->pair == pair) history = candidate;
  }
}

/* ---------------------------------------------------------------------- */

void GranularContactWalker::init(bool with_regions)
{
  region_walls = with_regions;
  locate();
  if (!pair)
    error->all(FLERR,
               "{} requires pair_style granular with a tangential <model>/acoustic "
               "sub-model (e.g. pair_coeff * * hertz/material 1e8 0.5 0.3 tangential "
               "mindlin/acoustic NULL 1.0 0.5)",
               command);
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "{} requires atom attributes radius and rmass (use atom_style sphere)",
               command);

  const int ntypes = atom->ntypes;
  for (int itype = 1; itype <= ntypes; itype++)
    for (int jtype = itype; jtype <= ntypes; jtype++)
      check_model(pair->models_list[pair->types_indices[itype][jtype]],
                  fmt::format("the contacts of atom types {} and {}", itype, jtype), true);

  if (!history)
    error->all(FLERR,
               "{}: pair_style granular keeps no contact history; its tangential models "
               "must be /acoustic ones",
               command);
  locate_walls(with_regions);
}

/* ----------------------------------------------------------------------
   the planes of fix wall/gran and the regions of fix wall/gran/region;
   other walls are free surfaces of the network
------------------------------------------------------------------------- */

void GranularContactWalker::locate_walls(bool with_regions)
{
  planes.clear();
  for (auto *fix : modify->get_fix_list()) {
    if (utils::strmatch(fix->style, "^wall/gran/region$")) {
      if (!with_regions) {
        error->warning(FLERR,
                       "{}: the contacts with fix {} (wall/gran/region) are not in the "
                       "vibration network (region_walls no): the wall is a free surface",
                       command, fix->id);
        continue;
      }
      check_model(dynamic_cast<FixWallGran *>(fix)->model,
                  fmt::format("the contacts with fix {}", fix->id), false);
      planes.push_back({fix->id, 0, -1, 0.0, true});
      continue;
    }
    if (!utils::strmatch(fix->style, "^wall/gran$")) continue;
    int dim = 0;
    const int *wallstyle = static_cast<int *>(fix->extract("wallstyle", dim));
    if (!wallstyle) {
      error->warning(FLERR,
                     "{}: fix {} cannot tell its contacts (a LAMMPS without the "
                     "ACOUSTIC patch fix-wall-gran-extract.patch): the wall is a free "
                     "surface of the vibration network",
                     command, fix->id);
      continue;
    }
    if (*wallstyle != XPLANE && *wallstyle != YPLANE && *wallstyle != ZPLANE) {
      error->warning(FLERR,
                     "{}: the contacts with fix {} (not a plane) are not in the vibration "
                     "network: the wall is a free surface",
                     command, fix->id);
      continue;
    }
    if (*static_cast<int *>(fix->extract("wiggle", dim)))
      error->all(FLERR,
                 "{}: fix {} wall/gran wiggles; a moving wall cannot be part of the "
                 "vibration network (remove wiggle, or make it a source with wall)",
                 command, fix->id);
    auto *model = dynamic_cast<FixWallGran *>(fix)->model;
    check_model(model, fmt::format("the contacts with fix {}", fix->id), false);
    const double lo = *static_cast<double *>(fix->extract("lo", dim));
    const double hi = *static_cast<double *>(fix->extract("hi", dim));
    if (lo > -ABSENT_PLANE) planes.push_back({fix->id, 0, *wallstyle, lo, false});
    if (hi < ABSENT_PLANE) planes.push_back({fix->id, 1, *wallstyle, hi, false});
  }
}

/* ---------------------------------------------------------------------- */

void GranularContactWalker::check_model(GranularModel *model, const std::string &where,
                                        bool needs_factor)
{
  const std::string &tangential = model->tangential_model->name;
  if (needs_factor && !acoustic_tangential(model))
    error->all(FLERR,
               "{}: {} use tangential model {}, which has no friction factor; use "
               "tangential {}/acoustic in pair_coeff",
               command, where, tangential, tangential);
  const std::string &normal = model->normal_model->name;
  const bool closed_form = normal_law(model->normal_model) != NormalLaw::OTHER;
  if (!closed_form && model->normal_model->size_history > 0)
    error->all(FLERR,
               "{}: {} use normal model {}, whose force depends on the loading history "
               "and cannot be linearised; use hooke, hertz, hertz/material, dmt or jkr",
               command, where, normal);
}

/* ---------------------------------------------------------------------- */

void GranularContactWalker::linearise(GranularModel *model, GranularContact &c)
{
  const double r = sqrt(model->rsq);
  c.delta = model->radsum - r;
  for (int k = 0; k < 3; k++) c.n[k] = model->dx[k] / r;

  c.fn = normal_force_at(model, c.delta);
  const double contact_radius = model->contact_radius;
  model->Fntot = c.fn;    // the Coulomb limit of the elastic force
  model->normal_model->set_fncrit();
  c.fncrit = model->normal_model->get_fncrit();
  c.kn = normal_stiffness(model, c.delta, c.fn);

  AcousticFrictionFactor *tangential = acoustic_tangential(model);
  c.mu = model->tangential_model->get_mu();
  if (tangential) {
    c.kt = tangential->tangential_stiffness(contact_radius);
    c.factor = model->history ? model->history + tangential->friction_factor_index() : nullptr;
  } else {
    // a wall without the /acoustic variant: the stiffness of its tangential
    // spring (k, or k a for the models that scale it), no friction factor
    const double k = model->tangential_model->get_k();
    c.kt = model->tangential_model->contact_radius_flag ? k * contact_radius : k;
    c.factor = nullptr;
  }
}

/* ---------------------------------------------------------------------- */

void GranularContactWalker::collect(std::vector<GranularContact> &contacts, int groupbit,
                                    CollectiveError &errors)
{
  contacts.clear();
  // pair granular as it is now (it may have been defined again since init())
  auto *current = dynamic_cast<PairGranular *>(force->pair_match("granular", 1));
  if (!pair || current != pair) init(region_walls);
  if (!neighbor_history_ready())
    error->all(FLERR,
               "{}: pair granular has no neighbor list yet (a new pair style since the "
               "last run); use 'run 0' first",
               command);
  collect_pair(contacts, groupbit, errors);
  collect_walls(contacts, groupbit, errors);
}

/* ----------------------------------------------------------------------
   the pair's neighbor list and contact history exist on every rank (a rank
   without atoms has no history arrays, and needs none)
------------------------------------------------------------------------- */

bool GranularContactWalker::neighbor_history_ready() const
{
  int ready = (pair && history && pair->list && (pair->list->inum == 0 || history->firstflag)) ? 1
                                                                                               : 0;
  int ready_everywhere = 0;
  MPI_Allreduce(&ready, &ready_everywhere, 1, MPI_INT, MPI_MIN, world);
  return ready_everywhere == 1;
}

/* ---------------------------------------------------------------------- */

void GranularContactWalker::collect_pair(std::vector<GranularContact> &contacts, int groupbit,
                                         CollectiveError &errors)
{
  double **x = atom->x;
  double *radius = atom->radius;
  int *type = atom->type;
  int *mask = atom->mask;
  tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const bool newton = force->newton_pair;
  const double *special_lj = force->special_lj;
  const int size_history = pair->get_size_history();

  NeighList *list = pair->list;
  int **firsttouch = history->firstflag;
  double **firstvalue = history->firstvalue;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    const int *jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      if (special_lj[(jlist[jj] >> SBBITS) & 3] == 0.0) continue;    // excluded, as in the pair
      const int j = jlist[jj] & NEIGHMASK;
      if (!(mask[j] & groupbit)) continue;

      GranularModel *model = pair->models_list[pair->types_indices[type[i]][type[j]]];
      model->xi = x[i];
      model->xj = x[j];
      model->radi = radius[i];
      model->radj = radius[j];
      model->i = i;
      model->j = j;
      model->itype = type[i];
      model->jtype = type[j];
      model->touch = firsttouch[i][jj];
      if (!model->check_contact()) continue;
      if (model->rsq == 0.0) {
        errors.report(fmt::format("{}: atoms {} and {} are at the same position: their contact "
                                  "has no normal",
                                  command, tag[i], tag[j]));
        continue;
      }
      model->history = &firstvalue[i][size_history * jj];

      GranularContact c;
      c.i = i;
      c.j = j;
      c.wall = -1;
      c.owned = newton || j < nlocal || tag[i] < tag[j];
      c.radi = radius[i];
      c.radj = radius[j];
      linearise(model, c);
      if (!(std::isfinite(c.fn) && std::isfinite(c.fncrit) && std::isfinite(c.kn) &&
            std::isfinite(c.kt))) {
        errors.report(fmt::format("{}: contact of atoms {} and {} (overlap {}): its normal model "
                                  "{} gives F_n = {}, k_n = {}, k_t = {}; check its coefficients",
                                  command, tag[i], tag[j], c.delta, model->normal_model->name, c.fn,
                                  c.kn, c.kt));
        continue;
      }
      contacts.push_back(c);
    }
  }
}

/* ---------------------------------------------------------------------- */

bool GranularContactWalker::reset_factors_between_runs(int groupbit)
{
  locate();
  if (!neighbor_history_ready()) return false;

  int *type = atom->type;
  int *mask = atom->mask;
  const int size_history = pair->get_size_history();
  NeighList *list = pair->list;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!(mask[j] & groupbit) || !history->firstflag[i][jj]) continue;
      GranularModel *model = pair->models_list[pair->types_indices[type[i]][type[j]]];
      AcousticFrictionFactor *tangential = acoustic_tangential(model);
      if (!tangential) continue;
      double *values = &history->firstvalue[i][size_history * jj];
      set_friction_factor(values + tangential->friction_factor_index(), 1.0);
    }
  }
  history->pre_exchange();

  // the walls keep their histories with the atoms: set them directly
  for (auto *fix : modify->get_fix_list()) {
    auto *region_wall = dynamic_cast<FixWallGranRegion *>(fix);
    if (region_wall) {
      AcousticFrictionFactor *tangential = acoustic_tangential(region_wall->model);
      if (!region_wall->history_many || !region_wall->ncontact || !tangential) continue;
      for (int i = 0; i < atom->nlocal; i++)
        if ((mask[i] & groupbit) && (mask[i] & fix->groupbit))
          for (int k = 0; k < region_wall->ncontact[i]; k++)
            set_friction_factor(
                region_wall->history_many[i][k] + tangential->friction_factor_index(), 1.0);
      continue;
    }
    if (!utils::strmatch(fix->style, "^wall/gran$")) continue;
    int dim = 0;
    auto **history_one = static_cast<double **>(fix->extract("history", dim));
    AcousticFrictionFactor *tangential =
        acoustic_tangential(dynamic_cast<FixWallGran *>(fix)->model);
    if (!history_one || !tangential) continue;
    for (int i = 0; i < atom->nlocal; i++)
      if ((mask[i] & groupbit) && (mask[i] & fix->groupbit))
        set_friction_factor(history_one[i] + tangential->friction_factor_index(), 1.0);
  }
  return true;
}

/* ----------------------------------------------------------------------
   the touching contact of owned atom i with a wall, whose geometry and
   history the model holds: linearised and added, or reported when its
   normal model gives a non-finite force or stiffness
------------------------------------------------------------------------- */

void GranularContactWalker::add_wall_contact(GranularModel *model, int i, int wall,
                                             std::vector<GranularContact> &contacts,
                                             CollectiveError &errors)
{
  GranularContact c;
  c.i = i;
  c.j = -1;
  c.wall = wall;
  c.owned = true;
  c.radi = atom->radius[i];
  c.radj = 0.0;    // a rigid wall
  linearise(model, c);
  if (!(std::isfinite(c.fn) && std::isfinite(c.fncrit) && std::isfinite(c.kn) &&
        std::isfinite(c.kt))) {
    errors.report(fmt::format("{}: contact of atom {} with fix {}: its normal model {} gives "
                              "F_n = {}, k_n = {}, k_t = {}; check its coefficients",
                              command, atom->tag[i], planes[wall].fix_id, model->normal_model->name,
                              c.fn, c.kn, c.kt));
    return;
  }
  contacts.push_back(c);
}

/* ----------------------------------------------------------------------
   contacts of owned atoms with the wall planes, as fix wall/gran finds them:
   each atom of the wall's group touches at most the nearer of its planes
------------------------------------------------------------------------- */

void GranularContactWalker::collect_walls(std::vector<GranularContact> &contacts, int groupbit,
                                          CollectiveError &errors)
{
  double **x = atom->x;
  double *radius = atom->radius;
  int *mask = atom->mask;
  tagint *tag = atom->tag;
  for (std::size_t p = 0; p < planes.size(); p++) {
    const WallPlane &plane = planes[p];
    if (plane.region) {
      collect_region_wall(contacts, groupbit, static_cast<int>(p), errors);
      continue;
    }
    auto *fix = dynamic_cast<FixWallGran *>(modify->get_fix_by_id(plane.fix_id));
    if (!fix) {
      errors.report(
          fmt::format("{}: fix {} (wall/gran) was deleted since the last run; use 'run 0' "
                      "first",
                      command, plane.fix_id));
      continue;
    }
    GranularModel *model = fix->model;
    int dim = 0;
    auto **history_one = static_cast<double **>(fix->extract("history", dim));
    const double lo = *static_cast<double *>(fix->extract("lo", dim));
    const double hi = *static_cast<double *>(fix->extract("hi", dim));
    const int axis = plane.axis;
    for (int i = 0; i < atom->nlocal; i++) {
      if (!(mask[i] & groupbit) || !(mask[i] & fix->groupbit)) continue;
      // the nearer plane, and the signed distance from it (FixWallGran::post_force)
      const double below = x[i][axis] - lo, above = hi - x[i][axis];
      const int side = (below < above) ? 0 : 1;
      if (side != plane.side) continue;
      for (int k = 0; k < 3; k++) model->dx[k] = 0.0;
      model->dx[axis] = (side == 0) ? below : -above;
      model->radi = radius[i];
      model->radj = 0.0;
      model->history = history_one ? history_one[i] : nullptr;
      if (model->beyond_contact) model->touch = history_one && history_one[i][0] != 0.0;
      if (!model->check_contact()) continue;
      if (model->rsq == 0.0) {
        errors.report(fmt::format("{}: the centre of atom {} lies on the plane of fix {}: the "
                                  "contact has no normal",
                                  command, tag[i], plane.fix_id));
        continue;
      }
      add_wall_contact(model, i, static_cast<int>(p), contacts, errors);
    }
  }
}

/* ----------------------------------------------------------------------
   contacts of owned atoms with the surface of the region of a fix
   wall/gran/region, as the fix finds them (FixWallGranRegion::post_force):
   the region where it is now (a moving region at its current displacement,
   taken at rest), its contact history matched by the region's wall index
------------------------------------------------------------------------- */

void GranularContactWalker::collect_region_wall(std::vector<GranularContact> &contacts,
                                                int groupbit, int wall, CollectiveError &errors)
{
  const std::string &fix_id = planes[wall].fix_id;
  auto *fix = dynamic_cast<FixWallGranRegion *>(modify->get_fix_by_id(fix_id));
  if (!fix) {
    errors.report(fmt::format("{}: fix {} (wall/gran/region) was deleted since the last run; use "
                              "'run 0' first",
                              command, fix_id));
    return;
  }
  // the fix's region, unless it was deleted since the fix's last init()
  bool region_exists = false;
  for (auto *region : domain->get_region_list()) region_exists |= (region == fix->region);
  if (!region_exists) {
    errors.report(fmt::format("{}: the region of fix {} (wall/gran/region) changed since the last "
                              "run; use 'run 0' first",
                              command, fix_id));
    return;
  }
  Region *region = fix->region;
  if (region->dynamic_check()) region->prematch();

  GranularModel *model = fix->model;
  double **x = atom->x;
  double *radius = atom->radius;
  int *mask = atom->mask;
  tagint *tag = atom->tag;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit) || !(mask[i] & fix->groupbit)) continue;
    if (!region->match(x[i][0], x[i][1], x[i][2])) continue;
    const int nc = region->surface(x[i][0], x[i][1], x[i][2],
                                   radius[i] + model->pulloff_distance(radius[i], 0.0));
    for (int ic = 0; ic < nc; ic++) {
      // the stored history of this region wall, if the fix has one
      double *history_of_contact = nullptr;
      if (fix->history_many && fix->ncontact)
        for (int k = 0; k < fix->ncontact[i]; k++)
          if (fix->walls[i][k] == region->contact[ic].iwall)
            history_of_contact = fix->history_many[i][k];
      model->dx[0] = region->contact[ic].delx;
      model->dx[1] = region->contact[ic].dely;
      model->dx[2] = region->contact[ic].delz;
      model->radi = radius[i];
      model->radj = region->contact[ic].radius;
      model->r = region->contact[ic].r;
      model->history = history_of_contact;
      if (model->beyond_contact) model->touch = history_of_contact && history_of_contact[0] != 0.0;
      if (!model->check_contact()) continue;
      if (model->rsq == 0.0) {
        errors.report(fmt::format("{}: the centre of atom {} lies on the surface of the region of "
                                  "fix {}: the contact has no normal",
                                  command, tag[i], fix_id));
        continue;
      }
      add_wall_contact(model, i, wall, contacts, errors);
    }
  }
}
