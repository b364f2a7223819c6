/* ----------------------------------------------------------------------
    ACOUSTIC for LIGGGHTS-PUBLIC 3.8: the contact network of a group.

    LIGGGHTS is open-source, distributed under the terms of the GNU Public
    License, version 2 or later.  This file is part of the ACOUSTIC
    package and distributed under the same terms.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   AcousticLiggghtsNetwork: the contact walker and gatherer that the
   ACOUSTIC styles of LIGGGHTS share (fix acoustic/mindlin, and the
   computes vibration/modes and vibration/pulse).  It depends on no style:
   give it the LAMMPS instance, a name for its error messages and the
   stiffness constants; it finds pair_style gran itself.

   Use:
     AcousticLiggghtsNetwork net(lmp, "fix acoustic/mindlin us");
     net.set_stiffness(E, nu, kappa_scale, ratio);
     net.init(true, modify->find_fix(id));   // in the style's init(): checks,
                                        // offsets, walls (a compute: init(false))
     net.collect(groupbit);             // this processor's contacts
     AcousticLiggghtsNetwork::Gathered g;
     net.gather(groupbit, flagbit, model, g);   // on rank 0: the facade's input
     ... rank 0: add g.input.prescribed (the walls: node g.tags.size() + w),
         set the frequency, solve_gathered_drive -> q ...
     net.broadcast(g.tags, q);          // every rank: tags and DOF values
     for each net.contacts()[k]: grain_index(g.tags, tag) (a wall:
         g.tags.size() + wall) -> its q, the factor into *slot

   What a contact is (collect): a pair (i, j) of pair gran's neighbor list
   (newton off: a pair with a ghost j is listed on both processors), both
   atoms in the group, whose spheres overlap at the current positions.  Its
   unit normal points from j to i; F_n is LIGGGHTS's elastic Hertz force
   (normal_model_hertz.h: 4/3 Y_eff sqrt(R_eff delta) delta, the pair's own
   property Yeff), k_n the Hertz stiffness at that force of the ACOUSTIC
   convention (k_n = 3/2 kappa^(2/3) F_n^(1/3), kappa = kappa_scale 4/3 E*
   sqrt(R*), E* = E / (2 (1 - nu^2)), the LAMMPS fix's hertz_kappa and
   hertz_normal_stiffness), k_t = ratio k_n, mu the pair's coeffFrict, and
   slot the history value 1 - s of tangential history/acoustic (NULL when
   init was told the factor is not needed).

   What is gathered (gather): the grains of the group (mass, radius), sorted
   by atom ID (grain g of the input is tags[g]), with flag[g] = 1 for the
   grains in flagbit's group, and every contact once (the copy owned by the
   processor of i if j is local, else the one of the lower ID), from its
   lower to its higher atom ID, in the facade's form
   (acoustic_gathered_drive.h).  The order of the contacts in the input is
   rank order; the facade sorts them, so the result does not depend on it.
   Contacts with k_n = 0 (touching, no force) are left out of the network.

   Walls (init, collect_walls): every fix wall/gran is part of the
   network: a primitive wall (xplane, ..., zcylinder) is one node, each
   mesh of a mesh wall (fix mesh/surface ... used by fix wall/gran ...
   mesh n_meshes n meshes ...) is one node, named by the mesh fix's ID;
   nodes of infinite mass (HUGE_VAL: every DOF prescribed by the caller,
   clamped unless named), after every atom in the gathered input (node
   tags.size() + w for wall w).  A wall contact is grain i (local) with
   wall w, j = -1, its normal from the wall to the grain, F_n LIGGGHTS's
   Hertz force of a wall contact (R_eff = r_i, Yeff of the grain's type
   and the wall's type), k_n at R* = r_i (a flat body of infinite radius,
   as the LAMMPS fix), mu coeffFrict of the two types, slot the 1 - s of
   the wall's contact history when its tangential model is history/acoustic
   (else NULL: that wall keeps its friction, as in LAMMPS; NULL for every
   contact, pair or wall, when init was told the factor is not needed).
   - primitive walls: the grains of the wall fix's group whose overlap
     with the wall, as PrimitiveWall::resolveContact gives it (the wall
     fix's own call), is > 0; history: the wall fix's per-atom history
     (fix property/atom history_<wall-ID>).
   - meshes: the grains the mesh's neighbor list (fix neighlist/mesh)
     lists for a triangle, with the distance of
     TriMesh::resolveTriSphereContactBary, the call of
     FixWallGran::post_force_mesh, in the same order (triangles owned and
     ghost, then the list).  Which of those contacts LIGGGHTS computes is
     decided by its contact tracker (fix contacthistory/mesh): a grain on
     two coplanar triangles is one contact, not two.  With a history
     (need_factor), the walk calls the tracker itself exactly as
     post_force_mesh does (markAllContacts, then handleContact for every
     contact within the contact distance), so that the network's contacts
     are the ones the forces will use and a new contact gets its history
     slot now; post_force_mesh then finds each again (its first test) and
     the tracker ends in the same state.  Rather than a copy of the
     contact geometry (the triangle's closest point, its edges and
     corners), the mesh's own function is called: the overlap and normal
     are LIGGGHTS's to the last bit.  Without need_factor the tracker is
     only read: a contact is taken if the tracker knows it, or it is not a
     face contact, or no coplanar triangle was taken before it.

   C++98, as LIGGGHTS.  Every error is error->all (or error->one where only
   one processor can see it) with the caller's name.
------------------------------------------------------------------------- */

#ifndef LMP_ACOUSTIC_LIGGGHTS_NETWORK_H
#define LMP_ACOUSTIC_LIGGGHTS_NETWORK_H

#include "pointers.h"

#include "acoustic_gathered_drive.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class AcousticLiggghtsNetwork : protected Pointers {
 public:
  // one contact of this processor
  struct Contact {
    int i, j;          // local atom indices (j may be a ghost; -1 for a wall)
    int wall;          // the wall (index in walls()), or -1 for two grains
    double n[3];       // unit normal from j (or the wall) to i
    double fn, kn, kt, mu;
    double *slot;      // the history value 1 - s, or NULL
    bool counted;      // this processor's copy is the one gathered and reported
  };

  // a wall of the network
  struct Wall {
    std::string id;            // fix wall/gran ID (primitive) or fix mesh/surface ID (mesh)
    class FixWallGran *fix;    // the wall fix
    class FixMeshSurface *mesh;    // the mesh, NULL for a primitive wall
    int plane_axis;            // a primitive plane: its axis (0, 1, 2); otherwise -1
    int factor_offset;         // of 1 - s in the wall's contact history, or -1
  };

  // the network on rank 0 (empty on the other ranks)
  struct Gathered {
    std::vector<double> tags;             // atom ID of grain g, ascending
    std::vector<char> flag;               // grain g is in the flag group (bit k: flag group k)
    Acoustic::GatheredDriveInput input;   // grains (then the walls) and contacts; no drive,
                                          // nothing prescribed
  };

  // caller: how error messages begin, e.g. "fix acoustic/mindlin us"
  AcousticLiggghtsNetwork(class LAMMPS *lmp, const std::string &caller);

  void set_stiffness(double youngs_modulus, double poisson_ratio, double kappa_scale,
                     double ratio);

  // find pair_style gran and check it (hertz, newton off, atom_style
  // granular) and the walls (fix wall/gran); need_factor: require
  // tangential history/acoustic of the pair and point each contact's slot
  // at its factor; caller_fix: the index of the calling fix in modify (the
  // mesh walls' neighbor lists must come before it), -1 for a compute
  void init(bool need_factor, int caller_fix = -1);

  // this processor's contacts between atoms of groupbit's group, and of
  // its owned atoms with the walls
  void collect(int groupbit);

  const std::vector<Wall> &walls() const { return walls_; }
  // the wall named id (fix wall/gran or fix mesh/surface ID), or -1
  int wall_index(const std::string &id) const;
  const std::vector<Contact> &contacts() const { return contacts_; }

  // everything on rank 0, in the facade's form (see above); model sets
  // input.dimension and input.model, the drive is left to the caller
  void gather(int groupbit, int flagbit, Acoustic::FacadeContactModel::Value model,
              Gathered &out);
  // the same with up to 8 flag groups: bit k of flag[g] is set for the
  // grains in flagbits[k]'s group (the computes' source, detector, fixed)
  void gather(int groupbit, const std::vector<int> &flagbits,
              Acoustic::FacadeContactModel::Value model, Gathered &out);

  // rank 0's tags and q (2 ndof values per node: the grains, then the
  // walls) to every rank
  void broadcast(std::vector<double> &tags, std::vector<double> &q);

  // index of atom ID tag in ascending tags, or -1
  static int grain_index(const std::vector<double> &tags, double tag);

  // gather a block of doubles from every processor on rank 0, in rank order
  void gather_words(const std::vector<double> &mine, std::vector<double> &all);

  class PairGran *pair() const { return pair_; }

 private:
  std::string caller_;
  double youngs_modulus_, poisson_ratio_, kappa_scale_, ratio_;
  class PairGran *pair_;
  int factor_offset_;
  bool need_factor_;
  std::vector<Contact> contacts_;
  std::vector<Wall> walls_;

  void error_all(const char *fmt, ...);
  void init_walls(int caller_fix);
  void settle_just_created(class Fix *fix);
  void collect_primitive(int groupbit, int w);
  void collect_mesh(int groupbit, int w);
  void add_wall_contact(int i, int w, const double *delta, double overlap, int wall_type,
                        double *history);
};

}    // namespace LAMMPS_NS

#endif
