/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   Steve Plimpton, sjplimp@sandia.gov

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Contributing authors: the ACOUSTIC package developers.
   The contact models are those of pair_style granular (Bolintineanu,
   Srivastava, Lechman, Silbert, Grest, SNL); see its documentation for
   the references of each model.
------------------------------------------------------------------------- */

#include "granular_contact_law.h"

#include "math_special.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace {

const double MY_PI = 3.14159265358979323846;
const double MY_2PI = 6.28318530717958647692;
const double TWOTHIRDS = 2.0 / 3.0;
const double PI27SQ = 266.47931882941264802866;       // 27*PI**2
const double THREEROOT3 = 5.19615242270663202362;     // 3*sqrt(3)
const double SIXROOT6 = 14.69693845669906728801;      // 6*sqrt(6)
const double INVROOT6 = 0.40824829046386307274;       // 1/sqrt(6)
const double FOURTHIRDS = 4.0 / 3.0;
const double THREEQUARTERS = 0.75;
const double EPSILON = 1e-10;

// effective contact modulus of two materials
double mix_stiffnessE(double Eii, double Ejj, double poisii, double poisjj)
{
  return 1 / ((1 - poisii * poisii) / Eii + (1 - poisjj * poisjj) / Ejj);
}

// effective shear modulus of two materials
double mix_stiffnessG(double Eii, double Ejj, double poisii, double poisjj)
{
  return 1 / ((2 * (2 - poisii) * (1 + poisii) / Eii) + (2 * (2 - poisjj) * (1 + poisjj) / Ejj));
}

double mix_geom(double valii, double valjj)
{
  return sqrt(valii * valjj);
}

// coefficient of normal damping of the Tsuji model from the restitution coefficient
double tsuji_damping(double cor)
{
  using namespace LAMMPS_NS::MathSpecial;
  return 1.2728 - 4.2783 * cor + 11.087 * square(cor) - 22.348 * cube(cor) +
      27.467 * powint(cor, 4) - 18.022 * powint(cor, 5) + 4.8218 * powint(cor, 6);
}

// reads the numbers that follow a model keyword
class WordReader {
 public:
  WordReader(const std::vector<std::string> &w) : words(w) {}
  bool has(std::size_t count) const { return pos + count <= words.size(); }
  const std::string &peek(std::size_t k = 0) const { return words[pos + k]; }
  void skip(std::size_t count) { pos += count; }
  bool done() const { return pos >= words.size(); }
  // parse words[pos+k] as a number; on failure fill msg
  bool number(std::size_t k, const char *what, double &value, std::string &msg) const
  {
    const std::string &s = words[pos + k];
    char *end = nullptr;
    errno = 0;
    value = strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(value)) {
      msg = "expected a number for " + std::string(what) + ", got '" + s + "'";
      return false;
    }
    return true;
  }

 private:
  const std::vector<std::string> &words;
  std::size_t pos = 0;
};

}    // namespace

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

std::string GranularContactLaw::supported_models()
{
  return "normal: hooke kn damp | hertz kn damp | hertz/material E damp nu | "
         "dmt E damp nu cohesion | jkr E damp nu cohesion; "
         "damping velocity|mass_velocity|viscoelastic|tsuji; "
         "tangential linear_nohistory xt mu | "
         "linear_history|mindlin|mindlin_rescale|mindlin/force|mindlin_rescale/force kt|NULL xt mu; "
         "rolling none | rolling sds kR gammaR muR; "
         "twisting none | twisting marshall | twisting sds kT gammaT muT; "
         "cutoff value; limit_damping";
}

/* ----------------------------------------------------------------------
   parse the words after "pair_coeff I J", same syntax as pair_style granular
------------------------------------------------------------------------- */

std::string GranularContactLaw::parse(const std::vector<std::string> &words)
{
  WordReader in(words);
  std::string msg;
  bool have_normal = false, have_tangential = false, kt_from_material = false;
  double damp_input = 0.0;

  while (!in.done()) {
    const std::string key = in.peek();
    if (key == "hooke" || key == "hertz") {
      if (!in.has(3)) return key + " needs 2 values: " + key + " kn damping";
      if (!in.number(1, (key + " kn").c_str(), kn, msg)) return msg;
      if (!in.number(2, (key + " damping").c_str(), damp_input, msg)) return msg;
      normal = (key == "hooke") ? HOOKE : HERTZ;
      in.skip(3);
      have_normal = true;
    } else if (key == "hertz/material") {
      if (!in.has(4)) return "hertz/material needs 3 values: hertz/material E damping nu";
      if (!in.number(1, "hertz/material E", Emod, msg)) return msg;
      if (!in.number(2, "hertz/material damping", damp_input, msg)) return msg;
      if (!in.number(3, "hertz/material nu", poisson, msg)) return msg;
      normal = HERTZ_MATERIAL;
      in.skip(4);
      have_normal = true;
    } else if (key == "dmt" || key == "jkr") {
      if (!in.has(5)) return key + " needs 4 values: " + key + " E damping nu cohesion";
      if (!in.number(1, (key + " E").c_str(), Emod, msg)) return msg;
      if (!in.number(2, (key + " damping").c_str(), damp_input, msg)) return msg;
      if (!in.number(3, (key + " nu").c_str(), poisson, msg)) return msg;
      if (!in.number(4, (key + " cohesion").c_str(), cohesion, msg)) return msg;
      normal = (key == "dmt") ? DMT : JKR;
      in.skip(5);
      have_normal = true;
    } else if (key == "damping") {
      if (!in.has(2)) return "damping needs a model: velocity, mass_velocity, viscoelastic or tsuji";
      const std::string &m = in.peek(1);
      if (m == "velocity") damping = VELOCITY;
      else if (m == "mass_velocity") damping = MASS_VELOCITY;
      else if (m == "viscoelastic") damping = VISCOELASTIC;
      else if (m == "tsuji") damping = TSUJI;
      else
        return "unknown damping model '" + m +
            "'; supported: velocity, mass_velocity, viscoelastic, tsuji";
      in.skip(2);
    } else if (key == "tangential") {
      if (!in.has(2)) return "tangential needs a model";
      const std::string &m = in.peek(1);
      if (m == "linear_nohistory") {
        if (!in.has(4)) return "tangential linear_nohistory needs 2 values: xt mu";
        kt = 0.0;
        if (!in.number(2, "tangential damping xt", damp_tangential, msg)) return msg;
        if (!in.number(3, "friction coefficient mu", mu, msg)) return msg;
        tangential = LINEAR_NOHISTORY;
        in.skip(4);
      } else if (m == "linear_history" || m == "mindlin" || m == "mindlin_rescale" ||
                 m == "mindlin/force" || m == "mindlin_rescale/force") {
        if (!in.has(5)) return "tangential " + m + " needs 3 values: kt xt mu";
        if (m == "linear_history") tangential = LINEAR_HISTORY;
        else if (m == "mindlin") tangential = MINDLIN;
        else if (m == "mindlin_rescale") tangential = MINDLIN_RESCALE;
        else if (m == "mindlin/force") tangential = MINDLIN_FORCE;
        else tangential = MINDLIN_RESCALE_FORCE;
        if (in.peek(2) == "NULL" && tangential != LINEAR_HISTORY) {
          kt_from_material = true;
        } else if (!in.number(2, "tangential stiffness kt", kt, msg)) {
          return msg;
        }
        if (!in.number(3, "tangential damping xt", damp_tangential, msg)) return msg;
        if (!in.number(4, "friction coefficient mu", mu, msg)) return msg;
        in.skip(5);
      } else {
        return "unknown tangential model '" + m +
            "'; supported: linear_nohistory, linear_history, mindlin, mindlin_rescale, "
            "mindlin/force, mindlin_rescale/force";
      }
      have_tangential = true;
    } else if (key == "rolling") {
      if (!in.has(2)) return "rolling needs a model: none or sds";
      if (in.peek(1) == "none") {
        roll = ROLL_NONE;
        in.skip(2);
      } else if (in.peek(1) == "sds") {
        if (!in.has(5)) return "rolling sds needs 3 values: kR gammaR muR";
        if (!in.number(2, "rolling kR", kroll, msg)) return msg;
        if (!in.number(3, "rolling gammaR", damp_roll, msg)) return msg;
        if (!in.number(4, "rolling muR", mu_roll, msg)) return msg;
        roll = ROLL_SDS;
        in.skip(5);
      } else {
        return "unknown rolling model '" + in.peek(1) + "'; supported: none, sds";
      }
    } else if (key == "twisting") {
      if (!in.has(2)) return "twisting needs a model: none, marshall or sds";
      if (in.peek(1) == "none") {
        twist = TWIST_NONE;
        in.skip(2);
      } else if (in.peek(1) == "marshall") {
        twist = TWIST_MARSHALL;
        in.skip(2);
      } else if (in.peek(1) == "sds") {
        if (!in.has(5)) return "twisting sds needs 3 values: kT gammaT muT";
        if (!in.number(2, "twisting kT", ktwist, msg)) return msg;
        if (!in.number(3, "twisting gammaT", damp_twist, msg)) return msg;
        if (!in.number(4, "twisting muT", mu_twist, msg)) return msg;
        twist = TWIST_SDS;
        in.skip(5);
      } else {
        return "unknown twisting model '" + in.peek(1) + "'; supported: none, marshall, sds";
      }
    } else if (key == "cutoff") {
      if (!in.has(2)) return "cutoff needs a value";
      if (!in.number(1, "cutoff", cutoff, msg)) return msg;
      in.skip(2);
    } else if (key == "limit_damping") {
      limit_damping = 1;
      in.skip(1);
    } else {
      return "unknown keyword '" + key + "'; supported: " + supported_models();
    }
  }

  if (!have_normal || !have_tangential)
    return "a normal model (hooke, hertz, hertz/material, dmt, jkr) and a tangential model "
           "are both required";
  const bool material = (normal != HOOKE && normal != HERTZ);
  if (kt_from_material && !material)
    return "NULL tangential stiffness (Mindlin from material) requires a normal model with "
           "material properties (hertz/material, dmt or jkr)";
  if (limit_damping && (normal == JKR || normal == DMT))
    return "limit_damping cannot be used with the JKR or DMT normal models";
  if (material && (Emod <= 0.0 || poisson <= -1.0 || poisson >= 0.5))
    return "material models need E > 0 and -1 < nu < 0.5";
  if (kn < 0.0 || kt < 0.0 || damp_input < 0.0 || damp_tangential < 0.0 || mu < 0.0)
    return "stiffness, damping and friction coefficients must be >= 0";

  damp = (damping == TSUJI) ? tsuji_damping(damp_input) : damp_input;
  if (material) kn = FOURTHIRDS * mix_stiffnessE(Emod, Emod, poisson, poisson);
  if (kt_from_material) kt = 8 * mix_stiffnessG(Emod, Emod, poisson, poisson);
  return std::string();
}

/* ---------------------------------------------------------------------- */

std::string GranularContactLaw::mix(const GranularContactLaw &ii, const GranularContactLaw &jj)
{
  if (ii.normal != jj.normal || ii.damping != jj.damping || ii.tangential != jj.tangential ||
      ii.roll != jj.roll || ii.twist != jj.twist)
    return "the two types use different contact models";

  *this = ii;
  if (normal == HERTZ || normal == HOOKE) kn = mix_geom(ii.kn, jj.kn);
  else kn = FOURTHIRDS * mix_stiffnessE(ii.Emod, jj.Emod, ii.poisson, jj.poisson);
  damp = mix_geom(ii.damp, jj.damp);
  if (normal == JKR || normal == DMT) cohesion = mix_geom(ii.cohesion, jj.cohesion);
  kt = mix_geom(ii.kt, jj.kt);
  damp_tangential = mix_geom(ii.damp_tangential, jj.damp_tangential);
  mu = mix_geom(ii.mu, jj.mu);
  if (roll != ROLL_NONE) {
    kroll = mix_geom(ii.kroll, jj.kroll);
    damp_roll = mix_geom(ii.damp_roll, jj.damp_roll);
    mu_roll = mix_geom(ii.mu_roll, jj.mu_roll);
  }
  if (twist == TWIST_SDS) {
    ktwist = mix_geom(ii.ktwist, jj.ktwist);
    damp_twist = mix_geom(ii.damp_twist, jj.damp_twist);
    mu_twist = mix_geom(ii.mu_twist, jj.mu_twist);
  }
  limit_damping = ii.limit_damping && jj.limit_damping;
  cutoff = -1.0;
  return std::string();
}

/* ---------------------------------------------------------------------- */

void GranularContactLaw::pack(int *iv, double *dv) const
{
  iv[0] = normal;
  iv[1] = damping;
  iv[2] = tangential;
  iv[3] = roll;
  iv[4] = twist;
  iv[5] = limit_damping;
  const double d[NDOUBLE] = {kn,     damp,      cohesion,        Emod,     poisson,
                             kt,     damp_tangential, mu,      kroll,    damp_roll,
                             mu_roll, ktwist,   damp_twist,      mu_twist, cutoff, 0.0};
  for (int k = 0; k < NDOUBLE; k++) dv[k] = d[k];
}

void GranularContactLaw::unpack(const int *iv, const double *dv)
{
  normal = static_cast<NormalModel>(iv[0]);
  damping = static_cast<DampingModel>(iv[1]);
  tangential = static_cast<TangentialModel>(iv[2]);
  roll = static_cast<RollModel>(iv[3]);
  twist = static_cast<TwistModel>(iv[4]);
  limit_damping = iv[5];
  double *d[NDOUBLE - 1] = {&kn,      &damp,      &cohesion,        &Emod,     &poisson,
                            &kt,      &damp_tangential, &mu,        &kroll,    &damp_roll,
                            &mu_roll, &ktwist,    &damp_twist,      &mu_twist, &cutoff};
  for (int k = 0; k < NDOUBLE - 1; k++) *d[k] = dv[k];
}

/* ---------------------------------------------------------------------- */

double GranularContactLaw::pulloff_distance(double radi, double radj) const
{
  if (normal != JKR) return 0.0;
  const double Reff = radi * radj / (radi + radj);
  if (Reff <= 0) return 0.0;
  const double E = kn * THREEQUARTERS;
  const double a = cbrt(9 * MY_PI * cohesion * Reff * Reff / (4 * E));
  return a * a / Reff - 2 * sqrt(MY_PI * cohesion * a / E);
}

double GranularContactLaw::jkr_touch_distance_sq(double radi, double radj) const
{
  // a JKR contact holds until the pull-off distance
  const double radsum = radi + radj;
  const double Reff = radi * radj / radsum;
  const double R2 = Reff * Reff;
  const double E = kn * THREEQUARTERS;
  const double a = cbrt(9.0 * MY_PI * cohesion * R2 / (4 * E));
  const double delta_pulloff = a * a / Reff - 2 * sqrt(MY_PI * cohesion * a / E);
  const double dist_pulloff = radsum - delta_pulloff;
  return dist_pulloff * dist_pulloff;
}

/* ----------------------------------------------------------------------
   normal step: unit normal, overlap, contact radius, elastic force,
   damping force and the normal force that enters the Coulomb limits
------------------------------------------------------------------------- */

void GranularContactLaw::normal_force(Contact &c) const
{
  const double radsum = c.radi + c.radj;
  c.Reff = c.radi * c.radj / radsum;
  c.r = sqrt(c.rsq);
  c.rinv = 1.0 / c.r;
  for (int k = 0; k < 3; k++) c.n[k] = c.del[k] * c.rinv;
  c.vnnr = c.vr[0] * c.n[0] + c.vr[1] * c.n[1] + c.vr[2] * c.n[2];
  c.delta = radsum - c.r;
  const double dR = c.delta * c.Reff;

  if (normal == JKR) {
    // contact radius from the overlap (closed-form root of the JKR relation)
    const double E = kn * THREEQUARTERS;
    const double R2 = c.Reff * c.Reff;
    const double coh = cohesion;
    const double dR2 = dR * dR;
    const double t0 = coh * coh * R2 * R2 * E;
    const double t1 = PI27SQ * t0;
    const double t2 = 8 * dR * dR2 * E * E * E;
    const double t3 = 4 * dR2 * E;
    const double sqrt1 = std::max(0.0, t0 * (t1 + 2 * t2));
    const double t4 = cbrt(t1 + t2 + THREEROOT3 * MY_PI * sqrt(sqrt1));
    const double t5 = t3 / t4 + t4 / E;
    const double sqrt2 = std::max(0.0, 2 * dR + t5);
    const double t6 = sqrt(sqrt2);
    const double sqrt3 = std::max(0.0, 4 * dR - t5 + SIXROOT6 * coh * MY_PI * R2 / (E * t6));
    c.a = INVROOT6 * (t6 + sqrt(sqrt3));
    const double a2 = c.a * c.a;
    c.knfac = kn * c.a;
    c.Fne = c.knfac * a2 / c.Reff - MY_2PI * a2 * sqrt(4 * coh * E / (MY_PI * c.a));
  } else {
    c.knfac = kn;
    c.Fne = c.knfac * c.delta;
    c.a = sqrt(dR);
    if (normal != HOOKE) {
      c.Fne *= c.a;
      c.knfac *= c.a;
    }
    if (normal == DMT) c.Fne -= 4 * MY_PI * cohesion * c.Reff;
  }

  double damp_normal;
  switch (damping) {
    case VELOCITY:
      damp_normal = 1;
      break;
    case MASS_VELOCITY:
      damp_normal = c.meff;
      break;
    case VISCOELASTIC:
      damp_normal = c.a * c.meff;
      break;
    case TSUJI:
      damp_normal = sqrt(c.meff * c.knfac);
      break;
    default:
      damp_normal = 0.0;
  }
  c.damp_normal_prefactor = damp * damp_normal;
  const double Fdamp = -c.damp_normal_prefactor * c.vnnr;
  c.Fntot = c.Fne + Fdamp;
  if (limit_damping && (c.Fntot < 0.0)) c.Fntot = 0.0;

  if (normal == JKR) {
    const double F_pulloff = 3 * MY_PI * cohesion * c.Reff;
    c.Fncrit = fabs(c.Fne + 2 * F_pulloff);
  } else if (normal == DMT) {
    const double F_pulloff = 4 * MY_PI * cohesion * c.Reff;
    c.Fncrit = fabs(c.Fne + 2 * F_pulloff);
  } else {
    c.Fncrit = fabs(c.Fntot);
  }
}

/* ----------------------------------------------------------------------
   linearised stiffnesses at the current state
------------------------------------------------------------------------- */

double GranularContactLaw::normal_stiffness(const Contact &c) const
{
  switch (normal) {
    case HOOKE:
      return kn;
    case HERTZ:
    case HERTZ_MATERIAL:
    case DMT:
      // F = kn a delta with a = sqrt(R delta): dF/d(delta) = 3/2 kn a
      return 1.5 * c.knfac;
    case JKR: {
      // F(a) = kn a^3/R - 2 pi sqrt(4 coh E/pi) a^(3/2), delta(a) = a^2/R - 2 sqrt(pi coh a/E)
      const double E = kn * THREEQUARTERS;
      const double a = c.a, R = c.Reff;
      const double dFda = 3 * kn * a * a / R - 3 * MY_PI * sqrt(4 * cohesion * E / MY_PI) * sqrt(a);
      const double ddda = 2 * a / R - sqrt(MY_PI * cohesion / E) / sqrt(a);
      return dFda / ddda;
    }
  }
  return 0.0;
}

double GranularContactLaw::tangential_stiffness(const Contact &c) const
{
  switch (tangential) {
    case LINEAR_NOHISTORY:
      return 0.0;
    case LINEAR_HISTORY:
      return kt;
    default:
      return kt * c.a;    // Mindlin: 8 G* a
  }
}

/* ---------------------------------------------------------------------- */

void GranularContactLaw::relative_tangential_velocity(const Contact &c, double *vtr) const
{
  const double *n = c.n;
  const double vn1 = n[0] * c.vnnr, vn2 = n[1] * c.vnnr, vn3 = n[2] * c.vnnr;
  const double vt1 = c.vr[0] - vn1, vt2 = c.vr[1] - vn2, vt3 = c.vr[2] - vn3;
  const double wr1 = (c.radi * c.omegai[0] + c.radj * c.omegaj[0]);
  const double wr2 = (c.radi * c.omegai[1] + c.radj * c.omegaj[1]);
  const double wr3 = (c.radi * c.omegai[2] + c.radj * c.omegaj[2]);
  vtr[0] = vt1 - (n[2] * wr2 - n[1] * wr3);
  vtr[1] = vt2 - (n[0] * wr3 - n[2] * wr1);
  vtr[2] = vt3 - (n[1] * wr1 - n[0] * wr2);
}

/* ----------------------------------------------------------------------
   rotate a history vector into the plane normal to n, keeping its length
------------------------------------------------------------------------- */

static void project_keep_magnitude(double *h, const double *n, double hdotn)
{
  const double mag = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  h[0] -= hdotn * n[0];
  h[1] -= hdotn * n[1];
  h[2] -= hdotn * n[2];
  const double prjmag = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  const double scalefac = (prjmag > 0) ? mag / prjmag : 0;
  h[0] *= scalefac;
  h[1] *= scalefac;
  h[2] *= scalefac;
}

/* ----------------------------------------------------------------------
   tangential step: spring-dashpot with history (or dashpot only) capped at
   the Coulomb limit s * mu * Fncrit
------------------------------------------------------------------------- */

void GranularContactLaw::tangential_force(Contact &c, double *history,
                                          const HistoryLayout &layout, double s) const
{
  const double Fscrit = (mu * s) * c.Fncrit;
  double vtr[3];
  relative_tangential_velocity(c, vtr);

  c.k_tangential = kt;
  c.damp_tangential = damp_tangential * c.damp_normal_prefactor;
  const double dmp = c.damp_tangential;

  if (tangential == LINEAR_NOHISTORY) {
    const double vrel = sqrt(vtr[0] * vtr[0] + vtr[1] * vtr[1] + vtr[2] * vtr[2]);
    const double fs = dmp * vrel;
    const double Ft = (vrel != 0.0) ? std::min(Fscrit, fs) / vrel : 0.0;
    for (int k = 0; k < 3; k++) c.fs[k] = -Ft * vtr[k];
    c.fsmag = std::min(Fscrit, fs);
    return;
  }

  double *h = history + layout.tangential;
  const bool force_history = (tangential == MINDLIN_FORCE || tangential == MINDLIN_RESCALE_FORCE);
  if (tangential != LINEAR_HISTORY) c.k_tangential *= c.a;
  const double k = c.k_tangential;
  if (has_rescale_history()) {
    // on unloading, rescale the shear displacement or force with the contact radius
    double &a_prev = history[layout.rescale];
    if (c.a < a_prev) {
      const double factor = c.a / a_prev;
      h[0] *= factor;
      h[1] *= factor;
      h[2] *= factor;
    }
  }

  if (c.history_update) {
    const double rsht = h[0] * c.n[0] + h[1] * c.n[1] + h[2] * c.n[2];
    const bool frameupdate =
        force_history ? fabs(rsht) > EPSILON * Fscrit : fabs(rsht) * k > EPSILON * Fscrit;
    if (frameupdate) project_keep_magnitude(h, c.n, rsht);
    if (force_history) {
      for (int m = 0; m < 3; m++) h[m] -= k * vtr[m] * c.dt;
    } else {
      for (int m = 0; m < 3; m++) h[m] += vtr[m] * c.dt;
    }
    if (has_rescale_history()) history[layout.rescale] = c.a;
  }

  for (int m = 0; m < 3; m++)
    c.fs[m] = force_history ? h[m] - dmp * vtr[m] : -k * h[m] - dmp * vtr[m];

  double fs = sqrt(c.fs[0] * c.fs[0] + c.fs[1] * c.fs[1] + c.fs[2] * c.fs[2]);
  if (fs > Fscrit) {
    // sliding: put the history on the Coulomb cone
    const double shrmag = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    if (shrmag != 0.0) {
      for (int m = 0; m < 3; m++) {
        if (force_history) h[m] = Fscrit * c.fs[m] / fs + dmp * vtr[m];
        else h[m] = -1.0 / k * (Fscrit * c.fs[m] / fs + dmp * vtr[m]);
      }
      for (int m = 0; m < 3; m++) c.fs[m] *= Fscrit / fs;
      fs = Fscrit;
    } else {
      c.fs[0] = c.fs[1] = c.fs[2] = 0.0;
      fs = 0.0;
    }
  }
  c.fsmag = fs;
}

/* ----------------------------------------------------------------------
   rolling resistance (SDS), see Wang et al, Particuology 23, 49 (2015)
------------------------------------------------------------------------- */

void GranularContactLaw::rolling_force(Contact &c, double *history,
                                       const HistoryLayout &layout) const
{
  c.fr[0] = c.fr[1] = c.fr[2] = c.frmag = 0.0;
  if (roll == ROLL_NONE) return;

  const double *n = c.n;
  const double relrot1 = c.omegai[0] - c.omegaj[0];
  const double relrot2 = c.omegai[1] - c.omegaj[1];
  const double relrot3 = c.omegai[2] - c.omegaj[2];
  const double vrl[3] = {c.Reff * (relrot2 * n[2] - relrot3 * n[1]),
                         c.Reff * (relrot3 * n[0] - relrot1 * n[2]),
                         c.Reff * (relrot1 * n[1] - relrot2 * n[0])};
  double *h = history + layout.roll;
  const double Frcrit = mu_roll * c.Fncrit;

  if (c.history_update) {
    const double rolldotn = h[0] * n[0] + h[1] * n[1] + h[2] * n[2];
    if (fabs(rolldotn) * kroll > EPSILON * Frcrit) project_keep_magnitude(h, n, rolldotn);
    for (int m = 0; m < 3; m++) h[m] += vrl[m] * c.dt;
  }
  for (int m = 0; m < 3; m++) c.fr[m] = -kroll * h[m] - damp_roll * vrl[m];

  double fr = sqrt(c.fr[0] * c.fr[0] + c.fr[1] * c.fr[1] + c.fr[2] * c.fr[2]);
  if (fr > Frcrit) {
    const double rollmag = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    if (rollmag != 0.0) {
      for (int m = 0; m < 3; m++) h[m] = -1.0 / kroll * (Frcrit * c.fr[m] / fr + damp_roll * vrl[m]);
      for (int m = 0; m < 3; m++) c.fr[m] *= Frcrit / fr;
      fr = Frcrit;
    } else {
      c.fr[0] = c.fr[1] = c.fr[2] = 0.0;
      fr = 0.0;
    }
  }
  c.frmag = fr;
}

/* ----------------------------------------------------------------------
   twisting torque (SDS or Marshall, Marshall J Comp Phys 228, 1541 (2009))
------------------------------------------------------------------------- */

void GranularContactLaw::twisting_torque(Contact &c, double *history,
                                         const HistoryLayout &layout) const
{
  c.magtortwist = 0.0;
  if (twist == TWIST_NONE) return;

  const double *n = c.n;
  const double magtwist = (c.omegai[0] - c.omegaj[0]) * n[0] +
      (c.omegai[1] - c.omegaj[1]) * n[1] + (c.omegai[2] - c.omegaj[2]) * n[2];
  double k_twist, damp, mu_t;
  if (twist == TWIST_MARSHALL) {
    k_twist = 0.5 * c.k_tangential * c.a * c.a;
    damp = 0.5 * c.damp_tangential * c.a * c.a;
    mu_t = TWOTHIRDS * c.a * mu;
  } else {
    k_twist = ktwist;
    damp = damp_twist;
    mu_t = mu_twist;
  }
  double &h = history[layout.twist];
  if (c.history_update) h += magtwist * c.dt;
  c.magtortwist = -k_twist * h - damp * magtwist;
  const double signtwist = (magtwist > 0) - (magtwist < 0);
  const double Mtcrit = mu_t * c.Fncrit;
  if (fabs(c.magtortwist) > Mtcrit) {
    h = 1.0 / k_twist * (Mtcrit * signtwist - damp * magtwist);
    c.magtortwist = -Mtcrit * signtwist;
  }
}
