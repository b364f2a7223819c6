/* ----------------------------------------------------------------------
   Compiled as C++98 (-std=gnu++98 -pedantic-errors): the facade headers of
   lib/acoustic compile as LIGGGHTS compiles, and their functions (in the
   shared library acoustic_liggghts) are called from C++98 code.
------------------------------------------------------------------------- */

#include "facade_cxx98.h"

#include <cmath>

#if __cplusplus >= 201103L
#error "facade_cxx98.cpp must be compiled as C++98"
#endif

namespace FacadeCxx98 {

Acoustic::GatheredDriveInput chain_input(int n_free, double m, double k, double c, double omega)
{
  Acoustic::GatheredDriveInput input;
  input.dimension = 2;
  input.model = Acoustic::FacadeContactModel::Normal;
  for (int g = 0; g < n_free; g++) input.grains.push_back(Acoustic::GatheredGrain(m, 0.5));
  input.grains.push_back(Acoustic::GatheredGrain(HUGE_VAL, 0.0));    // the wall
  // contact g joins grain g (at x = g + 1) to grain g - 1 (the wall for g = 0)
  for (int g = n_free - 1; g >= 0; g--) {
    Acoustic::GatheredContact contact;
    contact.i = (g == 0) ? n_free : g - 1;
    contact.j = g;
    contact.normal[0] = -1.0;    // from grain g to the grain before it
    contact.kn = k;
    contact.cn = c;
    input.contacts.push_back(contact);
  }
  input.prescribed.push_back(Acoustic::PrescribedDof(n_free, 0, 1.0));
  input.angular_frequency = omega;
  input.solver = "lu";
  return input;
}

bool solve(const Acoustic::GatheredDriveInput &input, Acoustic::GatheredDriveResult &result)
{
  return Acoustic::solve_gathered_drive(input, result);
}

bool contact_factor(const double *qi_re, const double *qi_im, const double *qj_re,
                    const double *qj_im, double amplitude, double kt, double mu, double fn,
                    double cmu, double mu_min, Acoustic::ContactFactorResult &result)
{
  double qi[6], qj[6];
  for (int k = 0; k < 3; k++) {
    qi[2 * k] = qi_re[k];
    qi[2 * k + 1] = qi_im[k];
    qj[2 * k] = qj_re[k];
    qj[2 * k + 1] = qj_im[k];
  }
  Acoustic::ContactFactorInput input;
  input.dimension = 3;
  input.model = Acoustic::FacadeContactModel::Normal;
  input.normal[2] = 1.0;
  input.radius_i = input.radius_j = 0.5;
  input.q_i = qi;
  input.q_j = qj;
  input.amplitude = amplitude;
  input.tangential_stiffness = kt;
  input.friction_coefficient = mu;
  input.normal_force = fn;
  input.cmu = cmu;
  input.mu_min = mu_min;
  return Acoustic::contact_mindlin_factor(input, result);
}

bool bad_drive(std::string &message, int &status)
{
  Acoustic::GatheredDriveInput input = chain_input(2, 1.0, 1.0, 0.0, 0.5);
  input.dimension = 4;
  Acoustic::GatheredDriveResult result;
  const bool ok = Acoustic::solve_gathered_drive(input, result);
  message = result.message;
  status = result.status;
  return ok;
}

Acoustic::GatheredModesInput chain_modes_input(int n, double m, double k, bool walls)
{
  Acoustic::GatheredModesInput input;
  input.dimension = 2;
  input.model = Acoustic::FacadeContactModel::Normal;
  for (int g = 0; g < n; g++) input.grains.push_back(Acoustic::GatheredGrain(m, 0.5));
  for (int e = 0; e < 2; e++) {
    input.grains.push_back(Acoustic::GatheredGrain(walls ? HUGE_VAL : m, 0.5));
    if (!walls) input.fixed.push_back(n + e);
  }
  // the springs from x = n + 1 down to x = 0: x position p is grain p - 1,
  // 0 is grain n, n + 1 is grain n + 1
  for (int p = n + 1; p >= 1; p--) {
    const int right = (p == n + 1) ? n + 1 : p - 1, left = (p == 1) ? n : p - 2;
    Acoustic::GatheredContact contact;
    contact.i = right;    // from the right grain: normal from j (left) to i (right) is +x
    contact.j = left;
    contact.normal[0] = 1.0;
    contact.kn = k;
    input.contacts.push_back(contact);
  }
  return input;
}

bool solve_modes(const Acoustic::GatheredModesInput &input, Acoustic::GatheredModesResult &result)
{
  return Acoustic::solve_gathered_modes(input, result);
}

Acoustic::GatheredPulseInput chain_pulse_input(int n, double m, double k, double T, int samples)
{
  Acoustic::GatheredPulseInput input;
  input.dimension = 2;
  input.model = Acoustic::FacadeContactModel::Normal;
  for (int g = 0; g < n + 2; g++) input.grains.push_back(Acoustic::GatheredGrain(m, 0.5));
  for (int g = n; g >= 0; g--) {
    Acoustic::GatheredContact contact;
    contact.i = g;
    contact.j = g + 1;
    contact.normal[0] = -1.0;    // from g + 1 to g
    contact.kn = k;
    input.contacts.push_back(contact);
  }
  input.source.push_back(0);
  input.detector.push_back(n + 1);
  input.direction[0] = 1.0;
  input.direction[1] = input.direction[2] = 0.0;
  input.duration = T;
  input.samples = samples;
  return input;
}

bool solve_pulse(const Acoustic::GatheredPulseInput &input, Acoustic::GatheredPulseResult &result)
{
  return Acoustic::solve_gathered_pulse(input, result);
}

}    // namespace FacadeCxx98
