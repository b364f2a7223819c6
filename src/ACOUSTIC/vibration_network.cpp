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
------------------------------------------------------------------------- */

#include "vibration_network.h"

#include "acoustic_mindlin_law.h"
#include "acoustic_solver_error.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"

#include <algorithm>
#include <cstring>
#include <numeric>

using namespace LAMMPS_NS;

static constexpr int GRAIN_WORDS = 4;      // tag, mass, radius, marked
static constexpr int CONTACT_WORDS = 9;    // tag_i, tag_j, n[3], kn, kt, cn, ct

/* ---------------------------------------------------------------------- */

int VibrationNetworkSettings::parse(int iarg, int narg, char **arg, const std::string &command,
                                    LAMMPS *lmp, bool allow_damping)
{
  Error *error = lmp->error;
  const std::string key = arg[iarg];
  auto need = [&](int n) {
    if (iarg + n >= narg)
      error->all(FLERR, "Illegal {} command: keyword {} needs {} value(s)", command, key, n);
  };
  if (key == "stiffness") {
    need(1);
    const std::string which = arg[iarg + 1];
    if (which == "pair") {
      stiffness = PAIR;
      return 2;
    }
    if (which == "hertz") {
      need(3);
      stiffness = HERTZ;
      youngs_modulus = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      poisson_ratio = utils::numeric(FLERR, arg[iarg + 3], false, lmp);
      if (youngs_modulus <= 0.0)
        error->all(FLERR, "Illegal {} command: stiffness hertz needs Young's modulus E > 0, got {}",
                   command, youngs_modulus);
      if (poisson_ratio <= -1.0 || poisson_ratio >= 0.5)
        error->all(FLERR, "Illegal {} command: stiffness hertz needs -1 < nu < 0.5, got {}",
                   command, poisson_ratio);
      return 4;
    }
    error->all(FLERR, "Illegal {} command: stiffness must be 'pair' or 'hertz E nu', got '{}'",
               command, which);
  }
  if (key == "kappa_scale") {
    need(1);
    kappa_scale = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    if (kappa_scale <= 0.0)
      error->all(FLERR, "Illegal {} command: kappa_scale must be > 0, got {}", command, kappa_scale);
    return 2;
  }
  if (key == "ratio") {
    need(1);
    ratio = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    if (ratio < 0.0)
      error->all(FLERR, "Illegal {} command: ratio k_t/k_n must be >= 0, got {}", command, ratio);
    return 2;
  }
  if (key == "model") {
    need(1);
    try {
      model = Acoustic::contact_model_from_name(arg[iarg + 1]);
    } catch (Acoustic::SolverError &e) {
      error->all(FLERR, "Illegal {} command: {}", command, e.what());
    }
    return 2;
  }
  if (key == "damping" && allow_damping) {
    need(1);
    damping_ratio = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    if (damping_ratio < 0.0)
      error->all(FLERR, "Illegal {} command: damping ratio must be >= 0, got {}", command,
                 damping_ratio);
    return 2;
  }
  return 0;
}

/* ---------------------------------------------------------------------- */

VibrationNetwork::VibrationNetwork(LAMMPS *lmp, const VibrationNetworkSettings &s,
                                   const std::string &cmd) :
    Pointers(lmp), settings(s), command(cmd), walker(lmp, cmd), ncontacts_all(0), ngrains_all(0)
{
}

VibrationNetwork::~VibrationNetwork() = default;

/* ---------------------------------------------------------------------- */

void VibrationNetwork::init()
{
  walker.init();
}

int VibrationNetwork::dofs_per_grain() const
{
  return Acoustic::dofs_per_grain(domain->dimension, settings.model);
}

/* ----------------------------------------------------------------------
   walk the contacts, gather grains and contacts to rank 0, build the network
------------------------------------------------------------------------- */

void VibrationNetwork::apply_settings(GranularContact &c) const
{
  const double default_ratio =
      (settings.stiffness == VibrationNetworkSettings::HERTZ) ? 2.0 / 7.0 : -1.0;
  const double ratio = (settings.ratio >= 0.0) ? settings.ratio : default_ratio;
  if (settings.stiffness == VibrationNetworkSettings::HERTZ) {
    const double kappa = settings.kappa_scale *
        Acoustic::hertz_kappa(settings.youngs_modulus, settings.poisson_ratio, c.radi, c.radj);
    c.kn = Acoustic::hertz_normal_stiffness(kappa, c.fn);
  }
  if (ratio >= 0.0) c.kt = ratio * c.kn;
}

void VibrationNetwork::build(int groupbit, int marker_groupbit)
{
  walker.collect(contacts, groupbit);

  tagint *tag = atom->tag;
  double *rmass = atom->rmass;
  double *radius = atom->radius;
  int *mask = atom->mask;
  const int nlocal = atom->nlocal;

  // contacts with the stiffnesses of the network
  std::vector<double> csend;
  csend.reserve(contacts.size() * CONTACT_WORDS);
  for (auto &c : contacts) {
    try {
      apply_settings(c);
    } catch (Acoustic::SolverError &e) {
      error->one(FLERR, "{}: contact of atoms {} and {}: {}", command, tag[c.i], tag[c.j], e.what());
    }

    // open or tensile contacts carry no stiffness and stay out of the network
    if (!c.owned || !(c.kn > 0.0)) continue;
    double cn = 0.0, ct = 0.0;
    if (settings.damping_ratio > 0.0) {
      cn = Acoustic::dashpot_coefficient(settings.damping_ratio, c.kn, rmass[c.i], rmass[c.j]);
      ct = Acoustic::dashpot_coefficient(settings.damping_ratio, c.kt, rmass[c.i], rmass[c.j]);
    }
    // orient every contact from the lower to the higher atom ID: the network
    // is then the same whatever the number of processors
    const bool flip = tag[c.i] > tag[c.j];
    const double sign = flip ? -1.0 : 1.0;
    csend.push_back(static_cast<double>(flip ? tag[c.j] : tag[c.i]));
    csend.push_back(static_cast<double>(flip ? tag[c.i] : tag[c.j]));
    for (int k = 0; k < 3; k++) csend.push_back(sign * c.n[k]);
    csend.push_back(c.kn);
    csend.push_back(c.kt);
    csend.push_back(cn);
    csend.push_back(ct);
  }

  // owned grains of the group
  std::vector<double> gsend;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    gsend.push_back(static_cast<double>(tag[i]));
    gsend.push_back(rmass[i]);
    gsend.push_back(radius[i]);
    gsend.push_back((mask[i] & marker_groupbit) ? 1.0 : 0.0);
  }

  // gather to rank 0
  const int nprocs = comm->nprocs;
  const int me = comm->me;
  int counts[2] = {static_cast<int>(gsend.size()), static_cast<int>(csend.size())};
  std::vector<int> gcounts(nprocs), ccounts(nprocs), gdispl(nprocs, 0), cdispl(nprocs, 0);
  MPI_Gather(&counts[0], 1, MPI_INT, gcounts.data(), 1, MPI_INT, 0, world);
  MPI_Gather(&counts[1], 1, MPI_INT, ccounts.data(), 1, MPI_INT, 0, world);
  std::vector<double> gall, call;
  if (me == 0) {
    for (int p = 1; p < nprocs; p++) {
      gdispl[p] = gdispl[p - 1] + gcounts[p - 1];
      cdispl[p] = cdispl[p - 1] + ccounts[p - 1];
    }
    gall.resize(gdispl[nprocs - 1] + gcounts[nprocs - 1]);
    call.resize(cdispl[nprocs - 1] + ccounts[nprocs - 1]);
  }
  MPI_Gatherv(gsend.data(), counts[0], MPI_DOUBLE, gall.data(), gcounts.data(), gdispl.data(),
              MPI_DOUBLE, 0, world);
  MPI_Gatherv(csend.data(), counts[1], MPI_DOUBLE, call.data(), ccounts.data(), cdispl.data(),
              MPI_DOUBLE, 0, world);

  bigint nc_local = static_cast<bigint>(csend.size() / CONTACT_WORDS);
  bigint ng_local = static_cast<bigint>(gsend.size() / GRAIN_WORDS);
  MPI_Allreduce(&nc_local, &ncontacts_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  MPI_Allreduce(&ng_local, &ngrains_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);

  if (me != 0) return;

  // rank 0: grains sorted by atom ID, remembering the order they were sent in
  const int ngrains = static_cast<int>(gall.size() / GRAIN_WORDS);
  std::vector<int> order(ngrains);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return gall[GRAIN_WORDS * a] < gall[GRAIN_WORDS * b]; });
  tags_all.resize(ngrains);
  sent_grain_index.assign(ngrains, 0);
  marked.clear();
  std::vector<Acoustic::Grain> grains(ngrains);
  for (int g = 0; g < ngrains; g++) {
    const double *w = &gall[GRAIN_WORDS * order[g]];
    tags_all[g] = static_cast<tagint>(w[0]);
    grains[g].mass = w[1];
    grains[g].radius = w[2];
    if (w[3] != 0.0) marked.push_back(g);
    sent_grain_index[order[g]] = g;
  }
  sent_counts.resize(nprocs);
  for (int p = 0; p < nprocs; p++) sent_counts[p] = gcounts[p] / GRAIN_WORDS;

  // grain index of an atom ID (IDs are at most the number of atoms in most
  // systems: a table; sparse IDs: a binary search in the sorted IDs)
  std::vector<int> index_by_tag;
  const tagint max_tag = ngrains ? tags_all.back() : 0;
  if (max_tag <= 4 * static_cast<tagint>(ngrains) + 1024) {
    index_by_tag.assign(max_tag + 1, -1);
    for (int g = 0; g < ngrains; g++) index_by_tag[tags_all[g]] = g;
  }
  auto index_of = [&](double t) {
    const tagint id = static_cast<tagint>(t);
    if (!index_by_tag.empty()) return index_by_tag[id];
    auto it = std::lower_bound(tags_all.begin(), tags_all.end(), id);
    return static_cast<int>(it - tags_all.begin());
  };
  const int ncontacts = static_cast<int>(call.size() / CONTACT_WORDS);
  std::vector<Acoustic::Contact> network_contacts(ncontacts);
  for (int k = 0; k < ncontacts; k++) {
    const double *w = &call[CONTACT_WORDS * k];
    Acoustic::Contact &c = network_contacts[k];
    c.i = index_of(w[0]);
    c.j = index_of(w[1]);
    c.normal = Eigen::Vector3d(w[2], w[3], w[4]);
    c.kn = w[5];
    c.kt = w[6];
    c.cn = w[7];
    c.ct = w[8];
  }
  std::sort(network_contacts.begin(), network_contacts.end(),
            [](const Acoustic::Contact &a, const Acoustic::Contact &b) {
              return (a.i < b.i) || (a.i == b.i && a.j < b.j);
            });
  try {
    net.reset(new Acoustic::ContactNetwork(domain->dimension, settings.model, std::move(grains),
                                           std::move(network_contacts)));
  } catch (Acoustic::SolverError &e) {
    error->one(FLERR, "{}: cannot build the contact network: {}", command, e.what());
  }
}

/* ----------------------------------------------------------------------
   send per-grain values from rank 0 to the owners of the grains
------------------------------------------------------------------------- */

void VibrationNetwork::scatter(const Eigen::VectorXcd &values, double **out, int groupbit)
{
  const int ndof = dofs_per_grain();
  const int nprocs = comm->nprocs;
  std::vector<int> counts(nprocs, 0), displs(nprocs, 0);
  std::vector<double> sendbuf;
  if (comm->me == 0) {
    for (int p = 0; p < nprocs; p++) counts[p] = 2 * ndof * sent_counts[p];
    for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
    sendbuf.reserve(2 * ndof * sent_grain_index.size());
    for (int g : sent_grain_index)
      for (int k = 0; k < ndof; k++) {
        sendbuf.push_back(values[g * ndof + k].real());
        sendbuf.push_back(values[g * ndof + k].imag());
      }
  }
  int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  int nmine = 0;
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) nmine++;
  std::vector<double> recvbuf(2 * ndof * nmine);
  MPI_Scatterv(sendbuf.data(), counts.data(), displs.data(), MPI_DOUBLE, recvbuf.data(),
               static_cast<int>(recvbuf.size()), MPI_DOUBLE, 0, world);
  int m = 0;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) {
      for (int k = 0; k < 2 * ndof; k++) out[i][k] = 0.0;
      continue;
    }
    for (int k = 0; k < 2 * ndof; k++) out[i][k] = recvbuf[m++];
  }
}
