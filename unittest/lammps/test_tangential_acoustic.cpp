// Integration tests of the tangential sub-models <model>/acoustic of pair_style
// granular and fix wall/gran: bitwise equality with <model> when every friction
// factor is 1, the Coulomb limit s*mu*F_n,crit, the walker's linearisation of
// the normal models against LAMMPS's own forces, and the factor's survival
// through reneighboring, MPI migration and restart files.
#include "lammps_fixture.h"

#include "atom.h"
#include "exceptions.h"
#include "fix_neigh_history.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

using AcousticTest::ContactKey;
using AcousticTest::LammpsInstance;
using LAMMPS_NS::GranularContact;
using LAMMPS_NS::GranularContactWalker;

namespace {

// a deterministic factor for the contact of atoms with IDs a and b, in (0.2, 0.9)
double factor_of(long a, long b)
{
  if (a > b) std::swap(a, b);
  const double h = std::sin(12.9898 * a + 78.233 * b) * 43758.5453;
  return 0.2 + 0.7 * (h - std::floor(h));
}

// between runs the history fix keeps the history in per-atom arrays (since
// post_run) and restores the neighbor lists from them at the next setup: a
// test that writes factors by hand between runs hands them over this way
void store_history_between_runs(LammpsInstance &L)
{
  for (auto *fix : L.lmp->modify->get_fix_by_style("^NEIGH_HISTORY$")) fix->pre_exchange();
}

void set_factors(LammpsInstance &L)
{
  const auto *tag = L.lmp->atom->tag;
  for (const auto &c : AcousticTest::granular_contacts(L))
    GranularContactWalker::set_friction_factor(c.factor, factor_of(tag[c.i], tag[c.j]));
  store_history_between_runs(L);
}

std::string num(double value)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.17g", value);
  return buf;
}

// ---------------------------------------------------------------------------
// 1. with every factor 1, <model>/acoustic gives the trajectories of <model>

const char *kNormalModels[] = {"hooke 2e5 0.5 damping mass_velocity",
                               "hertz 5e5 0.5 damping velocity",
                               "hertz/material 1e6 0.5 0.3 damping tsuji",
                               "dmt 1e6 0.3 0.3 0.5",
                               "jkr 1e6 0.3 0.3 0.5"};

const char *kTangentialModels[] = {"linear_nohistory", "linear_history",
                                   "linear_history_classic", "mindlin_classic",
                                   "mindlin", "mindlin/force",
                                   "mindlin_rescale", "mindlin_rescale/force"};

std::string tangential_coeffs(const std::string &model)
{
  if (model == "linear_nohistory") return "0.5 0.4";
  if (model.compare(0, 6, "linear") == 0) return "1.5e5 0.3 0.4";
  return "4e5 1.0 0.4";
}

std::string contact_model(int normal, const std::string &tangential, const std::string &suffix)
{
  std::string m = std::string(kNormalModels[normal]) + " tangential " + tangential + suffix + " " +
      tangential_coeffs(tangential);
  if (tangential == "mindlin") m += " rolling sds 1e4 50 0.1 twisting marshall";
  return m;
}

// a dense, moving packing under tilted gravity on a wall/gran floor
std::string moving_deck(int dimension, const std::string &newton, const std::string &model)
{
  std::string d = "units lj\natom_style sphere\nnewton " + newton + "\nprocessors * 1 1\n";
  if (dimension == 3) {
    d += "boundary p p fm\ncomm_modify vel yes\nregion box block 0 6 0 5 0 10\ncreate_box 1 box\n"
         "lattice sc 1.0\nregion fill block 0 6 0 5 0.5 5.5\ncreate_atoms 1 region fill\n"
         "fix wall all wall/gran granular " + model + " zplane 0.0 NULL\n"
         "fix grav all gravity 10 vector 0.3 0.0 -1.0\n";
  } else {
    d += "dimension 2\nboundary p fm p\ncomm_modify vel yes\n"
         "region box block 0 14 0 14 -0.5 0.5\ncreate_box 1 box\nlattice sq 1.0\n"
         "region fill block 0 14 0.5 9.5 -0.5 0.5\ncreate_atoms 1 region fill\n"
         "fix wall all wall/gran granular " + model + " yplane 0.0 NULL\n"
         "fix grav all gravity 10 vector 0.3 -1.0 0.0\nfix 2d all enforce2d\n";
  }
  d += "variable d atom 0.96+0.08*random(0,1,4321)\nset group all diameter v_d\n"
       "set group all density 1.0\nvelocity all create 0.5 87287 loop geom\n"
       "pair_style granular\npair_coeff * * " + model + "\n"
       "fix nve all nve/sphere\ntimestep 1e-4\nneighbor 0.3 bin\n"
       "neigh_modify delay 0 every 1 check yes\nthermo 0\n";
  return d;
}

typedef std::tuple<int, int, int, const char *> SameCase;    // normal, tangential, dim, newton

class SameAsModel : public ::testing::TestWithParam<SameCase> {};

TEST_P(SameAsModel, BitwiseTrajectory)
{
  const int normal = std::get<0>(GetParam());
  const std::string tangential = kTangentialModels[std::get<1>(GetParam())];
  const int dimension = std::get<2>(GetParam());
  const std::string newton = std::get<3>(GetParam());
  std::vector<double> x[2], v[2], w[2];
  const char *suffix[2] = {"", "/acoustic"};
  for (int k = 0; k < 2; k++) {
    LammpsInstance L;
    L.commands(moving_deck(dimension, newton, contact_model(normal, tangential, suffix[k])));
    L.command("run 2000");
    x[k] = L.gather("x", 3);
    v[k] = L.gather("v", 3);
    w[k] = L.gather("omega", 3);
  }
  double vmax = 0.0;
  std::size_t differ = 0;
  for (std::size_t m = 0; m < x[0].size(); m++) {
    vmax = std::max(vmax, std::fabs(v[0][m]));
    differ += (x[0][m] != x[1][m]) + (v[0][m] != v[1][m]) + (w[0][m] != w[1][m]);
  }
  ASSERT_GT(vmax, 0.05) << "the deck does not move: the comparison would be empty";
  EXPECT_EQ(differ, 0u) << "positions, velocities or spins differ from " << tangential;
}

INSTANTIATE_TEST_SUITE_P(
    Models, SameAsModel,
    ::testing::Combine(::testing::Range(0, 5), ::testing::Range(0, 8), ::testing::Values(2, 3),
                       ::testing::Values("on", "off")),
    [](const ::testing::TestParamInfo<SameCase> &info) {
      std::string normal = kNormalModels[std::get<0>(info.param)];
      normal = normal.substr(0, normal.find(' '));
      std::string name = normal + "_" + kTangentialModels[std::get<1>(info.param)] + "_" +
          std::to_string(std::get<2>(info.param)) + "d_newton_" + std::get<3>(info.param);
      for (char &ch : name)
        if (!isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return name;
    });

// ---------------------------------------------------------------------------
// 2. a grain pressed on a large fixed grain sticks below s*mu*F_n,crit and slides above

// normal models giving F_n ~ 10 at an overlap ~ 0.01 between grains of diameters 20 and 1
// (damping mass_velocity: tangential dashpots that do not depend on the contact radius)
const char *kPressedNormal[] = {"hooke 1000 50 damping mass_velocity",
                                "hertz 2e4 50 damping mass_velocity",
                                "hertz/material 3e4 50 0.3 damping mass_velocity",
                                "dmt 3e4 50 0.3 0.2 damping mass_velocity",
                                "jkr 3e4 50 0.3 0.2 damping mass_velocity"};

typedef std::tuple<int, int, double> CoulombCase;    // normal, tangential, Ft/(s mu Fn,crit)

class CoulombLimit : public ::testing::TestWithParam<CoulombCase> {};

TEST_P(CoulombLimit, StickOrSlide)
{
  const std::string normal = kPressedNormal[std::get<0>(GetParam())];
  const std::string tangential = kTangentialModels[std::get<1>(GetParam())];
  const double ratio = std::get<2>(GetParam());
  const double s = 0.6, mu = 0.5, Fn = 10.0;
  // tangential springs of about 1000 (the Mindlin and classic models scale k by
  // the contact radius, about 0.07 here): the elastic displacement stays far
  // below the size of the fixed grain, which the pushed grain must not roll over
  const std::string tcoeffs = tangential == "linear_nohistory"
      ? "20 0.5"
      : (tangential == "linear_history" ? "1000 1.0 0.5" : "15000 1.0 0.5");

  LammpsInstance L;
  L.commands("units lj\natom_style sphere\nboundary m m m\ncomm_modify vel yes\n"
             "region box block -12 12 -12 12 -12 12\ncreate_box 1 box\n"
             "create_atoms 1 single 0 0 0\ncreate_atoms 1 single 0 0 10.495\n"
             "set atom 1 diameter 20.0\nset atom 2 diameter 1.0\nset group all density 1.0\n"
             "group fixed id 1\ngroup pushed id 2\npair_style granular\n");
  L.command("pair_coeff * * " + normal + " tangential " + tangential + "/acoustic " + tcoeffs);
  // translation only: omega of the pushed grain stays zero (no rotation)
  L.commands("fix move pushed nve\ntimestep 1e-3\nvariable ft equal 0.0\n"
             "variable fn equal " + num(-Fn) + "\nfix push pushed addforce v_ft 0.0 v_fn\n"
             "fix calm pushed viscous 20.0\nthermo 0\nrun 3000\nunfix calm\nrun 0\n");

  const std::vector<GranularContact> contacts = AcousticTest::granular_contacts(L);
  ASSERT_EQ(contacts.size(), 1u);
  const GranularContact c = contacts[0];
  EXPECT_EQ(GranularContactWalker::friction_factor(c.factor), 1.0) << "a new contact starts at 1";
  if (normal.compare(0, 3, "dmt") != 0 && normal.compare(0, 3, "jkr") != 0)
    EXPECT_NEAR(c.fncrit, Fn, 1e-6 * Fn) << "the settled contact carries the applied force";
  GranularContactWalker::set_friction_factor(c.factor, s);
  store_history_between_runs(L);

  const double Ft = ratio * s * mu * c.fncrit;
  L.command("variable ft equal " + num(Ft) + "*ramp(0,1)");
  L.command("run 4000");    // force ramped over this run
  EXPECT_NEAR(GranularContactWalker::friction_factor(AcousticTest::granular_contacts(L).at(0).factor),
              s, 1e-15) << "the factor stays on its contact";
  L.command("variable ft equal " + num(Ft));
  L.command("run 1000");    // held
  const double x_mid = L.gather("x", 3)[3], v_mid = L.gather("v", 3)[3];
  L.command("run 1000");    // held
  const double x_end = L.gather("x", 3)[3], v_end = L.gather("v", 3)[3];

  // over the last time unit a slipping grain gains the velocity
  // 0.02 s mu F_n,crit / m; a stuck one stays put (linear_nohistory has no
  // tangential spring: below the limit it creeps at a constant velocity)
  const double mass = M_PI / 6.0;
  const double gain = 0.02 * s * mu * c.fncrit / mass;
  const double dv = v_end - v_mid, moved = x_end - x_mid;
  if (ratio < 1.0) {
    EXPECT_LT(std::fabs(dv), 0.1 * gain) << "should stick: dv = " << dv;
    if (tangential != "linear_nohistory")
      EXPECT_LT(std::fabs(moved), 1e-3) << "should stick";
  } else {
    EXPECT_GT(dv, 0.5 * gain) << "should slide: dv = " << dv;
    EXPECT_GT(moved, 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Models, CoulombLimit,
    ::testing::Combine(::testing::Range(0, 5), ::testing::Range(0, 8), ::testing::Values(0.98, 1.02)),
    [](const ::testing::TestParamInfo<CoulombCase> &info) {
      std::string normal = kPressedNormal[std::get<0>(info.param)];
      normal = normal.substr(0, normal.find(' '));
      std::string name = normal + "_" + kTangentialModels[std::get<1>(info.param)] +
          (std::get<2>(info.param) < 1.0 ? "_below" : "_above");
      for (char &ch : name)
        if (!isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return name;
    });

// ---------------------------------------------------------------------------
// 3. the walker's linearisation against LAMMPS's own normal force

class NormalStiffness : public ::testing::TestWithParam<int> {
 protected:
  // grains of diameters 1 and 0.8 at overlap delta along an oblique line, at
  // rest: the force on grain 1 is the elastic normal force (no damping at rest)
  void contact_at(double delta, GranularContact &c, double &force)
  {
    const double dir[3] = {0.3, 0.4, 0.866};
    const double len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    const double r = 0.9 - delta;
    LammpsInstance L;
    L.commands("units lj\natom_style sphere\nboundary f f f\ncomm_modify vel yes\n"
               "region box block -3 3 -3 3 -3 3\ncreate_box 1 box\n"
               "create_atoms 1 single 0 0 0\ncreate_atoms 1 single 0 0 1\n"
               "set atom 1 diameter 1.0\nset atom 2 diameter 0.8\nset group all density 1.0\n");
    L.command("set atom 2 x " + num(dir[0] / len * r) + " y " + num(dir[1] / len * r) + " z " +
              num(dir[2] / len * r));
    L.command("pair_style granular");
    L.command(std::string("pair_coeff * * ") + kNormalModels[GetParam()] +
              " tangential mindlin/acoustic 4e5 1.0 0.4");
    L.command("thermo 0\nrun 0");
    const std::vector<GranularContact> contacts = AcousticTest::granular_contacts(L);
    ASSERT_EQ(contacts.size(), 1u);
    c = contacts[0];
    c.factor = nullptr;    // belongs to the instance that is gone
    const std::vector<double> x = L.gather("x", 3), f = L.gather("f", 3);
    double d[3], dist = 0.0;
    for (int k = 0; k < 3; k++) {
      d[k] = x[k] - x[3 + k];
      dist += d[k] * d[k];
    }
    dist = std::sqrt(dist);
    force = 0.0;    // on grain 1 along the normal from grain 2 to grain 1
    for (int k = 0; k < 3; k++) force += f[k] * d[k] / dist;
    actual_delta = 0.9 - dist;
  }
  double actual_delta = 0.0;
};

TEST_P(NormalStiffness, IsCentredDifferenceOfLammpsForce)
{
  const double delta = 0.01, h = 1e-5;
  GranularContact c0, cp, cm;
  double f0, fp, fm;
  contact_at(delta, c0, f0);
  const double d0 = actual_delta;
  contact_at(delta + h, cp, fp);
  const double dp = actual_delta;
  contact_at(delta - h, cm, fm);
  const double dm = actual_delta;
  ASSERT_NEAR(d0, delta, 1e-12);
  EXPECT_NEAR(c0.delta, d0, 1e-14);
  EXPECT_NEAR(c0.fn, f0, 1e-12 * std::fabs(f0)) << "walker's F_n against LAMMPS's force";
  EXPECT_NEAR(c0.n[0] * c0.n[0] + c0.n[1] * c0.n[1] + c0.n[2] * c0.n[2], 1.0, 1e-14);
  EXPECT_LT(c0.n[2], 0.0) << "the normal points from grain 2 to grain 1";
  const double dFdd = (fp - fm) / (dp - dm);
  EXPECT_NEAR(c0.kn, dFdd, 1e-6 * std::fabs(dFdd)) << "F_n = " << f0;
  EXPECT_GT(c0.kn, 0.0);
  EXPECT_DOUBLE_EQ(c0.mu, 0.4);
}

INSTANTIATE_TEST_SUITE_P(Models, NormalStiffness, ::testing::Range(0, 5),
                         [](const ::testing::TestParamInfo<int> &info) {
                           std::string n = kNormalModels[info.param];
                           n = n.substr(0, n.find(' '));
                           for (char &ch : n)
                             if (ch == '/') ch = '_';
                           return n;
                         });

TEST(TangentialStiffness, LinearAndMindlin)
{
  // k of linear_history; 8 G* a of mindlin with material properties, where
  // 1/G* = 2 * 2 (2 - nu)(1 + nu) / E, a = sqrt(R* delta), 1/R* = 1/R1 + 1/R2
  const double E = 1e6, nu = 0.3, delta = 0.02;
  const double Rstar = 0.5 * 0.4 / 0.9;
  const double Gstar = 1.0 / (2 * 2 * (2 - nu) * (1 + nu) / E);
  const char *tangential[2] = {"linear_history/acoustic 1.5e5 0.5 0.4",
                               "mindlin/acoustic NULL 0.5 0.4"};
  const double expected[2] = {1.5e5, 8 * Gstar * std::sqrt(Rstar * delta)};
  for (int m = 0; m < 2; m++) {
    LammpsInstance L;
    L.commands("units lj\natom_style sphere\nboundary f f f\ncomm_modify vel yes\n"
               "region box block -3 3 -3 3 -3 3\ncreate_box 1 box\n"
               "create_atoms 1 single 0 0 0\n");
    L.command("create_atoms 1 single 0 0 " + num(0.9 - delta));
    L.commands("set atom 1 diameter 1.0\nset atom 2 diameter 0.8\nset group all density 1.0\n"
               "pair_style granular\n");
    L.command(std::string("pair_coeff * * hertz/material 1e6 0.3 0.3 tangential ") + tangential[m]);
    L.command("thermo 0\nrun 0");
    const std::vector<GranularContact> contacts = AcousticTest::granular_contacts(L);
    ASSERT_EQ(contacts.size(), 1u);
    EXPECT_NEAR(contacts[0].kt, expected[m], 1e-10 * expected[m]) << tangential[m];
  }
}

// ---------------------------------------------------------------------------
// 4. the factor follows each contact through reneighboring, migration, restart

std::string flowing_fixes(const std::string &tilt)
{
  return "fix wall all wall/gran granular hooke 2e4 20 damping mass_velocity "
         "tangential linear_history/acoustic 1e4 0.5 0.5 zplane 0.0 NULL\n"
         "fix grav all gravity 10 vector " + tilt + " 0.0 -1.0\nfix nve all nve/sphere\n";
}

// a layer settled under gravity, then sheared along x (periodic) across the
// boundary between the sub-domains of 2 ranks
std::string flowing_deck(const std::string &newton)
{
  return "units lj\natom_style sphere\nboundary p p fm\nnewton " + newton +
      "\nprocessors * 1 1\ncomm_modify vel yes\n"
      "region box block 0 8 0 6 0 12\ncreate_box 1 box\nlattice sc 1.0\n"
      "region fill block 0 8 0 6 0.5 8.5\ncreate_atoms 1 region fill\n"
      "displace_atoms all random 0.2 0.2 0.0 4451 units box\n"
      "variable d atom 0.9+0.1*random(0,1,777)\nset group all diameter v_d\n"
      "set group all density 1.0\npair_style granular\n"
      "pair_coeff * * hooke 2e4 20 damping mass_velocity tangential linear_history/acoustic "
      "1e4 0.5 0.5\n" + flowing_fixes("0.0") +
      "timestep 5e-4\nneighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\nthermo 0\n"
      "run 3000\n" + flowing_fixes("0.1") + "velocity all set 2.0 NULL NULL sum yes\n"
      "neighbor 0.05 bin\n";
}

class FactorHistory : public ::testing::TestWithParam<const char *> {};

TEST_P(FactorHistory, SurvivesReneighboringAndMigration)
{
  LammpsInstance L;
  L.commands(flowing_deck(GetParam()));
  set_factors(L);

  std::map<ContactKey, double> previous = AcousticTest::friction_factors(L);
  std::map<ContactKey, bool> original;    // contacts alive since the factors were set
  for (const auto &kv : previous) original[kv.first] = true;
  const std::size_t n_initial = original.size();
  ASSERT_GT(n_initial, 300u);

  const int natoms = static_cast<int>(L.natoms());
  std::vector<int> owner_before(natoms + 1, -1), owner_now(natoms + 1, -1);
  auto owners = [&](std::vector<int> &out) {
    std::vector<int> mine(natoms + 1, -1);
    for (int i = 0; i < L.lmp->atom->nlocal; i++) mine[L.lmp->atom->tag[i]] = AcousticTest::mpi_rank();
    MPI_Allreduce(mine.data(), out.data(), natoms + 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  };
  owners(owner_before);
  const LAMMPS_NS::bigint reneighbors_before = L.lmp->neighbor->ncalls;

  for (int step = 0; step < 600; step++) {
    L.command("run 1 pre no post no");
    std::map<ContactKey, double> now = AcousticTest::friction_factors(L);
    for (const auto &kv : now) {
      auto it = original.find(kv.first);
      const bool kept = (it != original.end()) && it->second && previous.count(kv.first);
      const double expected = kept ? factor_of(kv.first.first, kv.first.second) : 1.0;
      ASSERT_NEAR(kv.second, expected, 1e-14)
          << "contact " << kv.first.first << "-" << kv.first.second << " at step " << step
          << (kept ? " (kept its factor)" : " (new contact)");
    }
    // a contact that opened is no longer original, even if it closes again
    for (auto &kv : original)
      if (!now.count(kv.first)) kv.second = false;
    previous.swap(now);
  }
  owners(owner_now);

  std::size_t kept = 0;
  for (const auto &kv : original) kept += kv.second;
  int migrated = 0;
  for (int t = 1; t <= natoms; t++) migrated += (owner_before[t] != owner_now[t]);
  const LAMMPS_NS::bigint reneighbors = L.lmp->neighbor->ncalls - reneighbors_before;
  if (AcousticTest::mpi_rank() == 0)
    std::printf("[ newton %s ] %zu of %zu contacts kept their factor; %ld reneighborings; "
                "%d atoms changed rank\n", GetParam(), kept, n_initial, (long) reneighbors, migrated);
  EXPECT_GT(kept, 50u) << "too few contacts survived for the test to mean something";
  EXPECT_GT(reneighbors, 20);
  if (AcousticTest::mpi_size() > 1) EXPECT_GT(migrated, 10) << "no atom migrated between ranks";
}

void expect_same_factors(const std::map<ContactKey, double> &expected,
                         const std::map<ContactKey, double> &actual, const std::string &what)
{
  ASSERT_EQ(actual.size(), expected.size()) << what;
  std::size_t lowered = 0;
  for (const auto &kv : expected) {
    auto it = actual.find(kv.first);
    ASSERT_NE(it, actual.end()) << what << ": contact " << kv.first.first << "-" << kv.first.second;
    EXPECT_EQ(it->second, kv.second) << what << ": contact " << kv.first.first << "-"
                                     << kv.first.second;
    lowered += (kv.second != 1.0);
  }
  EXPECT_GT(lowered, expected.size() / 2) << what << ": too few factors below 1 to test";
}

std::string restarted_deck(const std::string &file)
{
  return "read_restart " + file + "\ncomm_modify vel yes\n" + flowing_fixes("0.1") +
      "neighbor 0.05 bin\nneigh_modify delay 0 every 1 check yes\nthermo 0\nrun 0\n";
}

TEST_P(FactorHistory, SurvivesWriteRestartBetweenRuns)
{
  const std::string file = "factor_history_between_" + std::string(GetParam()) + ".restart";
  std::map<ContactKey, double> before, continued;
  {
    LammpsInstance L;
    L.commands(flowing_deck(GetParam()));
    set_factors(L);
    L.command("run 50");
    before = AcousticTest::friction_factors(L);
    L.command("write_restart " + file);
    // the run goes on with the history it had before writing the file
    L.command("run 0");
    continued = AcousticTest::friction_factors(L);
  }
  ASSERT_GT(before.size(), 300u);
  expect_same_factors(before, continued, "the run continued after write_restart");

  LammpsInstance L;
  L.commands(restarted_deck(file));
  expect_same_factors(before, AcousticTest::friction_factors(L), "read_restart");
  if (AcousticTest::mpi_rank() == 0) std::remove(file.c_str());
}

TEST_P(FactorHistory, SurvivesRestartFilesDuringRun)
{
  const std::string base = "factor_history_during_" + std::string(GetParam());
  std::map<ContactKey, double> at_file;
  {
    LammpsInstance L;
    L.commands(flowing_deck(GetParam()));
    set_factors(L);
    L.command("restart 40 " + base + ".*.restart");
    L.command("run 40");    // the file of step 3040 is written at the end of this run's last step
    at_file = AcousticTest::friction_factors(L);
    L.command("restart 0");
  }
  const std::string file = base + ".3040.restart";
  LammpsInstance L;
  L.commands(restarted_deck(file));
  expect_same_factors(at_file, AcousticTest::friction_factors(L), "restart 40 during the run");
  if (AcousticTest::mpi_rank() == 0) std::remove(file.c_str());
}

INSTANTIATE_TEST_SUITE_P(Newton, FactorHistory, ::testing::Values("on", "off"),
                         [](const ::testing::TestParamInfo<const char *> &info) {
                           return std::string("newton_") + info.param;
                         });

// ---------------------------------------------------------------------------
// 5. a new contact starts at factor 1; the sub-models read and write restart files

TEST(AcousticSubModel, StyleListedAndMixed)
{
  LammpsInstance L;
  L.commands("units lj\natom_style sphere\nboundary f f f\ncomm_modify vel yes\n"
             "region box block -3 3 -3 3 -3 3\ncreate_box 2 box\n"
             "create_atoms 1 single 0 0 0\ncreate_atoms 2 single 0 0 0.95\n"
             "set group all diameter 1.0\nset group all density 1.0\npair_style granular\n"
             "pair_coeff 1 1 hertz/material 1e6 0.3 0.3 tangential mindlin/acoustic NULL 0.5 0.4\n"
             "pair_coeff 2 2 hertz/material 2e6 0.3 0.3 tangential mindlin/acoustic NULL 0.5 0.4\n"
             "thermo 0\nrun 0\n");
  // the mixed 1-2 model is an /acoustic one too
  const std::vector<GranularContact> contacts = AcousticTest::granular_contacts(L);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(GranularContactWalker::friction_factor(contacts[0].factor), 1.0);
  EXPECT_GT(contacts[0].kt, 0.0);
}

}    // namespace
