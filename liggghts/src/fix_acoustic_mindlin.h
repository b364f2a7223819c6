/* ----------------------------------------------------------------------
    ACOUSTIC for LIGGGHTS-PUBLIC 3.8: fix acoustic/mindlin.

    LIGGGHTS is open-source, distributed under the terms of the GNU Public
    License, version 2 or later.  This file is part of the ACOUSTIC
    package and distributed under the same terms.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   fix ID group acoustic/mindlin N frequency f amplitude U0 source src ...
     src = group-ID | wall <fix wall/gran ID> | mesh <fix mesh/surface ID>

   The LAMMPS fix of the same name (doc/fix_acoustic_mindlin.rst) for pair
   style gran with tangential history/acoustic: grain sources (a group) or
   a wall source, the grain-grain contacts of the fix group and the
   contacts of its grains with every fix wall/gran (primitive walls, and
   each mesh of a mesh wall: nodes of infinite mass, the source wall moving
   with the drive, the others clamped), stiffness hertz E nu.  The
   contacts are walked and gathered by AcousticLiggghtsNetwork
   (acoustic_liggghts_network.h, shared with the computes), solved on rank
   0 by the C++98 facade of the ACOUSTIC numerics
   (acoustic_gathered_drive.h), and each contact's factor is
   contact_mindlin_factor's (acoustic_contact_factor.h), evaluated from the
   lower to the higher atom ID (a wall second) so that both copies of a
   contact across processors get the same bits; 1 - s goes into the pair's
   or the wall's contact history, which LIGGGHTS's restart files keep.

   What differs from LAMMPS (doc/Using_ACOUSTIC_in_LIGGGHTS.rst): a mesh
   source is "source mesh <ID>" and needs keyword direction (a mesh has no
   single normal); stiffness hertz E nu is required (no stiffness pair);
   no damping, solver, reuse or per-atom output yet.  Define the fix after
   the fix wall/gran of a mesh (an ERROR says so).
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

FixStyle(acoustic/mindlin,FixAcousticMindlin)

#else

#ifndef LMP_FIX_ACOUSTIC_MINDLIN_H
#define LMP_FIX_ACOUSTIC_MINDLIN_H

#include "fix.h"
#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixAcousticMindlin : public Fix {
 public:
  FixAcousticMindlin(class LAMMPS *, int, char **);
  ~FixAcousticMindlin();
  int setmask();
  void init();
  void setup_pre_force(int);
  void pre_force(int);
  double compute_vector(int);
  double memory_usage();

 private:
  int source_group, source_groupbit;
  std::string source_wall_id;   // source wall <fix-ID> or source mesh <fix-ID>, else empty
  int source_wall;              // its index in the network's walls, or -1
  bool source_is_mesh;
  double frequency, amplitude;
  double direction[3];
  bool direction_given;
  int direction_axis;
  bool mode_normal;
  double youngs_modulus, poisson_ratio, kappa_scale, ratio;
  double cmu, mu_min;
  bool model_full;

  class AcousticLiggghtsNetwork *network;    // the contact walker and gatherer
  double stats[3];      // contacts, mean factor, min factor

  double **rows;        // local output: tag i, tag j, F_n, k_n, U_t, s
  int maxrows;

  void error_all(const char *fmt, ...);
  void parse(int narg, char **arg);
  void normalise_direction();
  void update_factors();
  bool solve_drive(std::vector<double> &tags_sorted, std::vector<double> &q);
  void set_factors(const std::vector<double> &tags_sorted, const std::vector<double> &q);
  void statistics();
};

}

#endif
#endif
