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

}    // namespace FacadeCxx98

#endif
