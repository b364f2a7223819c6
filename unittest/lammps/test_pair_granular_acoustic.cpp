// Integration tests of pair_style granular/acoustic: equality with pair_style
// granular when every friction factor is 1, the Coulomb limit s*mu*F_n, the
// factor's survival through reneighboring, MPI migration and restart files,
// single(), and the errors of bad input.
#include "lammps_fixture.h"

#include "atom.h"
#include "exceptions.h"
#include "force.h"
#include "modify.h"
#include "compute.h"
#include "neighbor.h"
#include "pair_granular_acoustic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

using AcousticTest::LammpsInstance;
using LAMMPS_NS::PairGranularAcoustic;

namespace {

PairGranularAcoustic *acoustic_pair(LammpsInstance &L)
{
  auto *pair = dynamic_cast<PairGranularAcoustic *>(L.lmp->force->pair);
  EXPECT_NE(pair, nullptr) << "pair style is not granular/acoustic";
  return pair;
}

// a deterministic factor for the contact of atoms with IDs a and b, in (0.2, 0.9)
double factor_of(long a, long b)
{
  if (a > b) std::swap(a, b);
  const double h = std::sin(12.9898 * a + 78.233 * b) * 43758.5453;
  return 0.2 + 0.7 * (h - std::floor(h));
}

using AcousticTest::ContactKey;

std::map<ContactKey, double> all_factors(LammpsInstance &L)
{
  return AcousticTest::friction_factors(L);
}

void set_factors(LammpsInstance &L)
{
  PairGranularAcoustic *pair = acoustic_pair(L);
  std::vector<PairGranularAcoustic::ContactState> contacts;
  pair->current_contacts(contacts, 1);
  const auto *tag = L.lmp->atom->tag;
  for (const auto &c : contacts) pair->set_friction_factor(c.history, factor_of(tag[c.i], tag[c.j]));
  pair->store_history_between_runs();
}

// ---------------------------------------------------------------------------
// 1. with all factors 1, trajectories equal those of pair_style granular

struct DeckCase {
  const char *name;
  int dimension;
  const char *coeff;
};

std::string dense_deck(const DeckCase &dc, const std::string &style)
{
  std::string d;
  if (dc.dimension == 3) {
    d = "units lj\natom_style sphere\nboundary p p fm\ncomm_modify vel yes\n"
        "region box block 0 10 0 10 0 14\ncreate_box 1 box\nlattice sc 1.0\n"
        "region fill block 0 10 0 10 0.5 12.5\ncreate_atoms 1 region fill\n"
        "fix wall all wall/gran granular hooke 2e5 0.5 tangential linear_history 1.5e5 0.3 0.4 "
        "zplane 0.0 NULL\n"
        "fix grav all gravity 10 vector 0.3 0.0 -1.0\n";
  } else {
    d = "units lj\ndimension 2\natom_style sphere\nboundary p fm p\ncomm_modify vel yes\n"
        "region box block 0 40 0 40 -0.5 0.5\ncreate_box 1 box\nlattice sq 1.0\n"
        "region fill block 0 40 0.5 30.5 -0.5 0.5\ncreate_atoms 1 region fill\n"
        "fix wall all wall/gran granular hooke 2e5 0.5 tangential linear_history 1.5e5 0.3 0.4 "
        "yplane 0.0 NULL\n"
        "fix grav all gravity 10 vector 0.3 -1.0 0.0\nfix 2d all enforce2d\n";
  }
  d += "variable d atom 0.96+0.08*random(0,1,4321)\nset group all diameter v_d\n"
       "set group all density 1.0\nvelocity all create 0.5 87287 loop geom\n"
       "pair_style " + style + "\npair_coeff * * " + dc.coeff + "\n"
       "fix nve all nve/sphere\ntimestep 1e-4\nneighbor 0.3 bin\n"
       "neigh_modify delay 0 every 1 check yes\nthermo 0\n";
  return d;
}

void PrintTo(const DeckCase &dc, std::ostream *os) { *os << dc.name; }

class SameAsGranular : public ::testing::TestWithParam<DeckCase> {};

TEST_P(SameAsGranular, Trajectory2000Steps)
{
  const DeckCase dc = GetParam();
  std::vector<double> x[2], v[2], w[2];
  const char *styles[2] = {"granular", "granular/acoustic"};
  for (int k = 0; k < 2; k++) {
    LammpsInstance L;
    L.commands(dense_deck(dc, styles[k]));
    L.command("run 2000");
    x[k] = L.gather("x", 3);
    v[k] = L.gather("v", 3);
    w[k] = L.gather("omega", 3);
  }
  double dx = 0.0, dv = 0.0, dw = 0.0, vmax = 0.0, displacement = 0.0;
  for (std::size_t m = 0; m < x[0].size(); m++) {
    dx = std::max(dx, std::fabs(x[0][m] - x[1][m]));
    dv = std::max(dv, std::fabs(v[0][m] - v[1][m]));
    dw = std::max(dw, std::fabs(w[0][m] - w[1][m]));
    vmax = std::max(vmax, std::fabs(v[0][m]));
  }
  ASSERT_GT(vmax, 0.1) << "the deck does not move: the comparison would be empty";
  if (AcousticTest::mpi_rank() == 0)
    std::printf("[ %s ] max |dx| = %.3g, |dv| = %.3g, |domega| = %.3g (max |v| %.3g)\n", dc.name,
                dx, dv, dw, vmax);
  EXPECT_LE(dx, 1e-12);
  EXPECT_LE(dv, 1e-10 * vmax);
  EXPECT_LE(dw, 1e-10 * std::max(1.0, vmax));
  (void) displacement;
}

const DeckCase kDecks[] = {
    {"3d_hooke_linear_nohistory", 3,
     "hooke 2e5 0.5 damping mass_velocity tangential linear_nohistory 0.5 0.4"},
    {"3d_hooke_linear_history_roll_twist", 3,
     "hooke 2e5 50 damping velocity tangential linear_history 1.5e5 0.3 0.4 "
     "rolling sds 1e4 50 0.1 twisting sds 1e3 10 0.05"},
    {"3d_hertz_linear_history", 3, "hertz 5e5 0.5 tangential linear_history 2e5 0.5 0.5"},
    {"3d_hertz_material_mindlin", 3, "hertz/material 1e6 0.3 0.3 tangential mindlin NULL 1.0 0.5"},
    {"3d_tsuji_mindlin_rescale_marshall", 3,
     "hertz/material 1e6 0.5 0.3 damping tsuji tangential mindlin_rescale NULL 1.0 0.5 "
     "twisting marshall"},
    // not dmt: pair granular of this LAMMPS version uses an unset cohesion in the
    // Coulomb limit of DMT contacts (see DmtContact below for the DMT check)
    {"3d_mindlin_force_roll", 3,
     "hertz/material 1e6 0.3 0.3 tangential mindlin/force NULL 1.0 0.5 rolling sds 1e4 50 0.1"},
    {"3d_jkr_mindlin_rescale_force", 3,
     "jkr 1e6 0.3 0.3 0.5 tangential mindlin_rescale/force NULL 1.0 0.5"},
    {"2d_hooke_linear_nohistory", 2,
     "hooke 2e5 0.5 damping mass_velocity tangential linear_nohistory 0.5 0.4"},
    {"2d_hooke_linear_history_limit", 2,
     "hooke 2e5 0.5 tangential linear_history 1.5e5 0.3 0.4 limit_damping"},
    {"2d_hertz_material_mindlin", 2, "hertz/material 1e6 0.3 0.3 tangential mindlin NULL 1.0 0.5"},
    {"2d_mindlin_rescale_roll", 2,
     "hertz/material 1e6 0.3 0.3 tangential mindlin_rescale NULL 1.0 0.5 rolling sds 1e4 50 0.1"},
    {"2d_mindlin_force_tsuji", 2,
     "hertz/material 1e6 0.5 0.3 damping tsuji tangential mindlin/force 4e5 1.0 0.5"},
    {"2d_jkr_mindlin_rescale_force", 2,
     "jkr 1e6 0.3 0.3 0.5 tangential mindlin_rescale/force NULL 1.0 0.5"},
};

INSTANTIATE_TEST_SUITE_P(Decks, SameAsGranular, ::testing::ValuesIn(kDecks),
                         [](const ::testing::TestParamInfo<DeckCase> &info) {
                           return std::string(info.param.name);
                         });

// ---------------------------------------------------------------------------
// 2. a grain pressed on a fixed grain sticks below s*mu*F_n and slides above

struct CoulombCase {
  double s;
  double ratio;    // F_t / (s mu F_n)
};

void PrintTo(const CoulombCase &cc, std::ostream *os)
{
  *os << "s=" << cc.s << " Ft/(s mu Fn)=" << cc.ratio;
}

class CoulombLimit : public ::testing::TestWithParam<CoulombCase> {};

TEST_P(CoulombLimit, StickOrSlide)
{
  const CoulombCase cc = GetParam();
  const double kn = 1000.0, kt = 800.0, mu = 0.5, Fn = 10.0;
  const double Ft = cc.ratio * cc.s * mu * Fn;
  const double overlap = Fn / kn;

  LammpsInstance L;
  L.commands("units lj\natom_style sphere\nboundary m m m\ncomm_modify vel yes\n"
             "region box block -3 3 -3 3 -3 3\ncreate_box 1 box\n");
  L.command("create_atoms 1 single 0 0 0");
  L.command("create_atoms 1 single 0 0 " + std::to_string(1.0 - overlap));
  L.commands("set group all diameter 1.0\nset group all density 1.0\n"
             "group fixed id 1\ngroup pushed id 2\n"
             "pair_style granular/acoustic\n");
  L.command("pair_coeff * * hooke " + std::to_string(kn) +
            " 50 damping mass_velocity tangential linear_history " + std::to_string(kt) + " 1.0 " +
            std::to_string(mu));
  // translation only: omega of the pushed grain stays zero (no rotation)
  L.commands("fix move pushed nve\ntimestep 1e-3\n"
             "variable ft equal " + std::to_string(Ft) + "*ramp(0,1)\n"
             "variable fn equal " + std::to_string(-Fn) + "\n"
             "fix push pushed addforce v_ft 0.0 v_fn\n"
             "compute pl all pair/local p13\n"
             "thermo 0\nrun 0\n");

  PairGranularAcoustic *pair = acoustic_pair(L);
  std::vector<PairGranularAcoustic::ContactState> contacts;
  pair->current_contacts(contacts, 1);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].fn, Fn, 1e-9 * Fn);
  EXPECT_DOUBLE_EQ(pair->friction_factor(contacts[0].history), 1.0) << "a new contact starts at 1";
  pair->set_friction_factor(contacts[0].history, cc.s);
  pair->store_history_between_runs();

  // single(): compute pair/local reports the factor of the contact
  L.command("run 0");
  LAMMPS_NS::Compute *pl = L.lmp->modify->compute[L.lmp->modify->find_compute("pl")];
  pl->compute_local();
  ASSERT_EQ(pl->size_local_rows, 1);
  EXPECT_NEAR(pl->vector_local[0], cc.s, 1e-15);

  L.command("run 6000");    // force ramped over this run
  L.command("variable ft equal " + std::to_string(Ft));
  L.command("run 4000");    // held

  std::vector<double> x = L.gather("x", 3);
  std::vector<double> v = L.gather("v", 3);
  const double slip = x[3];    // tangential displacement of grain 2
  const double elastic = Ft / kt;
  if (cc.ratio < 1.0) {
    EXPECT_LT(std::fabs(slip), 1.5 * elastic) << "should stick";
    EXPECT_LT(std::fabs(v[3]), 1e-6);
  } else {
    EXPECT_GT(slip, 20.0 * elastic) << "should slide";
    EXPECT_GT(v[3], 0.0);
  }

}

INSTANTIATE_TEST_SUITE_P(Factors, CoulombLimit,
                         ::testing::Values(CoulombCase{1.0, 0.98}, CoulombCase{1.0, 1.02},
                                           CoulombCase{0.6, 0.98}, CoulombCase{0.6, 1.02},
                                           CoulombCase{0.25, 0.98}, CoulombCase{0.25, 1.02}));

// ---------------------------------------------------------------------------
// 2b. contact interface: elastic normal force and linearised stiffnesses

struct StiffnessCase {
  const char *name;
  const char *coeff;
};

void PrintTo(const StiffnessCase &sc, std::ostream *os) { *os << sc.name; }

class ContactInterface : public ::testing::TestWithParam<StiffnessCase> {
 protected:
  // the one contact of two grains of diameters 1 and 0.8 at overlap delta
  PairGranularAcoustic::ContactState contact_at(double delta)
  {
    LammpsInstance L;
    L.commands("units lj\natom_style sphere\nboundary f f f\ncomm_modify vel yes\n"
               "region box block -3 3 -3 3 -3 3\ncreate_box 1 box\n"
               "create_atoms 1 single 0 0 0\n");
    L.command("create_atoms 1 single 0.3 0.4 " + std::to_string(0.9 - delta) +
              "\nset atom 1 diameter 1.0\nset atom 2 diameter 0.8\nset group all density 1.0");
    // the two centres are not aligned with z: place grain 2 at distance 0.9 - delta
    const double dir[3] = {0.3, 0.4, 0.9 - delta};
    const double len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    const double r = 0.9 - delta;
    L.command("set atom 2 x " + std::to_string(dir[0] / len * r) + " y " +
              std::to_string(dir[1] / len * r) + " z " + std::to_string(dir[2] / len * r));
    L.command("pair_style granular/acoustic");
    L.command(std::string("pair_coeff * * ") + GetParam().coeff);
    L.command("thermo 0\nrun 0");
    std::vector<PairGranularAcoustic::ContactState> contacts;
    acoustic_pair(L)->current_contacts(contacts, 1);
    EXPECT_EQ(contacts.size(), 1u);
    PairGranularAcoustic::ContactState c = contacts.at(0);
    c.history = nullptr;    // belongs to the instance that is gone
    actual_delta = c.delta;
    return c;
  }
  double actual_delta = 0.0;
};

TEST_P(ContactInterface, StiffnessIsDerivativeOfForce)
{
  const double delta = 0.01, h = 1e-5;
  const auto c0 = contact_at(delta);
  const double d0 = actual_delta;
  const auto cp = contact_at(delta + h);
  const double dp = actual_delta;
  const auto cm = contact_at(delta - h);
  const double dm = actual_delta;
  ASSERT_NEAR(d0, delta, 1e-6);
  // unit normal from grain 2 to grain 1
  EXPECT_NEAR(c0.n[0] * c0.n[0] + c0.n[1] * c0.n[1] + c0.n[2] * c0.n[2], 1.0, 1e-14);
  EXPECT_LT(c0.n[2], 0.0);
  const double dFdd = (cp.fn - cm.fn) / (dp - dm);
  EXPECT_NEAR(c0.kn, dFdd, 1e-6 * std::fabs(dFdd)) << "F_n = " << c0.fn;
  EXPECT_GT(c0.kn, 0.0);
  EXPECT_DOUBLE_EQ(c0.mu, 0.4);
}

TEST(ContactInterfaceClosedForm, HertzMaterialAndDmt)
{
  // F_n = 4/3 E* sqrt(R*) delta^(3/2) - 4 pi w R* with 1/E* = 2 (1 - nu^2) / E, 1/R* = 1/R1 + 1/R2
  const double E = 1e6, nu = 0.3, w = 0.5, delta = 0.02;
  const double Estar = E / (2 * (1 - nu * nu)), Rstar = 0.5 * 0.4 / 0.9;
  const double hertz = 4.0 / 3.0 * Estar * std::sqrt(Rstar) * std::pow(delta, 1.5);
  const char *models[2] = {"hertz/material 1e6 0.3 0.3", "dmt 1e6 0.3 0.3 0.5"};
  for (int m = 0; m < 2; m++) {
    LammpsInstance L;
    L.commands("units lj\natom_style sphere\nboundary f f f\ncomm_modify vel yes\n"
               "region box block -3 3 -3 3 -3 3\ncreate_box 1 box\n"
               "create_atoms 1 single 0 0 0\n");
    L.command("create_atoms 1 single 0 0 " + std::to_string(0.9 - delta));
    L.commands("set atom 1 diameter 1.0\nset atom 2 diameter 0.8\nset group all density 1.0\n"
               "pair_style granular/acoustic\n");
    L.command(std::string("pair_coeff * * ") + models[m] + " tangential mindlin NULL 0.5 0.4");
    L.command("thermo 0\nrun 0");
    std::vector<PairGranularAcoustic::ContactState> contacts;
    acoustic_pair(L)->current_contacts(contacts, 1);
    ASSERT_EQ(contacts.size(), 1u);
    const double expected = hertz - (m == 1 ? 4 * M_PI * w * Rstar : 0.0);
    EXPECT_NEAR(contacts[0].fn, expected, 1e-10 * hertz) << models[m];
    // Mindlin tangential stiffness 8 G* a with 1/G* = 2 * 2 (2 - nu)(1 + nu) / E, a = sqrt(R* delta)
    const double Gstar = 1.0 / (2 * 2 * (2 - nu) * (1 + nu) / E);
    EXPECT_NEAR(contacts[0].kt, 8 * Gstar * std::sqrt(Rstar * delta), 1e-10 * contacts[0].kt);
  }
}

const StiffnessCase kStiffness[] = {
    {"hooke", "hooke 2e5 0.5 tangential linear_history 1e5 0.5 0.4"},
    {"hertz", "hertz 5e5 0.5 tangential linear_history 1e5 0.5 0.4"},
    {"hertz_material", "hertz/material 1e6 0.3 0.3 tangential mindlin NULL 0.5 0.4"},
    {"dmt", "dmt 1e6 0.3 0.3 0.5 tangential mindlin NULL 0.5 0.4"},
    {"jkr", "jkr 1e6 0.3 0.3 0.5 tangential mindlin NULL 0.5 0.4"},
};

INSTANTIATE_TEST_SUITE_P(NormalModels, ContactInterface, ::testing::ValuesIn(kStiffness),
                         [](const ::testing::TestParamInfo<StiffnessCase> &info) {
                           return std::string(info.param.name);
                         });

// ---------------------------------------------------------------------------
// 3. the factor follows each contact through reneighboring, migration, restart

std::string flowing_fixes(const std::string &tilt)
{
  return "fix wall all wall/gran granular hooke 2e4 20 damping mass_velocity "
         "tangential linear_history 1e4 0.5 0.5 zplane 0.0 NULL\n"
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
      "set group all density 1.0\n"
      "pair_style granular/acoustic\n"
      "pair_coeff * * hooke 2e4 20 damping mass_velocity tangential linear_history 1e4 0.5 0.5\n"
      + flowing_fixes("0.0") +
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

  std::map<ContactKey, double> previous = all_factors(L);
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
    std::map<ContactKey, double> now = all_factors(L);
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

TEST_P(FactorHistory, SurvivesRestart)
{
  const std::string file = "factor_history_" + std::string(GetParam()) + ".restart";
  std::map<ContactKey, double> before;
  {
    LammpsInstance L;
    L.commands(flowing_deck(GetParam()));
    set_factors(L);
    L.command("run 50");
    before = all_factors(L);
    L.command("write_restart " + file);
  }
  ASSERT_GT(before.size(), 300u);
  std::size_t changed = 0;
  for (const auto &kv : before) changed += (kv.second != 1.0);
  ASSERT_GT(changed, before.size() / 2);

  LammpsInstance L;
  L.command("read_restart " + file);
  L.commands("comm_modify vel yes\n" + flowing_fixes("0.1") +
             "neighbor 0.05 bin\nneigh_modify delay 0 every 1 check yes\nthermo 0\nrun 0\n");
  std::map<ContactKey, double> after = all_factors(L);
  ASSERT_EQ(after.size(), before.size());
  for (const auto &kv : before) {
    auto it = after.find(kv.first);
    ASSERT_NE(it, after.end()) << "contact " << kv.first.first << "-" << kv.first.second;
    EXPECT_DOUBLE_EQ(it->second, kv.second) << "contact " << kv.first.first << "-" << kv.first.second;
  }
  if (AcousticTest::mpi_rank() == 0) std::remove(file.c_str());
}

INSTANTIATE_TEST_SUITE_P(Newton, FactorHistory, ::testing::Values("on", "off"),
                         [](const ::testing::TestParamInfo<const char *> &info) {
                           return std::string("newton_") + info.param;
                         });

// ---------------------------------------------------------------------------
// 4. errors

struct BadInput {
  const char *name;
  const char *setup;       // lines before the failing command
  const char *command;     // the command that must fail
  const char *message;     // part of the expected ERROR message
};

void PrintTo(const BadInput &b, std::ostream *os) { *os << b.name; }

class PairCoeffErrors : public ::testing::TestWithParam<BadInput> {};

TEST_P(PairCoeffErrors, ClearError)
{
  const BadInput bad = GetParam();
  LammpsInstance L;
  L.commands("units lj\natom_style sphere\ncomm_modify vel yes\n"
             "region box block 0 4 0 4 0 4\ncreate_box 1 box\n"
             "create_atoms 1 single 1 1 1\ncreate_atoms 1 single 1 1 1.9\n");
  L.commands(bad.setup);
  try {
    L.commands(bad.command);
    FAIL() << "no error for: " << bad.command;
  } catch (LAMMPS_NS::LAMMPSException &e) {
    EXPECT_NE(std::string(e.what()).find(bad.message), std::string::npos)
        << "message was: " << e.what();
    EXPECT_EQ(std::string(e.what()).find("ERROR"), 0u) << e.what();
  }
}

const BadInput kBadInputs[] = {
    {"unknown_keyword", "pair_style granular/acoustic",
     "pair_coeff * * hooke 1000 0.5 tangential linear_history 800 0.5 0.5 sticky 3",
     "unknown keyword 'sticky'"},
    {"unknown_tangential", "pair_style granular/acoustic",
     "pair_coeff * * hooke 1000 0.5 tangential coulomb 800 0.5 0.5",
     "unknown tangential model 'coulomb'; supported: linear_nohistory"},
    {"unknown_damping", "pair_style granular/acoustic",
     "pair_coeff * * hooke 1000 0.5 damping stokes tangential linear_history 800 0.5 0.5",
     "unknown damping model 'stokes'"},
    {"unknown_rolling", "pair_style granular/acoustic",
     "pair_coeff * * hooke 1000 0.5 tangential linear_history 800 0.5 0.5 rolling spring 1 1 1",
     "unknown rolling model 'spring'"},
    {"unknown_twisting", "pair_style granular/acoustic",
     "pair_coeff * * hooke 1000 0.5 tangential linear_history 800 0.5 0.5 twisting spin",
     "unknown twisting model 'spin'"},
    {"no_tangential", "pair_style granular/acoustic", "pair_coeff * * hooke 1000 0.5",
     "a normal model (hooke, hertz, hertz/material, dmt, jkr) and a tangential model"},
    {"no_normal", "pair_style granular/acoustic",
     "pair_coeff * * tangential linear_history 800 0.5 0.5", "a normal model"},
    {"missing_values", "pair_style granular/acoustic", "pair_coeff * * hooke 1000",
     "hooke needs 2 values"},
    {"not_a_number", "pair_style granular/acoustic",
     "pair_coeff * * hooke stiff 0.5 tangential linear_history 800 0.5 0.5",
     "expected a number for hooke kn, got 'stiff'"},
    {"null_kt_without_material", "pair_style granular/acoustic",
     "pair_coeff * * hertz 1000 0.5 tangential mindlin NULL 0.5 0.5",
     "NULL tangential stiffness (Mindlin from material) requires"},
    {"limit_damping_jkr", "pair_style granular/acoustic",
     "pair_coeff * * jkr 1e6 0.3 0.3 1 tangential mindlin NULL 0.5 0.5 limit_damping",
     "limit_damping cannot be used with the JKR or DMT"},
    {"bad_poisson", "pair_style granular/acoustic",
     "pair_coeff * * hertz/material 1e6 0.3 0.7 tangential mindlin NULL 0.5 0.5",
     "material models need E > 0 and -1 < nu < 0.5"},
    {"negative_friction", "pair_style granular/acoustic",
     "pair_coeff * * hooke 1000 0.5 tangential linear_history 800 0.5 -0.5",
     "friction coefficients must be >= 0"},
    {"bad_type", "pair_style granular/acoustic",
     "pair_coeff 1 3 hooke 1000 0.5 tangential linear_history 800 0.5 0.5", "Numeric index 3 is out of bounds"},
    {"pair_style_args", "", "pair_style granular/acoustic 1.0 2.0",
     "expected at most one argument (a global cutoff)"},
    {"no_ghost_velocity",
     "comm_modify vel no\npair_style granular/acoustic\n"
     "pair_coeff * * hooke 1000 0.5 tangential linear_history 800 0.5 0.5",
     "run 0", "requires ghost atoms to store velocity (use comm_modify vel yes)"},
};

INSTANTIATE_TEST_SUITE_P(BadInput, PairCoeffErrors, ::testing::ValuesIn(kBadInputs),
                         [](const ::testing::TestParamInfo<BadInput> &info) {
                           return std::string(info.param.name);
                         });

TEST(PairStyleErrors, AtomStyleWithoutRadius)
{
  LammpsInstance L;
  L.commands("units lj\natom_style atomic\nregion box block 0 4 0 4 0 4\ncreate_box 1 box\n"
             "create_atoms 1 single 1 1 1\nmass 1 1.0\npair_style granular/acoustic\n"
             "pair_coeff * * hooke 1000 0.5 tangential linear_history 800 0.5 0.5\n");
  try {
    L.command("run 0");
    FAIL() << "atom_style atomic accepted";
  } catch (LAMMPS_NS::LAMMPSException &e) {
    EXPECT_NE(std::string(e.what()).find("requires atom attributes radius and rmass (use atom_style sphere)"),
              std::string::npos)
        << e.what();
  }
}

}    // namespace
