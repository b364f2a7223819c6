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
   ACOUSTIC package numerics: density of vibrational states by the kernel
   polynomial method (KPM), at a cost linear in the number of DOFs.

   The spectrum of the mass-weighted matrix D (acoustic_dynamical_matrix.h)
   is mapped into [-1, 1] with the bounds [-0.01 B, 1.01 B], B the Gershgorin
   bound (D is positive semi-definite).  The Chebyshev moments
     mu_m = tr T_m(D~) / n
   are estimated by a stochastic trace over R random +-1 vectors (two
   moments per product with D), damped by the Jackson kernel g_m, and the
   fraction of eigenvalues in each frequency bin [f_a, f_b] is the exact
   integral of the KPM density over lambda in [(2 pi f_a)^2, (2 pi f_b)^2]:
     N(x) = g_0 mu_0 (1 - t/pi) - (2/pi) sum_{m>=1} g_m mu_m sin(m t)/m,  t = acos x.
   A range starting at fmin = 0 integrates from the lower end of the mapped
   spectrum instead of lambda = 0, so that the zero modes (which the kernel
   spreads to both sides of 0) are counted in full in the first bin.
   The histogram is normalised over the bins as in frequency_histogram();
   density_error is the standard error of the mean over the R vectors.
   The energy resolution is about pi B / moments in lambda; use bins wider
   than that (in f = sqrt(lambda)/(2 pi), low frequencies are resolved worst).
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_KPM_DENSITY_H
#define ACOUSTIC_KPM_DENSITY_H

#include "acoustic_dynamical_matrix.h"
#include "acoustic_frequency_histogram.h"

#include <cstdint>

namespace Acoustic {

struct KpmOptions {
  int moments = 256;            // number of Chebyshev moments (>= 2)
  int random_vectors = 32;      // number of random vectors of the stochastic trace (>= 2)
  std::uint64_t seed = 2021;    // seed of the random vectors (results are reproducible)
};

FrequencyHistogram kpm_frequency_histogram(const DynamicalMatrix &dynamical, int nbins, double fmin,
                                           double fmax, const KpmOptions &options = KpmOptions());

}    // namespace Acoustic

#endif
