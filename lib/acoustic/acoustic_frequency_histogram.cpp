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
   ACOUSTIC package numerics: histogram of vibration frequencies.
------------------------------------------------------------------------- */

#include "acoustic_frequency_histogram.h"

#include "acoustic_solver_error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace Acoustic {

void check_histogram_range(int nbins, double fmin, double fmax)
{
  if (nbins < 1)
    throw SolverError("frequency histogram: the number of bins must be >= 1, got " +
                      std::to_string(nbins));
  if (nbins > MAX_HISTOGRAM_BINS)
    throw SolverError("frequency histogram: " + std::to_string(nbins) + " bins is more than the " +
                      std::to_string(MAX_HISTOGRAM_BINS) + " a histogram may have");
  if (!std::isfinite(fmin) || !std::isfinite(fmax) || fmin < 0.0 || fmax <= fmin)
    throw SolverError("frequency histogram: need 0 <= fmin < fmax, got fmin = " +
                      std::to_string(fmin) + " and fmax = " + std::to_string(fmax));
}

FrequencyHistogram frequency_histogram(const Eigen::VectorXd &frequencies, int nbins, double fmin,
                                       double fmax)
{
  check_histogram_range(nbins, fmin, fmax);
  FrequencyHistogram hist;
  hist.bin_width = (fmax - fmin) / nbins;
  hist.bin_centres =
      Eigen::VectorXd::LinSpaced(nbins, fmin + 0.5 * hist.bin_width, fmax - 0.5 * hist.bin_width);
  hist.density = Eigen::VectorXd::Zero(nbins);
  hist.density_error = Eigen::VectorXd::Zero(nbins);
  for (Eigen::Index k = 0; k < frequencies.size(); ++k) {
    const double f = frequencies[k];
    if (!(f >= fmin && f <= fmax)) continue;
    const int bin = std::min(nbins - 1, static_cast<int>((f - fmin) / hist.bin_width));
    hist.density[bin] += 1.0;
    hist.counted += 1.0;
  }
  if (hist.counted > 0.0) hist.density /= hist.counted * hist.bin_width;
  return hist;
}

}    // namespace Acoustic
