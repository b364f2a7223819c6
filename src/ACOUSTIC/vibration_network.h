/* -*- c++ -*- ----------------------------------------------------------
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
   The contact network of the current packing, as fix acoustic/mindlin and
   compute vibration/modes see it: the contacts of pair granular (read by
   GranularContactWalker) between atoms of a group, with stiffnesses (and
   dashpots) from the settings shared by both commands, gathered to rank 0
   as an Acoustic::ContactNetwork keyed by atom IDs; and per-grain values
   sent back from rank 0 to the atoms' owners.
------------------------------------------------------------------------- */

#ifndef LMP_VIBRATION_NETWORK_H
#define LMP_VIBRATION_NETWORK_H

#include "pointers.h"

#include "acoustic_contact_network.h"
#include "granular_contact_walker.h"

#include <memory>
#include <vector>

namespace LAMMPS_NS {

// keywords shared by fix acoustic/mindlin and compute vibration/modes
struct VibrationNetworkSettings {
  enum Stiffness { PAIR, HERTZ };
  Stiffness stiffness = PAIR;
  double youngs_modulus = 0.0, poisson_ratio = 0.0;    // stiffness hertz
  double kappa_scale = 1.0;
  double ratio = -1.0;    // k_t / k_n; < 0: pair's own k_t (pair), 2/7 (hertz)
  Acoustic::ContactModel model = Acoustic::ContactModel::Normal;
  double damping_ratio = 0.0;
  bool region_walls = true;    // the walls of fix wall/gran/region are in the network

  // read the network keyword at the current position of args and its values
  // (then past them); false if it is not a network keyword
  bool parse(class CommandArguments &args, bool allow_damping);
};

// the part of the network one processor holds, for a distributed solve
// (Acoustic::KrylovHelmholtzSolver): the group atoms it owns (in the order
// of their local indices), then the ghost atoms its contacts touch, then the
// wall planes; the contacts it counts (every contact of the network on
// exactly one processor)
struct LocalNetworkPart {
  std::unique_ptr<Acoustic::ContactNetwork> network;
  int num_owned = 0;
  std::vector<int> atoms;                  // local atom index of each grain that is an atom
  std::vector<std::vector<int>> marked;    // the grains (owned or ghost) of each marker
  std::vector<int> wall_nodes;             // grain of each wall plane
};

class VibrationNetwork : protected Pointers {
 public:
  VibrationNetwork(class LAMMPS *, const VibrationNetworkSettings &, const std::string &command);
  ~VibrationNetwork() override;

  // check the pair style and the atom style; call from init()
  void init();

  // For the computes, which may be evaluated between runs: an internal fix
  // (ACOUSTIC/STATE) records the state of the system at every run;
  // require_current_state() stops every rank with an ERROR when, between
  // runs, the system is not that of the last run any more (atoms moved,
  // deleted or created, box, pair or wall coefficients or styles changed, a
  // wall removed): the neighbor lists and contact models no longer describe
  // it.  During a run it does nothing.  `owner` names the style in the ERROR.
  void add_state_fix(const std::string &owner_id, const std::string &group_name);
  void delete_state_fix();
  void require_current_state(const std::string &owner) const;

  // collective: walk the contacts of the group, gather them to rank 0 and
  // build the network there; marker k of marker_groupbits selects the grains
  // whose indices marked_grains(k) lists on rank 0 (the source, the
  // detector, fixed atoms).  Every wall plane is a node of the network (a
  // grain of the network without an atom, listed by wall_nodes()).  Bad
  // contacts or atoms stop every rank with an ERROR.
  void build(int groupbit, const std::vector<int> &marker_groupbits);

  // collective: only walk the contacts of the group (local_contacts()), without
  // building the network
  void collect(int groupbit);

  // collective: walk the contacts of the group and build this processor's
  // part of the network (local_part()), without gathering it; markers as in
  // build().  Bad contacts or atoms stop every rank with an ERROR.
  void build_local(int groupbit, const std::vector<int> &marker_groupbits);
  const LocalNetworkPart &local_part() const { return part; }

  // the contacts listed on this processor (both atoms in the group), with
  // kn and kt replaced by the stiffnesses of the network (from the settings)
  const std::vector<GranularContact> &local_contacts() const { return contacts; }
  bigint ncontacts_total() const { return ncontacts_all; }
  bigint ngrains_total() const { return ngrains_all; }

  // the wall planes (every rank), in the order of wall_nodes()
  const std::vector<WallPlane> &walls() const { return walker.walls(); }
  // index of the wall plane of fix wall/gran `fix_id`, -1 if it has none;
  // an ERROR if it has two (lower and upper) planes
  int wall_of_fix(const std::string &fix_id) const;
  // the unit normal of wall plane `wall` (along its axis) in normal[3]
  void wall_normal(int wall, double *normal) const;

  // rank 0 only
  const Acoustic::ContactNetwork &network() const { return *net; }
  const std::vector<int> &marked_grains(int marker) const { return marked[marker]; }
  // grain index of each wall plane
  const std::vector<int> &wall_nodes() const { return wall_grains; }
  const std::vector<tagint> &grain_tags() const { return tags_all; }

  // rank 0 holds one complex value per network DOF (grain by grain); each
  // owned atom of the group receives those of its grain in out[i] as
  // (re, im) pairs, 2 dofs_per_grain() numbers; atoms outside the group get zeros
  void scatter(const Eigen::VectorXcd &values, double **out, int groupbit);
  // rank 0 holds one real displacement per network DOF (a mode shape, a
  // snapshot); each owned atom of the group receives its grain's in out[i]
  // as LAMMPS lays out per-atom vectors: translations x, y, z in columns
  // 0-2 and, when ncols is 6 and the grains rotate, rotations about x, y, z
  // in columns 3-5 (in 2D about z only); zeros elsewhere and outside the group
  void scatter_displacements(const Eigen::VectorXd &values, double **out, int ncols, int groupbit);

  int dofs_per_grain() const;

 private:
  VibrationNetworkSettings settings;
  std::string command;
  GranularContactWalker walker;
  std::string state_fix_id;    // looked up by ID when used: a fix may be deleted

  std::vector<GranularContact> contacts;
  bigint ncontacts_all, ngrains_all;

  // rank 0: the network, tags of its grains (sorted), marked grains, and the
  // order in which each processor sent its grains (for scatter)
  std::unique_ptr<Acoustic::ContactNetwork> net;
  std::vector<tagint> tags_all;
  std::vector<std::vector<int>> marked;
  std::vector<int> wall_grains;
  tagint wall_tag_base;    // wall plane k is the grain of ID wall_tag_base + k
  std::vector<int> sent_counts;
  std::vector<int> sent_grain_index;

  LocalNetworkPart part;

  // the steps of build()
  void apply_settings(GranularContact &c) const;
  bool network_contact(GranularContact &c, double &cn, double &ct, class CollectiveError &errors);
  void check_grain(int i, class CollectiveError &errors) const;
  std::vector<double> pack_contacts(class CollectiveError &errors);
  std::vector<double> pack_grains(int groupbit, const std::vector<int> &marker_groupbits,
                                  class CollectiveError &errors);
  std::vector<double> gather_to_rank0(const std::vector<double> &mine, std::vector<int> &counts);
  std::vector<Acoustic::Grain> index_grains(const std::vector<double> &words,
                                            const std::vector<int> &counts, int nmarkers);
  std::vector<Acoustic::Contact> index_contacts(const std::vector<double> &words) const;
};

}    // namespace LAMMPS_NS

#endif
