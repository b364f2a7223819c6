/* ----------------------------------------------------------------------
    ACOUSTIC for LIGGGHTS-PUBLIC 3.8: the arguments of the computes (see
    the header).

    LIGGGHTS is open-source, distributed under the terms of the GNU Public
    License, version 2 or later.  This file is part of the ACOUSTIC
    package and distributed under the same terms.
------------------------------------------------------------------------- */

#include "acoustic_liggghts_arguments.h"

#include "error.h"
#include "group.h"

#include <climits>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

using namespace LAMMPS_NS;

AcousticLiggghtsArguments::AcousticLiggghtsArguments(LAMMPS *lmp, const std::string &caller_,
                                                     int narg_, char **arg_, int first) :
    Pointers(lmp), caller(caller_), narg(narg_), arg(arg_), iarg(first), nvalues(0)
{
}

void AcousticLiggghtsArguments::error_all(const char *fmt, ...)
{
  char message[1024];
  int n = snprintf(message, sizeof(message), "%s: ", caller.c_str());
  if (n < 0 || n >= static_cast<int>(sizeof(message))) n = 0;
  va_list args;
  va_start(args, fmt);
  vsnprintf(message + n, sizeof(message) - n, fmt, args);
  va_end(args);
  error->all(FLERR, message);
}

bool AcousticLiggghtsArguments::take(const char *word, int n)
{
  if (strcmp(arg[iarg], word) != 0) return false;
  if (iarg + n >= narg)
    error_all("keyword %s needs %d value%s, got %d", word, n, n > 1 ? "s" : "", narg - iarg - 1);
  nvalues = n;
  return true;
}

double AcousticLiggghtsArguments::number(int k)
{
  const char *s = arg[iarg + k];
  char *end = NULL;
  const double value = strtod(s, &end);
  if (end == s || *end != '\0' || !std::isfinite(value))
    error_all("keyword %s: '%s' is not a finite number", arg[iarg], s);
  return value;
}

int AcousticLiggghtsArguments::integer(int k)
{
  const char *s = arg[iarg + k];
  char *end = NULL;
  const long value = strtol(s, &end, 10);
  if (end == s || *end != '\0' || value < INT_MIN || value > INT_MAX)
    error_all("keyword %s: '%s' is not an integer", arg[iarg], s);
  return static_cast<int>(value);
}

int AcousticLiggghtsArguments::group_bit(int k)
{
  const int igroup = group->find(arg[iarg + k]);
  if (igroup < 0)
    error_all("keyword %s: no group '%s'; define it with the group command first", arg[iarg],
              arg[iarg + k]);
  return group->bitmask[igroup];
}

bool AcousticLiggghtsArguments::network(AcousticNetworkSettings &s, bool allow_damping)
{
  if (take("stiffness", 1)) {
    if (strcmp(word(1), "hertz") != 0)
      error_all("keyword stiffness: only 'hertz E nu' is available in LIGGGHTS, got '%s' "
                "(stiffness pair is not yet)",
                word(1));
    take("stiffness", 3);
    s.youngs_modulus = number(2);
    s.poisson_ratio = number(3);
    if (!(s.youngs_modulus > 0.0))
      error_all("keyword stiffness hertz needs Young's modulus E > 0, got '%s'", word(2));
    if (!(s.poisson_ratio > -1.0 && s.poisson_ratio < 0.5))
      error_all("keyword stiffness hertz needs -1 < nu < 0.5, got '%s'", word(3));
    s.stiffness_given = true;
  } else if (take("kappa_scale", 1)) {
    s.kappa_scale = number(1);
    if (!(s.kappa_scale > 0.0)) error_all("keyword kappa_scale must be > 0, got '%s'", word(1));
  } else if (take("ratio", 1)) {
    s.ratio = number(1);
    if (s.ratio < 0.0) error_all("keyword ratio k_t/k_n must be >= 0, got '%s'", word(1));
  } else if (take("model", 1)) {
    if (strcmp(word(1), "normal") == 0)
      s.model = Acoustic::FacadeContactModel::Normal;
    else if (strcmp(word(1), "full") == 0)
      s.model = Acoustic::FacadeContactModel::Full;
    else
      error_all("keyword model must be 'normal' or 'full', got '%s'", word(1));
  } else if (take("damping", 1)) {
    if (!allow_damping)
      error_all("keyword damping does not apply: the modes are those of the undamped network "
                "(use damping with compute vibration/pulse)");
    s.damping = number(1);
    if (s.damping < 0.0) error_all("keyword damping: zeta must be >= 0, got '%s'", word(1));
  } else {
    return false;
  }
  next();
  return true;
}

void AcousticLiggghtsArguments::unknown(const char *allowed)
{
  error_all("unknown keyword '%s' (allowed: %s)", arg[iarg], allowed);
}
