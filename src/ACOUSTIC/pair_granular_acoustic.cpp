/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   Steve Plimpton, sjplimp@sandia.gov

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Contributing authors: the ACOUSTIC package developers.

   pair_style granular/acoustic: the contact models of pair_style granular
   with one more value in each contact's history, the friction factor s of
   the contact, which scales its Coulomb limit.  fix acoustic/mindlin sets
   it from the ultrasonic vibration the contact feels.
------------------------------------------------------------------------- */

#include "pair_granular_acoustic.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "fix_dummy.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

static const char HISTORY_FIX_ID[] = "NEIGH_HISTORY_GRANULAR_ACOUSTIC";
static const char HISTORY_DUMMY_ID[] = "NEIGH_HISTORY_GRANULAR_ACOUSTIC_DUMMY";

/* ---------------------------------------------------------------------- */

PairGranularAcoustic::PairGranularAcoustic(LAMMPS *lmp) : Pair(lmp)
{
  single_enable = 1;
  no_virial_fdotr_compute = 1;
  centroidstressflag = CENTROID_NOTAVAIL;
  finitecutflag = 1;

  // single() extras: as pair granular, plus the friction factor s
  single_extra = 13;
  svector = new double[single_extra];

  dt = update->dt;
  freeze_group_bit = 0;
  ntypes_allocated = 0;
  cutoff_global = -1.0;
  beyond_contact = 0;
  beyond_contact_any = 0;
  nondefault_history_transfer = 1;

  onerad_dynamic = onerad_frozen = maxrad_dynamic = maxrad_frozen = nullptr;
  fix_rigid = nullptr;
  mass_rigid = nullptr;
  nmax = 0;
  neighprev = 0;
  history_size_created = 0;
  comm_forward = 1;

  // a dummy fix stands in for the history fix until init_style() creates it,
  // so that the history fix keeps this place in the fix list (as pair granular)
  fix_history = nullptr;
  fix_dummy = (FixDummy *) modify->add_fix(std::string(HISTORY_DUMMY_ID) + " all DUMMY");
}

/* ---------------------------------------------------------------------- */

PairGranularAcoustic::~PairGranularAcoustic()
{
  delete[] svector;
  if (!fix_history) modify->delete_fix(HISTORY_DUMMY_ID);
  else modify->delete_fix(HISTORY_FIX_ID);

  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    delete[] onerad_dynamic;
    delete[] onerad_frozen;
    delete[] maxrad_dynamic;
    delete[] maxrad_frozen;
  }
  memory->destroy(mass_rigid);
}

/* ---------------------------------------------------------------------- */

void PairGranularAcoustic::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  ntypes_allocated = n;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) setflag[i][j] = 0;
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  laws.assign((n + 1) * (n + 1), GranularContactLaw());
  onerad_dynamic = new double[n + 1];
  onerad_frozen = new double[n + 1];
  maxrad_dynamic = new double[n + 1];
  maxrad_frozen = new double[n + 1];
}

/* ---------------------------------------------------------------------- */

void PairGranularAcoustic::settings(int narg, char **arg)
{
  if (narg > 1)
    error->all(FLERR, "Illegal pair_style granular/acoustic command: expected at most one "
                      "argument (a global cutoff), got {}", narg);
  cutoff_global = (narg == 1) ? utils::numeric(FLERR, arg[0], false, lmp) : -1.0;
}

/* ---------------------------------------------------------------------- */

void PairGranularAcoustic::coeff(int narg, char **arg)
{
  if (narg < 2)
    error->all(FLERR, "Incorrect args for pair_coeff of granular/acoustic: "
                      "pair_coeff I J <models>; models: {}", GranularContactLaw::supported_models());
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  std::vector<std::string> words(arg + 2, arg + narg);
  GranularContactLaw one;
  const std::string msg = one.parse(words);
  if (!msg.empty()) error->all(FLERR, "Illegal pair_coeff command for granular/acoustic: {}", msg);

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      law(i, j) = law(j, i) = one;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients: no type pair selected");
}

/* ---------------------------------------------------------------------- */

void PairGranularAcoustic::init_style()
{
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "Pair granular/acoustic requires atom attributes radius and rmass "
                      "(use atom_style sphere)");
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "Pair granular/acoustic requires ghost atoms to store velocity "
                      "(use comm_modify vel yes)");

  // history layout, the same for all type pairs (as in pair granular), plus the factor
  const int n = atom->ntypes;
  bool tangential = false, rescale = false, roll = false, twist = false;
  beyond_contact_any = 0;
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) {
      const GranularContactLaw &l = law(i, j);
      tangential |= l.has_tangential_history();
      rescale |= l.has_rescale_history();
      roll |= (l.roll != GranularContactLaw::ROLL_NONE);
      twist |= (l.twist != GranularContactLaw::TWIST_NONE);
      if (l.beyond_contact()) beyond_contact_any = 1;
    }
  beyond_contact = beyond_contact_any;
  layout = GranularContactLaw::HistoryLayout();
  int next = 0;
  if (tangential) {
    layout.tangential = next;
    next += 3;
    if (rescale) layout.rescale = next++;
  }
  if (roll) {
    layout.roll = next;
    next += 3;
  }
  if (twist) layout.twist = next++;
  layout.reduction = next++;
  layout.size = next;

  // on a swap of i and j, vectors change sign; the contact radius and the factor do not
  history_transfer_factors.assign(layout.size, -1);
  if (layout.rescale >= 0) history_transfer_factors[layout.rescale] = 1;
  history_transfer_factors[layout.reduction] = 1;

  int irequest = neighbor->request(this, instance_me);
  neighbor->requests[irequest]->size = 1;
  neighbor->requests[irequest]->history = 1;

  dt = update->dt;

  if (fix_history == nullptr) {
    fix_history = (FixNeighHistory *) modify->replace_fix(
        HISTORY_DUMMY_ID, fmt::format("{} all NEIGH_HISTORY/ACOUSTIC {}", HISTORY_FIX_ID, layout.size), 1);
    fix_history->pair = this;
    history_size_created = layout.size;
  } else {
    int ifix = modify->find_fix(HISTORY_FIX_ID);
    if (ifix < 0) error->all(FLERR, "Could not find the history fix of pair granular/acoustic");
    fix_history = (FixNeighHistory *) modify->fix[ifix];
    if (history_size_created != layout.size)
      error->all(FLERR, "Pair granular/acoustic: the contact models changed the size of the "
                        "contact history between runs; use the same models for the whole input");
  }

  int ifix = modify->find_fix_by_style("^freeze");
  freeze_group_bit = (ifix < 0) ? 0 : modify->fix[ifix]->groupbit;

  fix_rigid = nullptr;
  for (int i = 0; i < modify->nfix; i++)
    if (modify->fix[i]->rigid_flag) {
      fix_rigid = modify->fix[i];
      break;
    }

  // largest radii of dynamic and frozen atoms per type, including future poured atoms
  int ipour = modify->find_fix_by_style("^pour");
  int idep = modify->find_fix_by_style("^deposit");
  for (int i = 1; i <= n; i++) {
    onerad_dynamic[i] = onerad_frozen[i] = 0.0;
    int itype = i;
    if (ipour >= 0) onerad_dynamic[i] = *((double *) modify->fix[ipour]->extract("radius", itype));
    if (idep >= 0) onerad_dynamic[i] = *((double *) modify->fix[idep]->extract("radius", itype));
  }
  double *radius = atom->radius;
  int *mask = atom->mask;
  int *type = atom->type;
  for (int i = 0; i < atom->nlocal; i++) {
    if (mask[i] & freeze_group_bit)
      onerad_frozen[type[i]] = MAX(onerad_frozen[type[i]], radius[i]);
    else
      onerad_dynamic[type[i]] = MAX(onerad_dynamic[type[i]], radius[i]);
  }
  MPI_Allreduce(&onerad_dynamic[1], &maxrad_dynamic[1], n, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(&onerad_frozen[1], &maxrad_frozen[1], n, MPI_DOUBLE, MPI_MAX, world);
}

/* ---------------------------------------------------------------------- */

double PairGranularAcoustic::init_one(int i, int j)
{
  if (setflag[i][j] == 0) {
    const std::string msg = law(i, j).mix(law(i, i), law(j, j));
    if (!msg.empty())
      error->all(FLERR, "Pair granular/acoustic cannot mix coefficients for types {} and {}: "
                        "{}; set this pair explicitly with pair_coeff {} {}", i, j, msg, i, j);
    law(j, i) = law(i, j);
  }
  const GranularContactLaw &l = law(i, j);

  double cutoff = 0.0;
  if (l.cutoff < 0 && cutoff_global < 0) {
    if ((maxrad_dynamic[i] > 0.0 && maxrad_dynamic[j] > 0.0) ||
        (maxrad_dynamic[i] > 0.0 && maxrad_frozen[j] > 0.0) ||
        (maxrad_frozen[i] > 0.0 && maxrad_dynamic[j] > 0.0)) {
      // radii of both types are known: largest contact distance, with JKR pull-off
      cutoff = maxrad_dynamic[i] + maxrad_dynamic[j] +
          l.pulloff_distance(maxrad_dynamic[i], maxrad_dynamic[j]);
      cutoff = MAX(cutoff, maxrad_frozen[i] + maxrad_dynamic[j] +
                       l.pulloff_distance(maxrad_frozen[i], maxrad_dynamic[j]));
      cutoff = MAX(cutoff, maxrad_dynamic[i] + maxrad_frozen[j] +
                       l.pulloff_distance(maxrad_dynamic[i], maxrad_frozen[j]));
    } else {
      // radius of i or j not known yet: largest cutoff of the system
      double cutmax = 0.0;
      for (int k = 1; k <= atom->ntypes; k++) {
        cutmax = MAX(cutmax, 2.0 * maxrad_dynamic[k]);
        cutmax = MAX(cutmax, 2.0 * maxrad_frozen[k]);
      }
      cutoff = cutmax;
    }
  } else if (l.cutoff > 0) {
    cutoff = l.cutoff;
  } else if (cutoff_global > 0) {
    cutoff = cutoff_global;
  }
  return cutoff;
}

/* ---------------------------------------------------------------------- */

void PairGranularAcoustic::update_rigid_masses()
{
  int tmp;
  int *body = (int *) fix_rigid->extract("body", tmp);
  double *mass_body = (double *) fix_rigid->extract("masstotal", tmp);
  if (atom->nmax > nmax) {
    memory->destroy(mass_rigid);
    nmax = atom->nmax;
    memory->create(mass_rigid, nmax, "pair:mass_rigid");
  }
  for (int i = 0; i < atom->nlocal; i++) mass_rigid[i] = (body[i] >= 0) ? mass_body[body[i]] : 0.0;
  comm->forward_comm_pair(this);
}

/* ----------------------------------------------------------------------
   effective mass of a pair; rigid bodies count with their mass, a frozen
   atom leaves the mass of its partner
------------------------------------------------------------------------- */

double PairGranularAcoustic::effective_mass(int i, int j) const
{
  double mi = atom->rmass[i];
  double mj = atom->rmass[j];
  if (fix_rigid) {
    if (mass_rigid[i] > 0.0) mi = mass_rigid[i];
    if (mass_rigid[j] > 0.0) mj = mass_rigid[j];
  }
  double meff = mi * mj / (mi + mj);
  if (atom->mask[i] & freeze_group_bit) meff = mj;
  if (atom->mask[j] & freeze_group_bit) meff = mi;
  return meff;
}

/* ---------------------------------------------------------------------- */

void PairGranularAcoustic::fill_contact(GranularContactLaw::Contact &c, int i, int j,
                                        double delx, double dely, double delz, double rsq) const
{
  double **v = atom->v;
  double **omega = atom->omega;
  c.del[0] = delx;
  c.del[1] = dely;
  c.del[2] = delz;
  c.rsq = rsq;
  c.radi = atom->radius[i];
  c.radj = atom->radius[j];
  c.vr[0] = v[i][0] - v[j][0];
  c.vr[1] = v[i][1] - v[j][1];
  c.vr[2] = v[i][2] - v[j][2];
  c.omegai = omega[i];
  c.omegaj = omega[j];
  c.meff = effective_mass(i, j);
  c.dt = dt;
}

/* ---------------------------------------------------------------------- */

void PairGranularAcoustic::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (fix_rigid && neighbor->ago == 0) update_rigid_masses();

  double **x = atom->x;
  double **f = atom->f;
  double **torque = atom->torque;
  double *radius = atom->radius;
  int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;

  const int inum = list->inum;
  int *ilist = list->ilist;
  int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  int **firsttouch = fix_history->firstflag;
  double **firsthistory = fix_history->firstvalue;
  const int nhistory = layout.size;

  GranularContactLaw::Contact c;
  c.history_update = !update->setupflag;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int itype = type[i];
    const double xtmp = x[i][0], ytmp = x[i][1], ztmp = x[i][2];
    const double radi = radius[i];
    int *touch = firsttouch[i];
    double *allhistory = firsthistory[i];
    int *jlist = firstneigh[i];
    const int jnum = numneigh[i];

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = xtmp - x[j][0];
      const double dely = ytmp - x[j][1];
      const double delz = ztmp - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const GranularContactLaw &l = law(itype, type[j]);
      double *history = &allhistory[nhistory * jj];

      if (rsq >= l.touch_distance_sq(radi, radius[j], touch[jj])) {
        // not in contact: the contact, if any, is lost with its history
        touch[jj] = 0;
        for (int k = 0; k < nhistory; k++) history[k] = 0.0;
        continue;
      }
      touch[jj] = 1;

      fill_contact(c, i, j, delx, dely, delz, rsq);
      l.normal_force(c);
      l.tangential_force(c, history, layout, friction_factor(history));
      l.rolling_force(c, history, layout);
      l.twisting_torque(c, history, layout);

      // forces and torques on i and j
      const double *n = c.n;
      const double *fs = c.fs;
      const double fx = n[0] * c.Fntot + fs[0];
      const double fy = n[1] * c.Fntot + fs[1];
      const double fz = n[2] * c.Fntot + fs[2];
      f[i][0] += fx;
      f[i][1] += fy;
      f[i][2] += fz;

      const double tor1 = n[1] * fs[2] - n[2] * fs[1];
      const double tor2 = n[2] * fs[0] - n[0] * fs[2];
      const double tor3 = n[0] * fs[1] - n[1] * fs[0];
      const bool twisting = (l.twist != GranularContactLaw::TWIST_NONE);
      const bool rolling = (l.roll != GranularContactLaw::ROLL_NONE);
      double tortwist[3] = {0.0, 0.0, 0.0}, torroll[3] = {0.0, 0.0, 0.0};
      if (twisting)
        for (int k = 0; k < 3; k++) tortwist[k] = c.magtortwist * n[k];
      if (rolling) {
        const double *fr = c.fr;
        torroll[0] = c.Reff * (n[1] * fr[2] - n[2] * fr[1]);
        torroll[1] = c.Reff * (n[2] * fr[0] - n[0] * fr[2]);
        torroll[2] = c.Reff * (n[0] * fr[1] - n[1] * fr[0]);
      }

      double dist_to_contact = radi - 0.5 * c.delta;
      torque[i][0] -= dist_to_contact * tor1;
      torque[i][1] -= dist_to_contact * tor2;
      torque[i][2] -= dist_to_contact * tor3;
      if (twisting)
        for (int k = 0; k < 3; k++) torque[i][k] += tortwist[k];
      if (rolling)
        for (int k = 0; k < 3; k++) torque[i][k] += torroll[k];

      if (newton_pair || j < nlocal) {
        f[j][0] -= fx;
        f[j][1] -= fy;
        f[j][2] -= fz;
        dist_to_contact = radius[j] - 0.5 * c.delta;
        torque[j][0] -= dist_to_contact * tor1;
        torque[j][1] -= dist_to_contact * tor2;
        torque[j][2] -= dist_to_contact * tor3;
        if (twisting)
          for (int k = 0; k < 3; k++) torque[j][k] -= tortwist[k];
        if (rolling)
          for (int k = 0; k < 3; k++) torque[j][k] -= torroll[k];
      }

      if (evflag)
        ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
    }
  }
}

/* ---------------------------------------------------------------------- */

void PairGranularAcoustic::current_contacts(std::vector<ContactState> &contacts, int groupbit)
{
  contacts.clear();
  if (!list || !fix_history) return;

  double **x = atom->x;
  double *radius = atom->radius;
  int *type = atom->type;
  int *mask = atom->mask;
  int **firsttouch = fix_history->firstflag;
  double **firsthistory = fix_history->firstvalue;

  GranularContactLaw::Contact c;
  c.history_update = false;
  ContactState s;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!(mask[j] & groupbit)) continue;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const GranularContactLaw &l = law(type[i], type[j]);
      if (rsq >= l.touch_distance_sq(radius[i], radius[j], firsttouch[i][jj])) continue;

      fill_contact(c, i, j, delx, dely, delz, rsq);
      l.normal_force(c);
      s.i = i;
      s.j = j;
      for (int k = 0; k < 3; k++) s.n[k] = c.n[k];
      s.delta = c.delta;
      s.radi = c.radi;
      s.radj = c.radj;
      s.fn = c.Fne;
      s.mu = l.mu;
      s.kn = l.normal_stiffness(c);
      s.kt = l.tangential_stiffness(c);
      s.history = &firsthistory[i][layout.size * jj];
      contacts.push_back(s);
    }
  }
}

/* ---------------------------------------------------------------------- */

void PairGranularAcoustic::store_history_between_runs()
{
  if (fix_history && fix_history->firstvalue) fix_history->pre_exchange();
}

/* ---------------------------------------------------------------------- */

void PairGranularAcoustic::transfer_history(double *source, double *target)
{
  for (int k = 0; k < layout.size; k++) target[k] = history_transfer_factors[k] * source[k];
}

/* ---------------------------------------------------------------------- */

void PairGranularAcoustic::write_restart(FILE *fp)
{
  int iv[GranularContactLaw::NINT];
  double dv[GranularContactLaw::NDOUBLE];
  for (int i = 1; i <= atom->ntypes; i++) {
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j]) {
        law(i, j).pack(iv, dv);
        fwrite(iv, sizeof(int), GranularContactLaw::NINT, fp);
        fwrite(dv, sizeof(double), GranularContactLaw::NDOUBLE, fp);
      }
    }
  }
}

/* ---------------------------------------------------------------------- */

void PairGranularAcoustic::read_restart(FILE *fp)
{
  allocate();
  int iv[GranularContactLaw::NINT];
  double dv[GranularContactLaw::NDOUBLE];
  const int me = comm->me;
  for (int i = 1; i <= atom->ntypes; i++) {
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (setflag[i][j]) {
        if (me == 0) {
          utils::sfread(FLERR, iv, sizeof(int), GranularContactLaw::NINT, fp, nullptr, error);
          utils::sfread(FLERR, dv, sizeof(double), GranularContactLaw::NDOUBLE, fp, nullptr, error);
        }
        MPI_Bcast(iv, GranularContactLaw::NINT, MPI_INT, 0, world);
        MPI_Bcast(dv, GranularContactLaw::NDOUBLE, MPI_DOUBLE, 0, world);
        law(i, j).unpack(iv, dv);
        law(j, i) = law(i, j);
      }
    }
  }
}

/* ---------------------------------------------------------------------- */

void PairGranularAcoustic::write_restart_settings(FILE *fp)
{
  fwrite(&cutoff_global, sizeof(double), 1, fp);
}

void PairGranularAcoustic::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) utils::sfread(FLERR, &cutoff_global, sizeof(double), 1, fp, nullptr, error);
  MPI_Bcast(&cutoff_global, 1, MPI_DOUBLE, 0, world);
}

/* ---------------------------------------------------------------------- */

void PairGranularAcoustic::reset_dt()
{
  dt = update->dt;
}

/* ----------------------------------------------------------------------
   force between i and j for compute pair/local, from the current history,
   which is left unchanged
------------------------------------------------------------------------- */

double PairGranularAcoustic::single(int i, int j, int itype, int jtype, double rsq,
                                    double /*factor_coul*/, double /*factor_lj*/, double &fforce)
{
  const int nall = atom->nlocal + atom->nghost;
  if ((i >= nall) || (j >= nall))
    error->all(FLERR, "Not enough atoms for pair granular/acoustic single function");
  for (int m = 0; m < single_extra; m++) svector[m] = 0.0;
  fforce = 0.0;

  if ((fix_history == nullptr) || (fix_history->firstvalue == nullptr))
    error->one(FLERR, "Pair granular/acoustic single computation needs the contact history");

  // find j in the neighbor list of i for the history
  const int jnum = list->numneigh[i];
  int *jlist = list->firstneigh[i];
  int found = -1;
  for (int jj = 0; jj < jnum; jj++) {
    neighprev++;
    if (neighprev >= jnum) neighprev = 0;
    if ((jlist[neighprev] & NEIGHMASK) == j) {
      found = neighprev;
      break;
    }
  }
  const GranularContactLaw &l = law(itype, jtype);
  const bool was_touching = (found >= 0) && fix_history->firstflag[i][found];
  if (rsq >= l.touch_distance_sq(atom->radius[i], atom->radius[j], was_touching)) return 0.0;

  std::vector<double> history(layout.size, 0.0);
  if (found >= 0) {
    const double *h = &fix_history->firstvalue[i][layout.size * found];
    history.assign(h, h + layout.size);
  }

  double **x = atom->x;
  GranularContactLaw::Contact c;
  c.history_update = false;
  fill_contact(c, i, j, x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2], rsq);
  l.normal_force(c);
  const double s = friction_factor(history.data());
  l.tangential_force(c, history.data(), layout, s);
  l.rolling_force(c, history.data(), layout);
  l.twisting_torque(c, history.data(), layout);

  fforce = c.Fntot * c.rinv;
  svector[0] = c.fs[0];
  svector[1] = c.fs[1];
  svector[2] = c.fs[2];
  svector[3] = c.fsmag;
  svector[4] = c.fr[0];
  svector[5] = c.fr[1];
  svector[6] = c.fr[2];
  svector[7] = c.frmag;
  svector[8] = c.magtortwist;
  svector[9] = c.del[0];
  svector[10] = c.del[1];
  svector[11] = c.del[2];
  svector[12] = s;
  return 0.0;
}

/* ---------------------------------------------------------------------- */

int PairGranularAcoustic::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/,
                                            int * /*pbc*/)
{
  for (int i = 0; i < n; i++) buf[i] = mass_rigid[list[i]];
  return n;
}

void PairGranularAcoustic::unpack_forward_comm(int n, int first, double *buf)
{
  for (int i = 0; i < n; i++) mass_rigid[first + i] = buf[i];
}

/* ---------------------------------------------------------------------- */

double PairGranularAcoustic::memory_usage()
{
  return (double) nmax * sizeof(double);
}

/* ----------------------------------------------------------------------
   self-interaction range of an atom, and the range of two radii
------------------------------------------------------------------------- */

double PairGranularAcoustic::atom2cut(int i)
{
  double cut = atom->radius[i] * 2;
  if (beyond_contact) {
    const int itype = atom->type[i];
    cut += law(itype, itype).pulloff_distance(cut, cut);
  }
  return cut;
}

double PairGranularAcoustic::radii2cut(double r1, double r2)
{
  double cut = 0.0;
  if (beyond_contact) {
    for (int i = 1; i <= atom->ntypes; i++)
      for (int j = 1; j <= atom->ntypes; j++) cut = MAX(cut, law(i, j).pulloff_distance(r1, r2));
  }
  return cut + r1 + r2;
}
