/* ----------------------------------------------------------------------
   Benchmark of the KPM density of vibrational states (not a unit test).

   1. A disordered 2D network of 5 000 grains (10 000 DOFs): KPM against the
      dense eigensolver, L1 difference of the normalised histograms and speed-up.
   2. A disordered 2D network with >= 300 000 DOFs: wall time of KPM.

   Usage: kpm_large [grains_per_side_of_the_large_network (default 390)]
------------------------------------------------------------------------- */

#include "acoustic_dynamical_matrix.h"
#include "acoustic_kpm_density.h"
#include "acoustic_vibration_modes.h"
#include "network_builders.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace Acoustic;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}    // namespace

int main(int argc, char **argv)
{
  const int large_side = argc > 1 ? std::atoi(argv[1]) : 390;
  const int nbins = 20;
  KpmOptions options;
  options.moments = 400;
  options.random_vectors = 32;

  {
    std::vector<int> fixed;
    const ContactNetwork network = AcousticTest::disordered_network(100, 50, 5u, fixed);
    const DynamicalMatrix dynamical(network.stiffness_matrix(), network.mass_diagonal(), fixed, 2);
    std::printf("5000-grain network: %d free DOFs, %ld stored entries in D\n", dynamical.num_free(),
                static_cast<long>(dynamical.matrix().nonZeros()));

    Clock::time_point start = Clock::now();
    const VibrationModes modes = dense_vibration_modes(dynamical, false);
    const double dense_time = seconds_since(start);
    const double fmax = modes.frequencies.maxCoeff() * 1.0001;
    const FrequencyHistogram exact = frequency_histogram(modes.frequencies, nbins, 0.0, fmax);

    start = Clock::now();
    const FrequencyHistogram kpm = kpm_frequency_histogram(dynamical, nbins, 0.0, fmax, options);
    const double kpm_time = seconds_since(start);
    const double l1 = (kpm.density - exact.density).cwiseAbs().sum() * kpm.bin_width;
    const double estimate = kpm.density_error.sum() * kpm.bin_width;
    std::printf("  dense eigenvalues: %.2f s\n  KPM (%d moments, %d vectors): %.3f s\n", dense_time,
                options.moments, options.random_vectors, kpm_time);
    std::printf("  speed-up %.1f, L1(KPM - dense) = %.4f, summed KPM error estimate = %.4f\n",
                dense_time / kpm_time, l1, estimate);
  }

  {
    std::vector<int> fixed;
    Clock::time_point start = Clock::now();
    const ContactNetwork network = AcousticTest::disordered_network(large_side, large_side, 9u, fixed);
    const DynamicalMatrix dynamical(network.stiffness_matrix(), network.mass_diagonal(), fixed, 2);
    const double build_time = seconds_since(start);
    std::printf("large network: %d grains, %d free DOFs, %ld stored entries in D (assembly %.2f s)\n",
                network.num_grains(), dynamical.num_free(), static_cast<long>(dynamical.matrix().nonZeros()),
                build_time);
    start = Clock::now();
    const FrequencyHistogram kpm = kpm_frequency_histogram(dynamical, nbins, 0.0,
                                                           std::sqrt(dynamical.spectrum_upper_bound()) / (2 * 3.14159265358979),
                                                           options);
    const double kpm_time = seconds_since(start);
    std::printf("  KPM (%d moments, %d vectors): %.2f s, %.1f ns per DOF and matrix-vector product\n",
                options.moments, options.random_vectors, kpm_time,
                1e9 * kpm_time / (dynamical.num_free() * 0.5 * options.moments * options.random_vectors));
    std::printf("  bin centre   density   error\n");
    for (int b = 0; b < nbins; ++b)
      std::printf("  %10.5f %9.4f %7.4f\n", kpm.bin_centres[b], kpm.density[b], kpm.density_error[b]);
  }
  return 0;
}
