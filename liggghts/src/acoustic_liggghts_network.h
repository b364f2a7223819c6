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
     net.init(true);                    // in the style's init(): checks, offsets
     net.collect(groupbit);             // this processor's contacts
     AcousticLiggghtsNetwork::Gathered g;
     net.gather(groupbit, flagbit, model, g);   // on rank 0: the facade's input
     ... rank 0: add g.input.prescribed, set frequency, solve_gathered_drive ...
     net.broadcast(g.tags, q, ndof);    // every rank: tags and DOF values
     for each net.contacts()[k]: grain_index(g.tags, tag) -> its q, the factor

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

   Walls are not handled here yet: only grain-grain contacts.

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
    int i, j;          // local atom indices (j may be a ghost)
    double n[3];       // unit normal from j to i
    double fn, kn, kt, mu;
    double *slot;      // the history value 1 - s, or NULL
    bool counted;      // this processor's copy is the one gathered and reported
  };

  // the network on rank 0 (empty on the other ranks)
  struct Gathered {
    std::vector<double> tags;             // atom ID of grain g, ascending
    std::vector<char> flag;               // grain g is in the flag group (bit k: flag group k)
    Acoustic::GatheredDriveInput input;   // grains and contacts; no drive, nothing prescribed
  };

  // caller: how error messages begin, e.g. "fix acoustic/mindlin us"
  AcousticLiggghtsNetwork(class LAMMPS *lmp, const std::string &caller);

  void set_stiffness(double youngs_modulus, double poisson_ratio, double kappa_scale,
                     double ratio);

  // find pair_style gran and check it (hertz, newton off, atom_style
  // granular); need_factor: require tangential history/acoustic and point
  // each contact's slot at its factor
  void init(bool need_factor);

  // this processor's contacts between atoms of groupbit's group
  void collect(int groupbit);
  const std::vector<Contact> &contacts() const { return contacts_; }

  // everything on rank 0, in the facade's form (see above); model sets
  // input.dimension and input.model, the drive is left to the caller
  void gather(int groupbit, int flagbit, Acoustic::FacadeContactModel::Value model,
              Gathered &out);
  // the same with up to 8 flag groups: bit k of flag[g] is set for the
  // grains in flagbits[k]'s group (the computes' source, detector, fixed)
  void gather(int groupbit, const std::vector<int> &flagbits,
              Acoustic::FacadeContactModel::Value model, Gathered &out);

  // rank 0's tags and q (2 ndof values per grain) to every rank
  void broadcast(std::vector<double> &tags, std::vector<double> &q, int ndof);

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
  std::vector<Contact> contacts_;

  void error_all(const char *fmt, ...);
};

}    // namespace LAMMPS_NS

#endif
