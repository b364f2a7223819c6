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

#include "vibration_network.h"

#include "acoustic_mindlin_law.h"
#include "acoustic_solver_error.h"
#include "collective_error.h"
#include "command_arguments.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_acoustic_state.h"
#include "modify.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <numeric>

using namespace LAMMPS_NS;

static constexpr int GRAIN_WORDS = 4;      // tag, mass, radius, markers (bit k: marker k)
static constexpr int CONTACT_WORDS = 9;    // tag_i, tag_j, n[3], kn, kt, cn, ct

/* ---------------------------------------------------------------------- */

bool VibrationNetworkSettings::parse(CommandArguments &args, bool allow_damping)
{
  if (args.take("stiffness", 1)) {
    const std::string which = args.word(1);
    if (which == "pair") {
      stiffness = PAIR;
    } else if (which == "hertz" && args.take("stiffness", 3)) {
      stiffness = HERTZ;
      youngs_modulus = args.number(2);
      poisson_ratio = args.number(3);
      if (youngs_modulus <= 0.0)
        args.reject(FLERR, 2, "stiffness hertz needs Young's modulus E > 0, got {}",
                    youngs_modulus);
      if (poisson_ratio <= -1.0 || poisson_ratio >= 0.5)
        args.reject(FLERR, 3, "stiffness hertz needs -1 < nu < 0.5, got {}", poisson_ratio);
    } else {
      args.reject(FLERR, 1, "stiffness must be 'pair' or 'hertz E nu', got '{}'", which);
    }
  } else if (args.take("kappa_scale", 1)) {
    kappa_scale = args.number(1);
    // a factor on the Hertz constant of a real material: far outside
    // 1e-100 .. 1e100 the stiffnesses leave the range of doubles
    if (!(kappa_scale >= 1e-100 && kappa_scale <= 1e100))
      args.reject(FLERR, 1,
                  "kappa_scale must be in [1e-100, 1e100] (a factor on the Hertz "
                  "constant), got {}",
                  kappa_scale);
  } else if (args.take("ratio", 1)) {
    ratio = args.number(1);
    if (ratio < 0.0) args.reject(FLERR, 1, "ratio k_t/k_n must be >= 0, got {}", ratio);
  } else if (args.take("model", 1)) {
    try {
      model = Acoustic::contact_model_from_name(args.word(1));
    } catch (Acoustic::SolverError &e) {
      args.reject(FLERR, 1, "{}", e.what());
    }
  } else if (args.take("region_walls", 1)) {
    region_walls = args.logical(1);
  } else if (allow_damping && args.take("damping", 1)) {
    damping_ratio = args.number(1);
    if (damping_ratio < 0.0)
      args.reject(FLERR, 1, "damping ratio must be >= 0, got {}", damping_ratio);
  } else {
    return false;
  }
  args.next();
  return true;
}

/* ---------------------------------------------------------------------- */

VibrationNetwork::VibrationNetwork(LAMMPS *lmp, const VibrationNetworkSettings &s,
                                   const std::string &cmd) :
    Pointers(lmp),
    settings(s), command(cmd), walker(lmp, cmd), ncontacts_all(0), ngrains_all(0), wall_tag_base(0)
{
}

VibrationNetwork::~VibrationNetwork() = default;

/* ---------------------------------------------------------------------- */

void VibrationNetwork::init()
{
  walker.init(settings.region_walls);
}

void VibrationNetwork::add_state_fix(const std::string &owner_id, const std::string &group_name)
{
  state_fix_id = owner_id + "_ACOUSTIC_STATE";
  modify->add_fix(fmt::format("{} {} ACOUSTIC/STATE {}", state_fix_id, group_name, owner_id));
}

void VibrationNetwork::delete_state_fix()
{
  // at the end of LAMMPS the fixes may be gone already
  if (!state_fix_id.empty() && modify && modify->get_fix_by_id(state_fix_id))
    modify->delete_fix(state_fix_id);
}

void VibrationNetwork::require_current_state(const std::string &owner) const
{
  if (update->whichflag != 0 || state_fix_id.empty()) return;
  const auto *state = dynamic_cast<FixAcousticState *>(modify->get_fix_by_id(state_fix_id));
  if (!state || !state->current())
    error->all(FLERR,
               "{}: the system changed since the last run (atoms moved, created or deleted, "
               "the box, the pair or wall coefficients, the walls): its contacts are those of "
               "the next run's setup; evaluate it after 'run 0'",
               owner);
}

int VibrationNetwork::dofs_per_grain() const
{
  return Acoustic::dofs_per_grain(domain->dimension, settings.model);
}

/* ----------------------------------------------------------------------
   collect, gather, index, assemble
------------------------------------------------------------------------- */

int VibrationNetwork::wall_of_fix(const std::string &fix_id) const
{
  int found = -1;
  for (std::size_t k = 0; k < walls().size(); k++) {
    if (walls()[k].fix_id != fix_id) continue;
    if (found >= 0)
      error->all(FLERR,
                 "{}: fix {} has two wall planes; give the source or detector plane a fix "
                 "wall/gran of its own",
                 command, fix_id);
    found = static_cast<int>(k);
  }
  return found;
}

/* ---------------------------------------------------------------------- */

void VibrationNetwork::wall_normal(int wall, double *normal) const
{
  normal[0] = normal[1] = normal[2] = 0.0;
  if (walls()[wall].axis < 0)
    error->all(FLERR,
               "{}: fix {} is a wall/gran/region, whose surface has no single normal; "
               "give the direction of its drive with the keyword direction",
               command, walls()[wall].fix_id);
  normal[walls()[wall].axis] = 1.0;
}

void VibrationNetwork::build(int groupbit, const std::vector<int> &marker_groupbits)
{
  tagint max_tag = 0, max_tag_all = 0;
  for (int i = 0; i < atom->nlocal; i++) max_tag = MAX(max_tag, atom->tag[i]);
  MPI_Allreduce(&max_tag, &max_tag_all, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  wall_tag_base = max_tag_all + 1;

  CollectiveError errors(lmp);
  walker.collect(contacts, groupbit, errors);
  const std::vector<double> contact_words = pack_contacts(errors);
  const std::vector<double> grain_words = pack_grains(groupbit, marker_groupbits, errors);
  errors.raise(FLERR);

  bigint counts_local[2] = {static_cast<bigint>(contact_words.size() / CONTACT_WORDS),
                            static_cast<bigint>(grain_words.size() / GRAIN_WORDS)};
  bigint counts_all[2];
  MPI_Allreduce(counts_local, counts_all, 2, MPI_LMP_BIGINT, MPI_SUM, world);
  ncontacts_all = counts_all[0];
  ngrains_all = counts_all[1];

  std::vector<int> contact_counts, grain_counts;
  const std::vector<double> all_contacts = gather_to_rank0(contact_words, contact_counts);
  const std::vector<double> all_grains = gather_to_rank0(grain_words, grain_counts);

  if (comm->me == 0) {
    try {
      std::vector<Acoustic::Grain> grains =
          index_grains(all_grains, grain_counts, static_cast<int>(marker_groupbits.size()));
      std::vector<Acoustic::Contact> network_contacts = index_contacts(all_contacts);
      net.reset(new Acoustic::ContactNetwork(domain->dimension, settings.model, std::move(grains),
                                             std::move(network_contacts)));
    } catch (Acoustic::SolverError &e) {
      errors.report(fmt::format("{}: cannot build the contact network: {}", command, e.what()));
    }
  }
  errors.raise(FLERR);
}

/* ---------------------------------------------------------------------- */

void VibrationNetwork::collect(int groupbit)
{
  CollectiveError errors(lmp);
  walker.collect(contacts, groupbit, errors);
  for (auto &c : contacts) {
    try {
      apply_settings(c);
    } catch (Acoustic::SolverError &e) {
      errors.report(fmt::format("{}: contact of atoms {} and {}: {}", command, atom->tag[c.i],
                                atom->tag[c.j], e.what()));
    }
  }
  errors.raise(FLERR);
}

/* ----------------------------------------------------------------------
   stiffnesses of the network from the settings (the walker gives the pair's)
------------------------------------------------------------------------- */

void VibrationNetwork::apply_settings(GranularContact &c) const
{
  const double default_ratio = (settings.stiffness == VibrationNetworkSettings::HERTZ) ? 2.0 / 7.0
                                                                                       : -1.0;
  const double ratio = (settings.ratio >= 0.0) ? settings.ratio : default_ratio;
  if (settings.stiffness == VibrationNetworkSettings::HERTZ) {
    // a flat wall is a body of infinite radius
    const double radj = (c.wall >= 0) ? INFINITY : c.radj;
    const double kappa = settings.kappa_scale *
        Acoustic::hertz_kappa(settings.youngs_modulus, settings.poisson_ratio, c.radi, radj);
    c.kn = Acoustic::hertz_normal_stiffness(kappa, c.fn);
  }
  if (ratio >= 0.0) c.kt = ratio * c.kn;
}

/* ----------------------------------------------------------------------
   contacts this processor counts, oriented from the lower to the higher
   atom ID, so that the network is the same on any number of processors
------------------------------------------------------------------------- */

std::vector<double> VibrationNetwork::pack_contacts(CollectiveError &errors)
{
  tagint *tag = atom->tag;
  std::vector<double> words;
  words.reserve(contacts.size() * CONTACT_WORDS);
  for (auto &c : contacts) {
    double cn = 0.0, ct = 0.0;
    if (!network_contact(c, cn, ct, errors)) continue;
    // a wall: the grain of ID wall_tag_base + plane
    const tagint tag_j = (c.wall >= 0) ? wall_tag_base + c.wall : tag[c.j];
    // from the lower to the higher ID (a wall's is the higher): the network is
    // then the same whatever the number of processors
    const bool flip = tag[c.i] > tag_j;
    const double sign = flip ? -1.0 : 1.0;
    words.push_back(static_cast<double>(flip ? tag_j : tag[c.i]));
    words.push_back(static_cast<double>(flip ? tag[c.i] : tag_j));
    for (int k = 0; k < 3; k++) words.push_back(sign * c.n[k]);
    words.push_back(c.kn);
    words.push_back(c.kt);
    words.push_back(cn);
    words.push_back(ct);
  }
  return words;
}

/* ----------------------------------------------------------------------
   the stiffnesses of contact c from the settings and its dashpots cn, ct;
   true if it belongs to the network (counted here, closed); a contact
   with a bad stiffness is reported and left out
------------------------------------------------------------------------- */

bool VibrationNetwork::network_contact(GranularContact &c, double &cn, double &ct,
                                       CollectiveError &errors)
{
  tagint *tag = atom->tag;
  double *rmass = atom->rmass;
  const bool wall = c.wall >= 0;
  // a wall is a body of infinite mass
  const double mass_j = wall ? INFINITY : rmass[c.j];
  auto what = [&]() {
    return wall ? fmt::format("contact of atom {} with fix {}", tag[c.i], walls()[c.wall].fix_id)
                : fmt::format("contact of atoms {} and {}", tag[c.i], tag[c.j]);
  };
  cn = ct = 0.0;
  try {
    apply_settings(c);
    if (c.owned && c.kn > 0.0 && settings.damping_ratio > 0.0) {
      cn = Acoustic::dashpot_coefficient(settings.damping_ratio, c.kn, rmass[c.i], mass_j);
      ct = Acoustic::dashpot_coefficient(settings.damping_ratio, c.kt, rmass[c.i], mass_j);
    }
  } catch (Acoustic::SolverError &e) {
    errors.report(fmt::format("{}: {}: {}", command, what(), e.what()));
    return false;
  }
  if (!(std::isfinite(c.kn) && std::isfinite(c.kt) && std::isfinite(cn) && std::isfinite(ct))) {
    errors.report(fmt::format("{}: {} has a non-finite stiffness (k_n = {}, k_t = {}) or "
                              "dashpot; check the contact model's coefficients and the keywords "
                              "stiffness, kappa_scale, ratio, damping",
                              command, what(), c.kn, c.kt));
    return false;
  }
  // open or tensile contacts carry no stiffness and stay out of the network
  return c.owned && c.kn > 0.0;
}

/* ----------------------------------------------------------------------
   owned grains of the group: ID, mass, radius, marked
------------------------------------------------------------------------- */

std::vector<double> VibrationNetwork::pack_grains(int groupbit,
                                                  const std::vector<int> &marker_groupbits,
                                                  CollectiveError &errors)
{
  tagint *tag = atom->tag;
  double *rmass = atom->rmass;
  double *radius = atom->radius;
  int *mask = atom->mask;
  std::vector<double> words;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    check_grain(i, errors);
    words.push_back(static_cast<double>(tag[i]));
    words.push_back(rmass[i]);
    words.push_back(radius[i]);
    int markers = 0;
    for (std::size_t k = 0; k < marker_groupbits.size(); k++)
      if (mask[i] & marker_groupbits[k]) markers |= 1 << k;
    words.push_back(static_cast<double>(markers));
  }
  return words;
}

void VibrationNetwork::check_grain(int i, CollectiveError &errors) const
{
  const double mass = atom->rmass[i], radius = atom->radius[i];
  if (!(std::isfinite(mass) && mass > 0.0 && std::isfinite(radius) && radius > 0.0))
    errors.report(fmt::format("{}: atom {} has mass {} and radius {}; every atom of the network "
                              "needs a positive, finite mass and radius (set density, diameter)",
                              command, atom->tag[i], mass, radius));
}

/* ----------------------------------------------------------------------
   this processor's part of the network: owned atoms of the group, the
   ghosts its counted contacts touch, the wall planes
------------------------------------------------------------------------- */

void VibrationNetwork::build_local(int groupbit, const std::vector<int> &marker_groupbits)
{
  CollectiveError errors(lmp);
  walker.collect(contacts, groupbit, errors);
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  int *mask = atom->mask;
  std::vector<int> grain_of_atom(nall, -1);
  part = LocalNetworkPart();
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    check_grain(i, errors);
    grain_of_atom[i] = static_cast<int>(part.atoms.size());
    part.atoms.push_back(i);
  }
  part.num_owned = static_cast<int>(part.atoms.size());

  struct Spring {
    int i, j;    // atom indices, j = -1 - plane for a wall
    double n[3], kn, kt, cn, ct;
  };
  std::vector<Spring> springs;
  for (auto &c : contacts) {
    double cn = 0.0, ct = 0.0;
    if (!network_contact(c, cn, ct, errors)) continue;
    if (c.wall < 0 && grain_of_atom[c.j] < 0) {
      grain_of_atom[c.j] = static_cast<int>(part.atoms.size());
      part.atoms.push_back(c.j);
    }
    springs.push_back(
        {c.i, c.wall < 0 ? c.j : -1 - c.wall, {c.n[0], c.n[1], c.n[2]}, c.kn, c.kt, cn, ct});
  }
  bigint counts_local[2] = {static_cast<bigint>(springs.size()),
                            static_cast<bigint>(part.num_owned)};
  bigint counts_all[2];
  MPI_Allreduce(counts_local, counts_all, 2, MPI_LMP_BIGINT, MPI_SUM, world);
  ncontacts_all = counts_all[0];
  ngrains_all = counts_all[1];

  const int natoms = static_cast<int>(part.atoms.size());
  std::vector<Acoustic::Grain> grains;
  grains.reserve(natoms + walls().size());
  for (int i : part.atoms) grains.push_back({atom->rmass[i], atom->radius[i]});
  for (std::size_t k = 0; k < walls().size(); k++) {
    // prescribed nodes: their mass and radius only need to be valid numbers
    part.wall_nodes.push_back(static_cast<int>(grains.size()));
    grains.push_back({1.0, 1.0});
  }
  part.marked.assign(marker_groupbits.size(), std::vector<int>());
  for (int g = 0; g < natoms; g++)
    for (std::size_t k = 0; k < marker_groupbits.size(); k++)
      if (mask[part.atoms[g]] & marker_groupbits[k]) part.marked[k].push_back(g);

  std::vector<Acoustic::Contact> network_contacts;
  network_contacts.reserve(springs.size());
  for (const Spring &s : springs) {
    const int gj = (s.j >= 0) ? grain_of_atom[s.j] : part.wall_nodes[-1 - s.j];
    network_contacts.push_back(
        {grain_of_atom[s.i], gj, Eigen::Vector3d(s.n[0], s.n[1], s.n[2]), s.kn, s.kt, s.cn, s.ct});
  }
  try {
    part.network.reset(new Acoustic::ContactNetwork(
        domain->dimension, settings.model, std::move(grains), std::move(network_contacts)));
  } catch (Acoustic::SolverError &e) {
    errors.report(fmt::format("{}: cannot build the contact network: {}", command, e.what()));
  }
  errors.raise(FLERR);
}

/* ----------------------------------------------------------------------
   the concatenation of every processor's words on rank 0, in rank order;
   counts[p] = number of words from processor p (rank 0)
------------------------------------------------------------------------- */

std::vector<double> VibrationNetwork::gather_to_rank0(const std::vector<double> &mine,
                                                      std::vector<int> &counts)
{
  const int nprocs = comm->nprocs;
  int count = static_cast<int>(mine.size());
  counts.assign(nprocs, 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world);
  std::vector<int> displs(nprocs, 0);
  for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
  std::vector<double> all;
  if (comm->me == 0) all.resize(displs[nprocs - 1] + counts[nprocs - 1]);
  MPI_Gatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE,
              0, world);
  return all;
}

/* ----------------------------------------------------------------------
   rank 0: grains sorted by atom ID, remembering the order they were sent in
------------------------------------------------------------------------- */

std::vector<Acoustic::Grain> VibrationNetwork::index_grains(const std::vector<double> &words,
                                                            const std::vector<int> &counts,
                                                            int nmarkers)
{
  const int ngrains = static_cast<int>(words.size() / GRAIN_WORDS);
  std::vector<int> order(ngrains);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return words[GRAIN_WORDS * a] < words[GRAIN_WORDS * b];
  });
  tags_all.resize(ngrains);
  sent_grain_index.assign(ngrains, 0);
  marked.assign(nmarkers, std::vector<int>());
  std::vector<Acoustic::Grain> grains(ngrains);
  for (int g = 0; g < ngrains; g++) {
    const double *w = &words[GRAIN_WORDS * order[g]];
    tags_all[g] = static_cast<tagint>(w[0]);
    grains[g].mass = w[1];
    grains[g].radius = w[2];
    const int markers = static_cast<int>(w[3]);
    for (int k = 0; k < nmarkers; k++)
      if (markers & (1 << k)) marked[k].push_back(g);
    sent_grain_index[order[g]] = g;
  }
  sent_counts.resize(counts.size());
  for (std::size_t p = 0; p < counts.size(); p++) sent_counts[p] = counts[p] / GRAIN_WORDS;

  // the wall planes: grains after every atom (their IDs are higher), always
  // prescribed, so that their mass and radius only need to be valid numbers
  wall_grains.clear();
  for (std::size_t k = 0; k < walls().size(); k++) {
    wall_grains.push_back(static_cast<int>(grains.size()));
    tags_all.push_back(wall_tag_base + static_cast<tagint>(k));
    grains.push_back({1.0, 1.0});
  }
  return grains;
}

/* ----------------------------------------------------------------------
   rank 0: contacts between grain indices, sorted
------------------------------------------------------------------------- */

std::vector<Acoustic::Contact>
VibrationNetwork::index_contacts(const std::vector<double> &words) const
{
  // grain index of an atom ID: a table when IDs are at most a few times the
  // number of grains, a binary search in the sorted IDs otherwise
  const int ngrains = static_cast<int>(tags_all.size());
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
  const int ncontacts = static_cast<int>(words.size() / CONTACT_WORDS);
  std::vector<Acoustic::Contact> result(ncontacts);
  for (int k = 0; k < ncontacts; k++) {
    const double *w = &words[CONTACT_WORDS * k];
    Acoustic::Contact &c = result[k];
    c.i = index_of(w[0]);
    c.j = index_of(w[1]);
    c.normal = Eigen::Vector3d(w[2], w[3], w[4]);
    c.kn = w[5];
    c.kt = w[6];
    c.cn = w[7];
    c.ct = w[8];
  }
  std::sort(result.begin(), result.end(),
            [](const Acoustic::Contact &a, const Acoustic::Contact &b) {
              return (a.i < b.i) || (a.i == b.i && a.j < b.j);
            });
  return result;
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

/* ---------------------------------------------------------------------- */

void VibrationNetwork::scatter_displacements(const Eigen::VectorXd &values, double **out, int ncols,
                                             int groupbit)
{
  const int ndof = dofs_per_grain();
  const int dim = domain->dimension;
  const int nprocs = comm->nprocs;
  std::vector<int> counts(nprocs, 0), displs(nprocs, 0);
  std::vector<double> sendbuf;
  if (comm->me == 0) {
    for (int p = 0; p < nprocs; p++) counts[p] = ndof * sent_counts[p];
    for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
    sendbuf.reserve(ndof * sent_grain_index.size());
    for (int g : sent_grain_index)
      for (int k = 0; k < ndof; k++) sendbuf.push_back(values[g * ndof + k]);
  }
  int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  int nmine = 0;
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) nmine++;
  std::vector<double> recvbuf(ndof * nmine);
  MPI_Scatterv(sendbuf.data(), counts.data(), displs.data(), MPI_DOUBLE, recvbuf.data(),
               static_cast<int>(recvbuf.size()), MPI_DOUBLE, 0, world);
  // DOFs of a grain: dim translations, then its rotations (1 in 2D, 3 in 3D)
  const bool rotations = ncols >= 6 && ndof > dim;
  int m = 0;
  for (int i = 0; i < nlocal; i++) {
    for (int k = 0; k < ncols; k++) out[i][k] = 0.0;
    if (!(mask[i] & groupbit)) continue;
    const double *grain = &recvbuf[m];
    m += ndof;
    for (int k = 0; k < dim; k++) out[i][k] = grain[k];
    if (!rotations) continue;
    if (dim == 2)
      out[i][5] = grain[dim];
    else
      for (int k = 0; k < 3; k++) out[i][3 + k] = grain[dim + k];
  }
}
