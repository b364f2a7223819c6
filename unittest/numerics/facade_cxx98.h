/* ----------------------------------------------------------------------
   Test helpers compiled as C++98 (-std=gnu++98, as the LIGGGHTS tree):
   they include the facade headers of lib/acoustic and nothing else of it,
   fill the facade's structs and call its functions from C++98 code.
   Declarations shared by facade_cxx98.cpp (C++98) and test_facade.cpp (C++17).
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_TEST_FACADE_CXX98_H
#define ACOUSTIC_TEST_FACADE_CXX98_H

#include "acoustic_contact_factor.h"
#include "acoustic_gathered_drive.h"
#include "acoustic_gathered_modes.h"
#include "acoustic_gathered_pulse.h"

#include <string>
#include <vector>

namespace FacadeCxx98 {

// 2D chain, model normal: free grains 0 .. n_free-1 of mass m along x, then a
// wall (grain n_free) driven along x with amplitude 1 (its y clamped by the
// facade); springs k and dashpots c; grain 0 touches the wall.  The
// contacts are given in reverse order, the wall's from the wall to grain 0,
// so that the facade reorders them.
Acoustic::GatheredDriveInput chain_input(int n_free, double m, double k, double c, double omega);

// solve_gathered_drive called from C++98 code
bool solve(const Acoustic::GatheredDriveInput &input, Acoustic::GatheredDriveResult &result);

// contact_mindlin_factor called from C++98 code on a 3D contact of model
// normal along z: q_i = (qi_re[k], qi_im[k]), q_j likewise
bool contact_factor(const double *qi_re, const double *qi_im, const double *qj_re,
                    const double *qj_im, double amplitude, double kt, double mu, double fn,
                    double cmu, double mu_min, Acoustic::ContactFactorResult &result);

// a bad input built in C++98 code (dimension 4): the status and message come back
bool bad_drive(std::string &message, int &status);

// 2D chain along x, model normal: free grains 0 .. n-1 of mass m at x = 1 ..
// n, and two end grains n (x = 0) and n + 1 (x = n + 1): walls (infinite
// mass) if walls, else grains of mass m listed as fixed; springs k between
// neighbours, given in reverse order and from the far grain (the facade
// reorders them).  Eigenfrequencies of x: 2 sqrt(k/m) sin(j pi / (2 (n + 1))) / (2 pi).
Acoustic::GatheredModesInput chain_modes_input(int n, double m, double k, bool walls);
bool solve_modes(const Acoustic::GatheredModesInput &input, Acoustic::GatheredModesResult &result);

// 2D chain along x, model normal: grains 0 .. n + 1 of mass m at x = 0 .. n + 1,
// springs k between neighbours; grain 0 the source, grain n + 1 the detector,
// pulse along +x, duration T and `samples` samples
Acoustic::GatheredPulseInput chain_pulse_input(int n, double m, double k, double T, int samples);
bool solve_pulse(const Acoustic::GatheredPulseInput &input, Acoustic::GatheredPulseResult &result);

}    // namespace FacadeCxx98

#endif
