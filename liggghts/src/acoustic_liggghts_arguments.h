/* ----------------------------------------------------------------------
    ACOUSTIC for LIGGGHTS-PUBLIC 3.8: the arguments of the computes.

    LIGGGHTS is open-source, distributed under the terms of the GNU Public
    License, version 2 or later.  This file is part of the ACOUSTIC
    package and distributed under the same terms.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   AcousticLiggghtsArguments: a keyword loop over a style's arguments with
   LIGGGHTS ERROR lines that name the style, the keyword and what it wants,
   and the network keywords that compute vibration/modes and
   vibration/pulse share (as VibrationNetworkSettings::parse of the LAMMPS
   package):

     stiffness hertz E nu   required (LIGGGHTS has no stiffness pair yet)
     kappa_scale s          > 0 (1)
     ratio eta              k_t / k_n >= 0 (2/7)
     model normal|full      (normal)
     damping zeta           >= 0 (0; only where allowed)

   C++98, as LIGGGHTS.
------------------------------------------------------------------------- */

#ifndef LMP_ACOUSTIC_LIGGGHTS_ARGUMENTS_H
#define LMP_ACOUSTIC_LIGGGHTS_ARGUMENTS_H

#include "pointers.h"

#include "acoustic_facade.h"

#include <string>

namespace LAMMPS_NS {

struct AcousticNetworkSettings {
  double youngs_modulus, poisson_ratio, kappa_scale, ratio, damping;
  bool stiffness_given;
  Acoustic::FacadeContactModel::Value model;

  AcousticNetworkSettings() :
      youngs_modulus(-1.0), poisson_ratio(0.0), kappa_scale(1.0), ratio(2.0 / 7.0), damping(0.0),
      stiffness_given(false), model(Acoustic::FacadeContactModel::Normal)
  {
  }
};

class AcousticLiggghtsArguments : protected Pointers {
 public:
  // caller: how the ERROR lines begin ("compute vibration/modes m");
  // the keywords start at arg[first]
  AcousticLiggghtsArguments(class LAMMPS *lmp, const std::string &caller, int narg, char **arg,
                            int first);

  bool more() const { return iarg < narg; }
  const char *keyword() const { return arg[iarg]; }
  // the current keyword is `word`: check it has n values, then true
  bool take(const char *word, int n);
  // value k (1-based) of the current keyword
  const char *word(int k) const { return arg[iarg + k]; }
  double number(int k);             // finite
  int integer(int k);               // within int
  int group_bit(int k);             // an existing group's bitmask
  void next() { iarg += 1 + nvalues; }
  // the network keywords at the current position (then past them); false
  // if the keyword is not one of them
  bool network(AcousticNetworkSettings &settings, bool allow_damping);
  // an ERROR for the current keyword, listing the allowed ones
  void unknown(const char *allowed);

  // an ERROR line "caller: message" on every rank
  void error_all(const char *fmt, ...);

 private:
  std::string caller;
  int narg;
  char **arg;
  int iarg, nvalues;
};

}    // namespace LAMMPS_NS

#endif
