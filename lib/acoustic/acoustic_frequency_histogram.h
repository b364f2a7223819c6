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
   ACOUSTIC package numerics: histogram of vibration frequencies.

   nbins equal bins over [fmin, fmax]; a frequency equal to fmax falls in the
   last bin, frequencies outside the range are not counted.  density is
   normalised over the modes counted: sum(density * bin_width) = 1 (all zero
   if no mode falls in the range).
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_FREQUENCY_HISTOGRAM_H
#define ACOUSTIC_FREQUENCY_HISTOGRAM_H

#include <Eigen/Core>

namespace Acoustic {

struct FrequencyHistogram {
  Eigen::VectorXd bin_centres;
  Eigen::VectorXd density;
  Eigen::VectorXd density_error;    // statistical error of density (0 for exact counts)
  double bin_width = 0.0;
  double counted = 0.0;    // number of modes in [fmin, fmax] (an estimate for KPM)
};

// Largest number of bins (a histogram is a global array of LAMMPS: one row per bin).
constexpr int MAX_HISTOGRAM_BINS = 1000000;

// Throws SolverError unless 1 <= nbins <= MAX_HISTOGRAM_BINS and 0 <= fmin < fmax (finite).
void check_histogram_range(int nbins, double fmin, double fmax);

// Exact histogram of a list of frequencies.
FrequencyHistogram frequency_histogram(const Eigen::VectorXd &frequencies, int nbins, double fmin,
                                       double fmax);

}    // namespace Acoustic

#endif
