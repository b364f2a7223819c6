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
#include "force.h"
#include "neigh_list.h"
#include "pair_gran.h"
#include "pair_gran_proxy.h"
#include "properties.h"
#include "property_registry.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>

using namespace LAMMPS_NS;

namespace {
const int GRAIN_WORDS = 4;      // tag, mass, radius, flag
const int CONTACT_WORDS = 7;    // tag lo, tag hi, normal (3, from hi to lo), k_n, k_t
}    // namespace

AcousticLiggghtsNetwork::AcousticLiggghtsNetwork(LAMMPS *lmp, const std::string &caller) :
    Pointers(lmp), caller_(caller), youngs_modulus_(-1.0), poisson_ratio_(0.0), kappa_scale_(1.0),
    ratio_(2.0 / 7.0), pair_(NULL), factor_offset_(-1)
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

void AcousticLiggghtsNetwork::init(bool need_factor)
{
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
  const int nc = static_cast<int>(all_contacts.size()) / CONTACT_WORDS;
  for (int k = 0; k < nc; k++) {
    const double *w = &all_contacts[CONTACT_WORDS * k];
    Acoustic::GatheredContact c;
    c.i = static_cast<int>(std::lower_bound(out.tags.begin(), out.tags.end(), w[0]) -
                           out.tags.begin());
    c.j = static_cast<int>(std::lower_bound(out.tags.begin(), out.tags.end(), w[1]) -
                           out.tags.begin());
    for (int d = 0; d < 3; d++) c.normal[d] = w[2 + d];
    c.kn = w[5];
    c.kt = w[6];
    out.input.contacts.push_back(c);
  }
}

/* ---------------------------------------------------------------------- */

void AcousticLiggghtsNetwork::broadcast(std::vector<double> &tags, std::vector<double> &q, int ndof)
{
  int ngrains = static_cast<int>(tags.size());
  MPI_Bcast(&ngrains, 1, MPI_INT, 0, world);
  tags.resize(ngrains);
  q.resize(static_cast<size_t>(ngrains) * 2 * ndof);
  if (ngrains > 0) {
    MPI_Bcast(&tags[0], ngrains, MPI_DOUBLE, 0, world);
    MPI_Bcast(&q[0], ngrains * 2 * ndof, MPI_DOUBLE, 0, world);
  }
}

int AcousticLiggghtsNetwork::grain_index(const std::vector<double> &tags, double tag)
{
  const std::vector<double>::const_iterator it = std::lower_bound(tags.begin(), tags.end(), tag);
  if (it == tags.end() || *it != tag) return -1;
  return static_cast<int>(it - tags.begin());
}
