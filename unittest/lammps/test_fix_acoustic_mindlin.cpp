// Integration tests of fix acoustic/mindlin: the amplitudes it computes equal
// the steady response of the DEM itself to a vibrating base (lock-in), the
// Mindlin law through LAMMPS, 1 vs 2 ranks, restart, frequency 0, a singular
// solve, outputs, and the errors of bad input.
#include "lammps_fixture.h"

#include "acoustic_dynamical_matrix.h"
#include "acoustic_vibration_modes.h"
#include "atom.h"
#include "compute.h"
#include "domain.h"
#include "exceptions.h"
#include "fix.h"
#include "group.h"
#include "modify.h"
#include "update.h"
#include "vibration_network.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using AcousticTest::ContactKey;
using AcousticTest::LammpsInstance;

namespace {

LAMMPS_NS::Fix *find_fix(LammpsInstance &L, const char *id)
{
  const int ifix = L.lmp->modify->find_fix(id);
  EXPECT_GE(ifix, 0) << "no fix " << id;
  return (ifix >= 0) ? L.lmp->modify->fix[ifix] : nullptr;
}

std::string file_text(const std::string &name)
{
  std::ifstream in(name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string fmt_double(double v)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.17g", v);
  return buf;
}

// A 2D hexagonal crystal of equal discs, 6 rows on a row of base grains,
// periodic along x, every contact preloaded by a slight overlap, settled under
// gravity.  Hooke normal springs: stiffness pair is the exact linearisation.
std::string crystal_deck(const std::string &tangential)
{
  return "units lj\ndimension 2\natom_style sphere\nboundary p fm p\ncomm_modify vel yes\n"
         "lattice hex 1.1547005383792517\n"    // nearest neighbour distance 1
         "region box block 0 8 0 5 -0.5 0.5\ncreate_box 2 box\n"
         "region base block INF INF -0.1 0.1 INF INF units box\n"
         "region layer block INF INF 0.5 5.3 INF INF units box\n"
         "create_atoms 2 region base\ncreate_atoms 1 region layer\n"
         "group base type 2\ngroup grains type 1\n"
         "set group all diameter 1.002\nset group all density 1.0\n"
         "pair_style granular\n"
         "pair_coeff * * hooke 1e4 150 damping mass_velocity tangential " + tangential + "\n"
         "fix integrate grains nve/sphere\nfix plane all enforce2d\n"
         "fix grav grains gravity 1.0 vector 0 -1 0\n"
         "timestep 1e-3\nneighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\nthermo 0\n"
         "run 20000\n";
}

// lowest non-zero eigenfrequency of the network with the base clamped
double lowest_frequency(LammpsInstance &L, const std::string &model)
{
  LAMMPS_NS::VibrationNetworkSettings settings;
  settings.model = Acoustic::contact_model_from_name(model);
  LAMMPS_NS::VibrationNetwork net(L.lmp, settings, "test");
  net.init();
  const int all = L.lmp->group->bitmask[L.lmp->group->find("all")];
  const int base = L.lmp->group->bitmask[L.lmp->group->find("base")];
  net.build(all, {base});
  const auto &network = net.network();
  std::vector<int> fixed;
  for (int g : net.marked_grains(0))
    for (int k = 0; k < network.dofs_per_grain(); k++) fixed.push_back(network.dof(g, k));
  Acoustic::DynamicalMatrix D(network.stiffness_matrix(), network.mass_diagonal(), fixed,
                              network.dofs_per_grain());
  Acoustic::VibrationModes modes = Acoustic::dense_vibration_modes(D, false);
  EXPECT_EQ(modes.zero_modes, 0) << "the crystal should have no floppy mode";
  return modes.frequencies[modes.zero_modes];
}

// ---------------------------------------------------------------------------
// 1. the fix's amplitudes are the DEM's own steady response to a vibrating base

// Relax the crystal, drive its base vertically with amplitude A (ramped up over
// 10 periods), and return, per atom ID t, the lock-in sums <dx cos>, <dx sin>,
// <dy cos>, <dy sin> over the last 20 of 60 periods (entries 4t .. 4t+3).
std::vector<double> lock_in(const std::string &tangential, int steps_per_period, double dt,
                            double A, int natoms)
{
  LammpsInstance L;
  L.commands(crystal_deck(tangential));
  const int nperiods = 60, nlock = 20, nramp = 10;
  const int nsteps = nperiods * steps_per_period, ramp = nramp * steps_per_period;
  const double omega = 2.0 * M_PI / (steps_per_period * dt);
  L.commands("pair_coeff * * hooke 1e4 4 damping mass_velocity tangential " + tangential + "\n"
             "reset_timestep 0\ntimestep " + fmt_double(dt) + "\n"
             "compute dsp all displace/atom\n"
             "variable ph equal 2.0*PI*step/" + std::to_string(steps_per_period) + "\n"
             "variable ramp equal (step<" + std::to_string(ramp) + ")*step/" + std::to_string(ramp) +
             "+(step>=" + std::to_string(ramp) + ")\n"
             "variable dy equal " + fmt_double(A) + "*v_ramp*sin(v_ph)\n"
             "variable vy equal " + fmt_double(A * omega) + "*v_ramp*cos(v_ph)\n"
             // a NULL displacement would let fix move integrate that coordinate: hold x
             "variable zero equal 0.0\n"
             "fix shake base move variable v_zero v_dy NULL v_zero v_vy NULL units box\n"
             "variable xc atom c_dsp[1]*cos(v_ph)\nvariable xs atom c_dsp[1]*sin(v_ph)\n"
             "variable yc atom c_dsp[2]*cos(v_ph)\nvariable ys atom c_dsp[2]*sin(v_ph)\n"
             "fix lock all ave/atom 1 " + std::to_string(nlock * steps_per_period) + " " +
             std::to_string(nsteps) + " v_xc v_xs v_yc v_ys\n");
  L.command("run " + std::to_string(nsteps));
  std::vector<double> sums(4 * (natoms + 1), 0.0);
  LAMMPS_NS::Fix *lock = find_fix(L, "lock");
  if (!lock) return sums;
  for (int i = 0; i < L.lmp->atom->nlocal; i++)
    for (int k = 0; k < 4; k++) sums[4 * L.lmp->atom->tag[i] + k] = lock->array_atom[i][k];
  return sums;
}

struct ResponseCase {
  const char *model;
  const char *tangential;
};

void PrintTo(const ResponseCase &rc, std::ostream *os) { *os << rc.model; }

class LinearResponse : public ::testing::TestWithParam<ResponseCase> {};

TEST_P(LinearResponse, MatchesDrivenDemByLockIn)
{
  const ResponseCase rc = GetParam();
  LammpsInstance L;
  L.commands(crystal_deck(rc.tangential));

  const double fmin = lowest_frequency(L, rc.model);
  const double f = 0.6 * fmin;
  const double period = 1.0 / f;
  // an integer number of steps per period, with a step no larger than the relaxation's
  const int steps_per_period = static_cast<int>(std::ceil(period / 1e-3));
  const double dt = period / steps_per_period;
  const double A = 1e-7;    // drive amplitude, far below the overlaps (~1e-3)

  // the fix at the equilibrium: U0 |q| per translation
  L.command("fix ac all acoustic/mindlin 1000000 frequency " + fmt_double(f) + " amplitude " +
            fmt_double(A) + " source base stiffness pair model " + rc.model);
  L.command("run 0");
  LAMMPS_NS::Fix *fix = find_fix(L, "ac");
  ASSERT_NE(fix, nullptr);
  const int natoms = static_cast<int>(L.natoms());
  std::vector<double> predicted(2 * (natoms + 1), 0.0);
  for (int i = 0; i < L.lmp->atom->nlocal; i++)
    for (int k = 0; k < 2; k++) predicted[2 * L.lmp->atom->tag[i] + k] = fix->array_atom[i][k];
  EXPECT_LT(fix->compute_vector(4), 1e-10) << "relative residual of the solve";
  EXPECT_EQ(fix->compute_vector(10), 1.0) << "one symbolic analysis";
  L.command("unfix ac");

  // the DEM from the same equilibrium, with the base driven at f and without
  // drive: the difference of the two lock-ins is the response to the drive,
  // free of the slow relaxation the packing may still have
  std::vector<double> driven = lock_in(rc.tangential, steps_per_period, dt, A, natoms);
  std::vector<double> still = lock_in(rc.tangential, steps_per_period, dt, 0.0, natoms);
  std::vector<double> measured(2 * (natoms + 1), 0.0);
  for (int t = 1; t <= natoms; t++)
    for (int k = 0; k < 2; k++) {
      // the part in phase with the drive A sin(phase): the undamped fix's
      // amplitudes are signed displacements in phase with it
      const double s = driven[4 * t + 2 * k + 1] - still[4 * t + 2 * k + 1];
      measured[2 * t + k] = 2.0 * s;
    }

  double max_pred = 0.0, max_err = 0.0, worst_ratio = 1.0;
  if (getenv("ACOUSTIC_TEST_VERBOSE"))
    for (int t = 1; t <= natoms; t++)
      std::printf("atom %d: fix %.4g %.4g  DEM %.4g %.4g\n", t, predicted[2 * t] / A,
                  predicted[2 * t + 1] / A, measured[2 * t] / A, measured[2 * t + 1] / A);
  for (int t = 1; t <= natoms; t++)
    for (int k = 0; k < 2; k++) {
      max_pred = std::max(max_pred, std::fabs(predicted[2 * t + k]));
      max_err = std::max(max_err, std::fabs(predicted[2 * t + k] - measured[2 * t + k]));
    }
  for (int t = 1; t <= natoms; t++)    // the vertical response of every grain, relative
    if (std::fabs(predicted[2 * t + 1]) > 0.2 * max_pred) {
      const double ratio = measured[2 * t + 1] / predicted[2 * t + 1];    // < 0: opposite signs
      worst_ratio = std::max(worst_ratio, ratio > 0.0 ? std::max(ratio, 1.0 / ratio) : HUGE_VAL);
    }
  std::printf("[ model %s ] f = %.4g (0.6 f_min), max |q| = %.4g A, max |DEM - fix| = %.3g of it, "
              "worst ratio of vertical amplitudes %.4f\n",
              rc.model, f, max_pred / A, max_err / max_pred, worst_ratio);
  ASSERT_GT(max_pred, 1.05 * A) << "the response should differ from a rigid motion";
  EXPECT_LT(max_err, 0.02 * max_pred);
  EXPECT_LT(worst_ratio, 1.02);
}

INSTANTIATE_TEST_SUITE_P(Models, LinearResponse,
                         ::testing::Values(ResponseCase{"normal", "linear_nohistory/acoustic 0.0 0.5"},
                                           ResponseCase{"full", "linear_history/acoustic 8e3 1.0 10.0"}),
                         [](const ::testing::TestParamInfo<ResponseCase> &info) {
                           return std::string(info.param.model);
                         });

// ---------------------------------------------------------------------------
// 2. the Mindlin law through LAMMPS, outputs, frequency 0

// a wider crystal of Hertz grains with friction, settled under gravity
std::string layer_deck(const std::string &newton = "on", int length = 16, int height = 5)
{
  return "units lj\ndimension 2\natom_style sphere\nboundary p fm p\ncomm_modify vel yes\n"
         "newton " + newton + "\nprocessors * 1 1\n"
         "lattice hex 1.1547005383792517\n"
         "region box block 0 " + std::to_string(length) + " 0 " + std::to_string(height) +
         " -0.5 0.5\ncreate_box 2 box\n"
         "region base block INF INF -0.1 0.1 INF INF units box\n"
         "region layer block INF INF 0.5 " + std::to_string(height + 0.3) + " INF INF units box\n"
         "create_atoms 2 region base\ncreate_atoms 1 region layer\n"
         "group base type 2\ngroup grains type 1\n"
         "set group all diameter 1.002\nset group all density 1.0\n"
         "pair_style granular\n"
         "pair_coeff * * hertz/material 1e5 0.5 0.3 tangential mindlin/acoustic NULL 1.0 0.5\n"
         "fix integrate grains nve/sphere\nfix plane all enforce2d\n"
         "fix grav grains gravity 1.0 vector 0 -1 0\n"
         "timestep 1e-3\nneighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\nthermo 0\n"
         "run 3000\n";
}

TEST(FixMindlinLaw, LocalArrayFollowsPaperClosedForm)
{
  // stiffness hertz, eta = 2/7, C_mu = 1: mu*/mu = 1 - 3 U0 kappa^(2/3) |P dq| / (7 mu f_n^(2/3))
  // which with k_n = 3/2 kappa^(2/3) f_n^(1/3) and U_t = U0 |P dq| is 1 - (2/7) k_n U_t / (mu f_n)
  LammpsInstance L;
  L.commands(layer_deck());
  L.command("fix ac all acoustic/mindlin 100 frequency 3.0 amplitude 5e-4 source base "
            "stiffness hertz 1e5 0.3 kappa_scale 2.0");
  L.command("run 0");
  LAMMPS_NS::Fix *fix = find_fix(L, "ac");
  ASSERT_NE(fix, nullptr);
  const int nrows = fix->size_local_rows;
  ASSERT_GT(nrows, 50);
  const double mu = 0.5;
  double sum = 0.0, minimum = 1.0;
  int reduced = 0, weak = 0;
  for (int r = 0; r < nrows; r++) {
    const double *row = fix->array_local[r];
    const double fn = row[2], kn = row[3], ut = row[4], s = row[5];
    ASSERT_TRUE(std::isfinite(s));
    const double expected = std::min(1.0, std::max(0.0, 1.0 - (2.0 / 7.0) * kn * ut / (mu * fn)));
    EXPECT_NEAR(s, expected, 1e-12) << "contact " << row[0] << "-" << row[1];
    // k_n of stiffness hertz with kappa_scale: 3/2 kappa^(2/3) f_n^(1/3) (checked on one contact)
    sum += s;
    minimum = std::min(minimum, s);
    reduced += (s < 1.0);
    weak += (s < 0.5);
  }
  EXPECT_GT(reduced, nrows / 4) << "the vibration should reduce friction on many contacts";
  EXPECT_DOUBLE_EQ(fix->compute_vector(0), nrows);
  EXPECT_NEAR(fix->compute_vector(1), sum / nrows, 1e-12);
  EXPECT_DOUBLE_EQ(fix->compute_vector(2), minimum);
  EXPECT_NEAR(fix->compute_vector(3), double(weak) / nrows, 1e-12);

  // the factors are in the contact history, where the pair style reads them
  std::map<ContactKey, double> factors = AcousticTest::friction_factors(L);
  for (int r = 0; r < nrows; r++) {
    const double *row = fix->array_local[r];
    const ContactKey key(std::min<long>(row[0], row[1]), std::max<long>(row[0], row[1]));
    ASSERT_TRUE(factors.count(key));
    EXPECT_NEAR(factors[key], row[5], 1e-15);
  }
}

TEST(FixMindlinLaw, FrequencyZeroSetsEveryFactorToOne)
{
  LammpsInstance L;
  L.commands(layer_deck());
  L.command("fix ac all acoustic/mindlin 100 frequency 3.0 amplitude 5e-4 source base");
  L.command("run 0");
  int reduced = 0;
  for (const auto &kv : AcousticTest::friction_factors(L)) reduced += (kv.second < 1.0);
  ASSERT_GT(reduced, 10);
  L.command("unfix ac");
  L.command("fix ac all acoustic/mindlin 100 frequency 0 amplitude 5e-4 source base");
  L.command("run 0");
  for (const auto &kv : AcousticTest::friction_factors(L)) EXPECT_EQ(kv.second, 1.0);
}

TEST(FixMindlinLaw, UpdatesAtMultiplesOfNOnly)
{
  // a deck made of short runs (as the tilt ramps): the factors are updated at
  // the steps that are multiples of N, and at the setup of a run only when
  // they are not those of the last multiple of N
  LammpsInstance L;
  L.commands(layer_deck());
  L.command("fix ac all acoustic/mindlin 50 frequency 3.0 amplitude 5e-4 source base");
  L.command("run 50");    // updates at setup (a new fix) and at step 50
  LAMMPS_NS::Fix *fix = find_fix(L, "ac");
  const double solves = fix->compute_vector(11) + fix->compute_vector(12);
  EXPECT_EQ(fix->compute_vector(11), 2.0);
  const std::map<ContactKey, double> before = AcousticTest::friction_factors(L);
  L.command("fix grav grains gravity 1.0 vector 0.1 -1 0");    // new tilt, atoms unmoved
  L.command("run 0");    // step 50: the factors of step 50 are current
  EXPECT_EQ(fix->compute_vector(11) + fix->compute_vector(12), solves);
  EXPECT_EQ(AcousticTest::friction_factors(L), before);
  L.command("run 30");    // steps 51 to 80: no multiple of 50
  EXPECT_EQ(fix->compute_vector(11) + fix->compute_vector(12), solves);
  L.command("run 30");    // steps 81 to 110: step 100
  EXPECT_EQ(fix->compute_vector(11) + fix->compute_vector(12), solves + 1.0);
}

// ---------------------------------------------------------------------------
// 3. 1 vs 2 ranks, restart

TEST(FixParallel, EverySolverGivesTheSameFactors)
{
  // MUMPS (auto, mumps: on every rank), UMFPACK (lu) and CHOLMOD (ldlt) on rank 0:
  // independent factorisations of the same system, undamped and damped
  for (const std::string damping : {"", " damping 0.05"}) {
    std::map<ContactKey, double> reference;
    for (const std::string solver : {"auto", "mumps", "lu", "ldlt"}) {
      if (solver == "ldlt" && !damping.empty()) continue;    // real symmetric only
      SCOPED_TRACE("solver " + solver + damping);
      LammpsInstance L;
      L.commands(layer_deck());
      L.command("fix ac all acoustic/mindlin 50 frequency 3.0 amplitude 5e-4 source base model full" +
                damping + " solver " + solver);
      L.command("run 0");
      const std::map<ContactKey, double> factors = AcousticTest::friction_factors(L);
      if (reference.empty()) {
        reference = factors;
        int reduced = 0;
        for (const auto &kv : factors) reduced += (kv.second < 1.0);
        EXPECT_GT(reduced, 10);
        continue;
      }
      ASSERT_EQ(factors.size(), reference.size());
      for (const auto &kv : reference) EXPECT_NEAR(factors.at(kv.first), kv.second, 1e-8);
    }
  }
}

// x and y of every atom of the instance, keyed by atom ID, on every rank
static std::map<long, std::pair<double, double>> positions_by_tag(LammpsInstance &L)
{
  std::vector<double> mine;
  LAMMPS_NS::Atom *atom = L.lmp->atom;
  for (int i = 0; i < atom->nlocal; i++) {
    mine.push_back(static_cast<double>(atom->tag[i]));
    mine.push_back(atom->x[i][0]);
    mine.push_back(atom->x[i][1]);
  }
  const std::vector<double> all = AcousticTest::allgather(L, mine);
  std::map<long, std::pair<double, double>> by_tag;
  for (std::size_t k = 0; k < all.size(); k += 3)
    by_tag[static_cast<long>(all[k])] = {all[k + 1], all[k + 2]};
  return by_tag;
}

TEST(FixParallel, DefaultSolverGivesBitwiseTheSameRunTwice)
{
  // the same input on the same ranks (1, or 2 under mpirun -np 2): a tilted
  // layer of 48 x 10 grains that flows under updates every 20 steps,
  // undamped and damped network; the positions after 600 steps must be
  // identical bit for bit.  (With solver mumps, the MUMPS team of both
  // ranks, this fails on 2 ranks: MUMPS sums in the order messages arrive.)
  for (const std::string damping : {"", " damping 0.05"}) {
    SCOPED_TRACE("network" + damping);
    std::map<long, std::pair<double, double>> settled, first;
    for (int repeat = 0; repeat < 2; ++repeat) {
      LammpsInstance L;
      L.commands(layer_deck("on", 48, 10));
      if (repeat == 0) settled = positions_by_tag(L);
      L.commands("fix grav grains gravity 1.0 vector 1 -1 0\n"
                 "fix ac all acoustic/mindlin 20 frequency 3.0 amplitude 5e-4 source base model full" +
                 damping + "\nrun 600\n");
      const std::map<long, std::pair<double, double>> now = positions_by_tag(L);
      if (repeat == 0) {
        first = now;
        continue;
      }
      ASSERT_EQ(now.size(), first.size());
      for (const auto &kv : first) {
        EXPECT_EQ(kv.second.first, now.at(kv.first).first) << "atom " << kv.first;
        EXPECT_EQ(kv.second.second, now.at(kv.first).second) << "atom " << kv.first;
      }
    }
    // the layer really flowed: the comparison is of a sensitive state
    int moved = 0;
    for (const auto &kv : first) moved += (std::fabs(kv.second.first - settled.at(kv.first).first) > 1e-3);
    EXPECT_GT(moved, 20);
  }
}

TEST(FixParallel, OneAndTwoRanksGiveTheSameFactors)
{
  // the same packing (written once by rank 0 alone) read by rank 0 alone and
  // by every rank together (2 under mpirun -np 2); the factors of the solve
  // at setup must agree contact by contact
  const std::string file = "fix_acoustic_ranks.restart";
  const std::string fix = "comm_modify vel yes\nfix integrate grains nve/sphere\n"
                          "fix plane all enforce2d\nneighbor 0.2 bin\nthermo 0\n"
                          "fix ac all acoustic/mindlin 50 frequency 3.0 amplitude 5e-4 source base "
                          "stiffness hertz 1e5 0.3 model full damping 0.05\nrun 0\n";
  std::map<ContactKey, double> serial;
  if (AcousticTest::mpi_rank() == 0) {
    {
      LammpsInstance W(MPI_COMM_SELF);
      W.commands(layer_deck());
      W.command("write_restart " + file);
    }
    LammpsInstance S(MPI_COMM_SELF);
    S.command("read_restart " + file);
    S.commands(fix);
    serial = AcousticTest::friction_factors(S);
  }
  serial = AcousticTest::broadcast_from_rank0(serial);

  LammpsInstance P;
  P.command("read_restart " + file);
  P.commands(fix);
  std::map<ContactKey, double> parallel = AcousticTest::friction_factors(P);
  ASSERT_EQ(parallel.size(), serial.size());
  int reduced = 0;
  double maxdiff = 0.0;
  for (const auto &kv : serial) {
    ASSERT_TRUE(parallel.count(kv.first)) << kv.first.first << "-" << kv.first.second;
    maxdiff = std::max(maxdiff, std::fabs(parallel[kv.first] - kv.second));
    reduced += (kv.second < 1.0);
  }
  if (AcousticTest::mpi_rank() == 0)
    std::printf("[ %d ranks ] %zu contacts, %d with reduced friction, max |s(1) - s(N)| = %.3g\n",
                AcousticTest::mpi_size(), serial.size(), reduced, maxdiff);
  EXPECT_GT(reduced, 10);
  EXPECT_LE(maxdiff, 1e-8);
  MPI_Barrier(MPI_COMM_WORLD);
  if (AcousticTest::mpi_rank() == 0) std::remove(file.c_str());
}

TEST(FixParallel, RestartKeepsTheFactors)
{
  const std::string file = "fix_acoustic_restart.bin";
  std::map<ContactKey, double> before;
  {
    LammpsInstance L;
    L.commands(layer_deck("off"));
    L.commands("fix ac all acoustic/mindlin 40 frequency 3.0 amplitude 5e-4 source base\n"
               "run 100\n");
    before = AcousticTest::friction_factors(L);
    L.command("write_restart " + file);
  }
  int reduced = 0;
  for (const auto &kv : before) reduced += (kv.second < 1.0);
  ASSERT_GT(reduced, 10);

  // the factors come back with the contacts, without the fix
  LammpsInstance L;
  L.command("read_restart " + file);
  L.commands("comm_modify vel yes\nfix integrate grains nve/sphere\nfix plane all enforce2d\n"
             "neighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\nthermo 0\nrun 0\n");
  std::map<ContactKey, double> after = AcousticTest::friction_factors(L);
  ASSERT_EQ(after.size(), before.size());
  for (const auto &kv : before) {
    ASSERT_TRUE(after.count(kv.first));
    // newton off: a contact across the periodic boundary has two copies, equal to
    // the rounding of the image coordinates (1e-10, see friction_factors());
    // either may be the one listed
    EXPECT_NEAR(after[kv.first], kv.second, 1e-10) << kv.first.first << "-" << kv.first.second;
  }
  MPI_Barrier(MPI_COMM_WORLD);
  if (AcousticTest::mpi_rank() == 0) std::remove(file.c_str());
}

// the local rows of fix `id` on every rank, keyed by (lower atom ID, higher
// atom ID), or (atom ID, 0) for a wall: f_n, k_n, U_t, mu*/mu
std::map<ContactKey, std::vector<double>> local_rows(LammpsInstance &L, const char *id)
{
  LAMMPS_NS::Fix *fix = L.lmp->modify->get_fix_by_id(id);
  std::vector<double> mine;
  for (int r = 0; r < fix->size_local_rows; r++)
    for (int k = 0; k < 6; k++) mine.push_back(fix->array_local[r][k]);
  const std::vector<double> all = AcousticTest::allgather(L, mine);
  std::map<ContactKey, std::vector<double>> rows;
  for (std::size_t k = 0; k < all.size(); k += 6) {
    const long i = static_cast<long>(all[k]), j = static_cast<long>(all[k + 1]);
    const ContactKey key = (j == 0) ? ContactKey(i, 0) : ContactKey(std::min(i, j), std::max(i, j));
    EXPECT_EQ(rows.count(key), 0u) << "contact " << key.first << "-" << key.second << " listed twice";
    rows[key] = std::vector<double>(all.begin() + k + 2, all.begin() + k + 6);
  }
  return rows;
}

TEST(FixParallel, RestartWrittenWithOtherSettingsUpdatesAtTheSetup)
{
  // the factors in a restart file belong to the drive that wrote it: the
  // same fix ID defined with another amplitude (or frequency, source, ...)
  // updates at the setup, even at a multiple of N, and its factors are those
  // of a new fix with that amplitude on the same packing
  const std::string file = "fix_acoustic_settings.restart";
  auto fix = [](const std::string &id, const std::string &amplitude) {
    return "fix " + id + " all acoustic/mindlin 40 frequency 3.0 amplitude " + amplitude + " source base\n";
  };
  const std::string continued = "comm_modify vel yes\nfix integrate grains nve/sphere\nfix plane all enforce2d\n"
                                "neighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\nthermo 0\n";
  double factorisations = 0.0, mean_written = 0.0;
  {
    LammpsInstance L;
    L.commands(layer_deck("off"));
    L.commands(fix("ac", "5e-4") + "run 80\n");
    factorisations = L.lmp->modify->get_fix_by_id("ac")->compute_vector(11);
    mean_written = L.lmp->modify->get_fix_by_id("ac")->compute_vector(1);
    L.command("write_restart " + file);
  }
  ASSERT_LT(mean_written, 1.0);
  double mean_new = 0.0;
  {
    // the same packing, the fix defined anew (another ID: no restart state)
    LammpsInstance L;
    L.command("read_restart " + file);
    L.commands(continued + fix("fresh", "1e-4") + "run 0\n");
    mean_new = L.lmp->modify->get_fix_by_id("fresh")->compute_vector(1);
  }
  ASSERT_GT(mean_new, mean_written) << "a smaller amplitude lowers the friction less";
  LammpsInstance L;
  L.command("read_restart " + file);
  L.commands(continued + fix("ac", "1e-4") + "run 0\n");
  LAMMPS_NS::Fix *ac = L.lmp->modify->get_fix_by_id("ac");
  ASSERT_EQ(L.lmp->update->ntimestep % 40, 0);
  EXPECT_EQ(ac->compute_vector(11), factorisations + 1.0) << "an update at the setup";
  EXPECT_EQ(ac->compute_vector(1), mean_new) << "the factors of the new amplitude";
  MPI_Barrier(MPI_COMM_WORLD);
  if (AcousticTest::mpi_rank() == 0) std::remove(file.c_str());
}

TEST(FixParallel, GlobalRestartStateOfAnEarlierVersionIsRead)
{
  // files written before the settings' signature hold [step of the last
  // update, statistics]: read, the step says the factors are current (no
  // update at the setup) and the solver counts go on from the written ones
  const std::string file = "fix_acoustic_old_state.restart";
  const std::string deck = "fix ac all acoustic/mindlin 40 frequency 3.0 amplitude 5e-4 source base\n";
  std::vector<double> earlier_state;
  {
    LammpsInstance L;
    L.commands(layer_deck("off"));
    L.commands(deck + "run 80\n");
    LAMMPS_NS::Fix *ac = L.lmp->modify->get_fix_by_id("ac");
    earlier_state.push_back(static_cast<double>(L.lmp->update->ntimestep));
    for (int k = 0; k < ac->size_vector; k++) earlier_state.push_back(ac->compute_vector(k));
    L.command("write_restart " + file);
  }
  LammpsInstance L;
  L.command("read_restart " + file);
  L.commands("comm_modify vel yes\nfix integrate grains nve/sphere\nfix plane all enforce2d\n"
             "neighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\nthermo 0\n" + deck);
  LAMMPS_NS::Fix *ac = L.lmp->modify->get_fix_by_id("ac");
  // the state of the file replaced by that of an earlier version
  ac->restart(reinterpret_cast<char *>(earlier_state.data()));
  L.command("run 0");
  EXPECT_EQ(ac->compute_vector(11), earlier_state[12]) << "no update at the setup";
  EXPECT_EQ(ac->compute_vector(0), earlier_state[1]) << "the contacts of the last update";
  // the mean is taken again from the factors of the file, summed in the
  // order of the restarted contacts
  EXPECT_NEAR(ac->compute_vector(1), earlier_state[2], 1e-12) << "the factors of the file";
  MPI_Barrier(MPI_COMM_WORLD);
  if (AcousticTest::mpi_rank() == 0) std::remove(file.c_str());
}

TEST(FixParallel, LocalOutputOfARestartedFixHasTheRowsOfItsLastUpdate)
{
  // restarted at a multiple of N: the factors are current, no update at the
  // setup; the local rows at that step are those of the last update, rebuilt
  // from the DOF amplitudes in the restart file (they were once missing until
  // the next update, and before that a dump local read an unset row count)
  const std::string file = "fix_acoustic_local.restart";
  const std::string fix = "fix ac all acoustic/mindlin 40 frequency 3.0 amplitude 5e-4 source base\n";
  double factorisations = 0.0, contacts = 0.0;
  std::map<ContactKey, std::vector<double>> before;
  {
    LammpsInstance L;
    L.commands(layer_deck("off"));
    L.commands(fix + "run 80\n");
    factorisations = L.lmp->modify->get_fix_by_id("ac")->compute_vector(11);
    contacts = L.lmp->modify->get_fix_by_id("ac")->compute_vector(0);
    before = local_rows(L, "ac");
    L.command("write_restart " + file);
  }
  ASSERT_GT(factorisations, 0.0);
  int reduced = 0;
  for (const auto &kv : before) reduced += (kv.second[3] < 1.0);
  ASSERT_GT(reduced, 10);

  LammpsInstance L;
  L.command("read_restart " + file);
  L.commands("comm_modify vel yes\nfix integrate grains nve/sphere\nfix plane all enforce2d\n"
             "neighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\nthermo 0\n" + fix +
             "dump rows all local 40 fix_acoustic_local.dump f_ac[1] f_ac[2] f_ac[6]\nrun 0\n");
  LAMMPS_NS::Fix *ac = L.lmp->modify->get_fix_by_id("ac");
  EXPECT_EQ(ac->compute_vector(11), factorisations) << "no update at the setup";
  EXPECT_EQ(ac->compute_vector(0), contacts) << "the network of the last update, as in the file";
  const LAMMPS_NS::bigint restart_step = L.lmp->update->ntimestep;
  ASSERT_EQ(restart_step % 40, 0);
  // the same contacts with the same f_n, k_n, U_t and factor, up to
  // rounding: read_restart maps atoms that left the periodic box back into
  // it, which moves the images of a contact across the boundary by ~1e-16
  // relative (1e-12 in the overlap and f_n); and on 2 ranks the factor is
  // read from the history of the copy of a contact across a sub-domain
  // boundary that the rank owns now, which may be the other copy (the two
  // agree to the rounding of the image coordinates, see friction_factors())
  const std::map<ContactKey, std::vector<double>> after = local_rows(L, "ac");
  ASSERT_EQ(after.size(), before.size());
  int identical = 0;
  for (const auto &kv : before) {
    ASSERT_TRUE(after.count(kv.first)) << kv.first.first << "-" << kv.first.second;
    const std::vector<double> &row = after.at(kv.first);
    for (int k = 0; k < 3; k++)
      EXPECT_NEAR(row[k], kv.second[k], 1e-10 * std::fabs(kv.second[k]))
          << "column " << k + 3 << " of contact " << kv.first.first << "-" << kv.first.second;
    EXPECT_NEAR(row[3], kv.second[3], 1e-10) << "factor of contact " << kv.first.first << "-" << kv.first.second;
    identical += (row == kv.second);
  }
  // the contacts away from the boundaries are the same to the last bit
  EXPECT_GT(identical, static_cast<int>(before.size()) / 2);
  L.command("run 40");
  EXPECT_GT(ac->size_local_rows, 10);
  // the counters go on from the writer's: the new solver analyses and
  // factorises afresh, and its counts add to the restored ones
  EXPECT_GE(ac->compute_vector(11), factorisations + 1.0) << "counters continue across a restart";
  L.command("undump rows");
  MPI_Barrier(MPI_COMM_WORLD);
  if (AcousticTest::mpi_rank() == 0) {
    // the dump local at the restart step holds every contact
    const std::string dump = file_text("fix_acoustic_local.dump");
    const std::string at_restart =
        "ITEM: TIMESTEP\n" + std::to_string(restart_step) + "\nITEM: NUMBER OF ENTRIES\n";
    const std::size_t rows = dump.find(at_restart);
    ASSERT_NE(rows, std::string::npos) << dump.substr(0, 300);
    EXPECT_EQ(std::stoul(dump.substr(rows + at_restart.size())), before.size());
    std::remove(file.c_str());
    std::remove("fix_acoustic_local.dump");
  }
}

TEST(FixParallel, RestartBetweenUpdatesLeavesTheLocalOutputEmpty)
{
  // restarted at a step that is not a multiple of N: the positions are no
  // longer those of the last update, so no rows until the next update
  const std::string file = "fix_acoustic_local_between.restart";
  const std::string fix = "fix ac all acoustic/mindlin 40 frequency 3.0 amplitude 5e-4 source base\n";
  {
    LammpsInstance L;
    L.commands(layer_deck("off"));
    L.commands(fix + "run 90\n");
    L.command("write_restart " + file);
  }
  LammpsInstance L;
  L.command("read_restart " + file);
  L.commands("comm_modify vel yes\nfix integrate grains nve/sphere\nfix plane all enforce2d\n"
             "neighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\nthermo 0\n" + fix + "run 0\n");
  EXPECT_TRUE(local_rows(L, "ac").empty());
  L.command("run 40");
  EXPECT_GT(local_rows(L, "ac").size(), 10u);
  MPI_Barrier(MPI_COMM_WORLD);
  if (AcousticTest::mpi_rank() == 0) std::remove(file.c_str());
}

// ---------------------------------------------------------------------------
// 3b. a run split by write_restart/read_restart continues like the uninterrupted one

// the settled layer under gravity tilted by 0.3 rad, with vibration strong
// enough that the friction factors decide which contacts slide.  The contacts
// have no dashpots: with velocity-dependent forces the setup of a restarted
// run computes the forces of its first step from the full-step velocities
// instead of the half-step ones, and the runs differ by 1e-8 in v after a
// few steps whatever the fix does (measured: max |dv| 1.4e-8 after 5 steps
// with dashpots, 3e-13 without, frequency 0)
const char kTiltedFixes[] =
    "pair_coeff * * hertz/material 1e5 0.0 0.3 tangential mindlin/acoustic NULL 0.0 0.5\n"
    "fix grav grains gravity 1.0 vector 0.3 -1 0\n"
    "fix ac all acoustic/mindlin 40 frequency 3.0 amplitude 2e-3 source base solver lu\n";

std::vector<double> positions_after_split_run(int split, int total)
{
  const std::string file = "fix_acoustic_split.restart";
  std::vector<double> x;
  {
    LammpsInstance L;
    L.commands(layer_deck());
    L.command("reset_timestep 0");
    L.commands(kTiltedFixes);
    L.command("run " + std::to_string(split > 0 ? split : total));
    if (split <= 0) return L.gather("x", 3);
    L.command("write_restart " + file);
  }
  LammpsInstance L;
  L.command("read_restart " + file);
  L.commands("comm_modify vel yes\nfix integrate grains nve/sphere\nfix plane all enforce2d\n"
             "neighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\nthermo 0\n");
  L.commands(kTiltedFixes);
  L.command("run " + std::to_string(total - split));
  x = L.gather("x", 3);
  MPI_Barrier(MPI_COMM_WORLD);
  if (AcousticTest::mpi_rank() == 0) std::remove(file.c_str());
  return x;
}

double uninterrupted_box_length()
{
  LammpsInstance L;
  L.commands("units lj\ndimension 2\nboundary p fm p\nlattice hex 1.1547005383792517\n"
             "region box block 0 16 0 5 -0.5 0.5\ncreate_box 2 box\n");
  return L.lmp->domain->xprd;
}

class FixRestart : public ::testing::TestWithParam<int> {};

TEST_P(FixRestart, SplitRunContinuesTheUninterruptedOne)
{
  const int total = 1000;
  static std::vector<double> uninterrupted;    // the same for every split
  if (uninterrupted.empty()) uninterrupted = positions_after_split_run(0, total);
  const std::vector<double> split = positions_after_split_run(GetParam(), total);
  ASSERT_EQ(split.size(), uninterrupted.size());
  // x is periodic: compare the nearest images
  const double period = uninterrupted_box_length();
  double largest = 0.0;
  for (std::size_t m = 0; m < split.size(); m++) {
    double d = split[m] - uninterrupted[m];
    if (m % 3 == 0) d = std::remainder(d, period);
    largest = std::max(largest, std::fabs(d));
  }
  if (AcousticTest::mpi_rank() == 0)
    std::printf("[ split at %d ] max |dx| = %.3g after %d steps\n", GetParam(), largest, total);
  EXPECT_LE(largest, 1e-10);
}

// split at a multiple of N = 40 and between two multiples
INSTANTIATE_TEST_SUITE_P(Steps, FixRestart, ::testing::Values(400, 430));

TEST(FixRestart, TheTiltedLayerMoves)
{
  // the comparison above means something only if the factors matter: the
  // layer slides further with the vibration than without it
  double travel[2];
  const char *amplitudes[2] = {"0", "2e-3"};
  for (int k = 0; k < 2; k++) {
    LammpsInstance L;
    L.commands(layer_deck());
    L.commands(std::string("pair_coeff * * hertz/material 1e5 0.0 0.3 tangential "
                           "mindlin/acoustic NULL 0.0 0.5\n"
                           "compute dsp grains displace/atom\n"
                           "compute travel grains reduce ave c_dsp[1]\n"
                           "thermo_style custom step c_travel\n"
                           "fix grav grains gravity 1.0 vector 0.3 -1 0\n"
                           "fix ac all acoustic/mindlin 40 frequency 3.0 amplitude ") +
               amplitudes[k] + " source base solver lu\nrun 1000\n");
    travel[k] = L.lmp->modify->get_compute_by_id("travel")->compute_scalar();
  }
  EXPECT_GT(travel[1], 2.0 * travel[0] + 1e-3) << "travel " << travel[0] << " / " << travel[1];
}

// ---------------------------------------------------------------------------
// 3c. unfix gives full friction back; one fix per contact

TEST(FixLifetime, UnfixRestoresFullFriction)
{
  LammpsInstance L;
  L.commands(layer_deck());
  L.command("fix ac all acoustic/mindlin 20 frequency 3.0 amplitude 2e-3 source base");
  L.command("run 50");
  int reduced = 0;
  for (const auto &kv : AcousticTest::friction_factors(L)) reduced += (kv.second < 1.0);
  ASSERT_GT(reduced, 10);
  L.command("unfix ac");
  L.command("run 0");
  for (const auto &kv : AcousticTest::friction_factors(L))
    EXPECT_EQ(kv.second, 1.0) << kv.first.first << "-" << kv.first.second;
  L.command("run 20");    // and they stay there
  for (const auto &kv : AcousticTest::friction_factors(L)) EXPECT_EQ(kv.second, 1.0);
}

TEST(FixLifetime, UnfixAfterAtomsMovedWarns)
{
  // atoms that changed processors since the last run: the neighbor lists no
  // longer match them, the factors cannot be reset, and the user is told
  if (AcousticTest::mpi_size() < 2) GTEST_SKIP() << "needs atoms that change processors";
  LammpsInstance L;
  L.commands(layer_deck());
  L.command("fix ac all acoustic/mindlin 20 frequency 3.0 amplitude 2e-3 source base");
  L.command("run 50");
  L.command("displace_atoms all move 9.2 0 0 units box");
  L.command("log fix_acoustic_unfix.log");
  L.command("unfix ac");
  L.command("log none");
  if (AcousticTest::mpi_rank() == 0) {
    const std::string log = file_text("fix_acoustic_unfix.log");
    EXPECT_NE(log.find("WARNING: fix acoustic/mindlin ac: the friction factors it set stay"),
              std::string::npos)
        << log;
    EXPECT_NE(log.find("Use 'run 0' before 'unfix ac'"), std::string::npos) << log;
    std::remove("fix_acoustic_unfix.log");
  }
}

TEST(FixLifetime, SecondFixOnTheSameContactsIsRefused)
{
  LammpsInstance L;
  L.commands(layer_deck());
  L.commands("fix ac all acoustic/mindlin 20 frequency 3.0 amplitude 2e-3 source base\n"
             "fix ac2 grains acoustic/mindlin 20 frequency 5.0 amplitude 2e-3 source base\n");
  try {
    L.command("run 0");
    FAIL() << "two fixes on the same contacts accepted";
  } catch (LAMMPS_NS::LAMMPSException &e) {
    EXPECT_NE(std::string(e.what()).find("would overwrite each other's friction factors"),
              std::string::npos)
        << e.what();
  }
}

TEST(FixLifetime, SourceGroupPartlyOutsideTheFixGroupIsRefused)
{
  LammpsInstance L;
  L.commands(layer_deck());
  L.commands("group halfbase id <= 8\ngroup sheet union grains halfbase\n"
             "fix ac sheet acoustic/mindlin 20 frequency 3.0 amplitude 2e-3 source base\n");
  try {
    L.command("run 0");
    FAIL() << "a source group partly outside the fix group accepted";
  } catch (LAMMPS_NS::LAMMPSException &e) {
    EXPECT_NE(std::string(e.what()).find("atoms of the source group base are not in the fix group "
                                         "sheet"),
              std::string::npos)
        << e.what();
  }
}

// ---------------------------------------------------------------------------
// 4. a singular solve warns and keeps the factors

// one free grain of mass 1 on a base grain, nothing integrated: with model
// normal its vertical DOF has K - omega^2 M = k - omega^2 = 0 exactly at
// f = sqrt(k)/(2 pi)
std::string resonance_deck(double k)
{
  return "units lj\ndimension 2\natom_style sphere\nboundary p p p\ncomm_modify vel yes\n"
         "region box block -3 3 -3 3 -0.5 0.5\ncreate_box 2 box\n"
         "create_atoms 2 single 0 0 0\ncreate_atoms 1 single 0 0.99 0\n"
         "set group all diameter 1.0\nset group all mass 1.0\n"
         "group base type 2\npair_style granular\n"
         "pair_coeff * * hooke " + fmt_double(k) + " 0 tangential linear_history/acoustic " +
         fmt_double(k) + " 0 0.5\nfix plane all enforce2d\nthermo 0\n";
}

TEST(FixSolverFailure, ResonanceWarnsAndKeepsFactors)
{
  const double f = 5.0, omega = 2.0 * M_PI * f, k = omega * omega;
  LammpsInstance L;
  L.commands(resonance_deck(0.5 * k));
  L.commands("fix ac all acoustic/mindlin 10 frequency " + fmt_double(f) +
             " amplitude 1e-3 source base direction 1 1 0\nrun 0\n");
  std::map<ContactKey, double> first = AcousticTest::friction_factors(L);
  ASSERT_EQ(first.size(), 1u);
  const double s0 = first.begin()->second;
  ASSERT_LT(s0, 1.0);

  // the same contact made resonant: the update of step 10 fails
  L.command("log fix_acoustic_warning.log");
  L.command("pair_coeff * * hooke " + fmt_double(k) + " 0 tangential linear_history/acoustic " +
            fmt_double(k) + " 0 0.5");
  L.command("run 10");
  L.command("log none");
  std::map<ContactKey, double> second = AcousticTest::friction_factors(L);
  ASSERT_EQ(second.size(), 1u);
  EXPECT_EQ(second.begin()->second, s0) << "the failed solve must keep the previous factor";
  LAMMPS_NS::Fix *fix = find_fix(L, "ac");
  EXPECT_EQ(fix->compute_vector(1), s0) << "statistics of the factors in the history";
  const std::string log = file_text("fix_acoustic_warning.log");
  EXPECT_NE(log.find("WARNING: fix acoustic/mindlin: the Helmholtz solve at f = 5 failed"),
            std::string::npos)
      << log;
  std::remove("fix_acoustic_warning.log");
}

TEST(FixSolverFailure, StatisticsAfterAFailedFirstSolve)
{
  // the first solve is singular: the one contact keeps factor 1, and the
  // statistics say so
  const double f = 5.0, omega = 2.0 * M_PI * f, k = omega * omega;
  LammpsInstance L;
  L.commands(resonance_deck(k));
  L.commands("fix ac all acoustic/mindlin 10 frequency " + fmt_double(f) +
             " amplitude 1e-3 source base direction 1 1 0\nrun 0\n");
  LAMMPS_NS::Fix *fix = find_fix(L, "ac");
  EXPECT_EQ(fix->compute_vector(0), 1.0) << "contacts in the network";
  EXPECT_EQ(fix->compute_vector(1), 1.0) << "mean factor";
  EXPECT_EQ(fix->compute_vector(2), 1.0) << "smallest factor";
  EXPECT_EQ(fix->compute_vector(3), 0.0) << "fraction below 0.5";
  for (const auto &kv : AcousticTest::friction_factors(L)) EXPECT_EQ(kv.second, 1.0);
}

// ---------------------------------------------------------------------------
// 5. errors

struct BadFix {
  const char *name;
  const char *command;
  const char *message;
};

void PrintTo(const BadFix &b, std::ostream *os) { *os << b.name; }

class FixErrors : public ::testing::TestWithParam<BadFix> {};

TEST_P(FixErrors, ClearError)
{
  const BadFix bad = GetParam();
  LammpsInstance L;
  L.commands("units lj\natom_style sphere\ncomm_modify vel yes\n"
             "region box block 0 4 0 4 0 4\ncreate_box 2 box\n"
             "create_atoms 2 single 1 1 1\ncreate_atoms 1 single 1 1 1.9\n"
             "group base type 2\ngroup empty type 3\ngroup grains type 1\n"
             "pair_style granular\n"
             "pair_coeff * * hooke 1000 0.5 tangential linear_history/acoustic 800 0.5 0.5\n");
  try {
    L.commands(bad.command);
    FAIL() << "no error for: " << bad.command;
  } catch (LAMMPS_NS::LAMMPSException &e) {
    EXPECT_NE(std::string(e.what()).find(bad.message), std::string::npos) << "message was: " << e.what();
  }
}

const BadFix kBadFixes[] = {
    {"too_few_args", "fix ac all acoustic/mindlin 10 frequency 5", "expected fix ID group-ID acoustic/mindlin N"},
    {"bad_every", "fix ac all acoustic/mindlin 0 frequency 5 amplitude 1e-3 source base", "N must be > 0"},
    {"misspelt_frequency", "fix ac all acoustic/mindlin 10 freq 5 amplitude 1e-3 source base",
     "expected 'frequency' as argument 5, got 'freq'"},
    {"negative_frequency", "fix ac all acoustic/mindlin 10 frequency -5 amplitude 1e-3 source base",
     "frequency must be >= 0"},
    {"negative_amplitude", "fix ac all acoustic/mindlin 10 frequency 5 amplitude -1e-3 source base",
     "amplitude must be >= 0"},
    {"missing_source_group", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source floor",
     "source group floor does not exist"},
    {"empty_source", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source empty\nrun 0",
     "source group empty has no atom in the fix group"},
    {"source_outside_group", "fix ac grains acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base\nrun 0",
     "the source grains must belong to the fix group"},
    {"unknown_keyword", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base loud yes",
     "Unknown fix acoustic/mindlin keyword: loud"},
    {"zero_direction", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base direction 0 0 0",
     "direction must not be the zero vector"},
    {"oblique_normal_mode",
     "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base direction 1 0 1 mode normal",
     "mode normal prescribes one Cartesian component"},
    {"bad_mode", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base mode some",
     "mode must be 'all' or 'normal'"},
    {"bad_stiffness", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base stiffness soft",
     "stiffness must be 'pair' or 'hertz E nu'"},
    {"hertz_bad_modulus",
     "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base stiffness hertz -1 0.3",
     "Young's modulus E > 0"},
    {"hertz_missing_values", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base stiffness hertz 1e9",
     "Illegal fix acoustic/mindlin stiffness command: missing argument(s)"},
    {"bad_kappa_scale",
     "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base kappa_scale 0",
     "kappa_scale must be in [1e-100, 1e100]"},
    {"negative_ratio", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base ratio -1",
     "ratio k_t/k_n must be >= 0"},
    {"negative_cmu", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base cmu -1",
     "cmu must be >= 0"},
    {"bad_mu_min", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base mu_min 1.5",
     "mu_min must be in [0, 1]"},
    {"bad_model", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base model rigid",
     "rigid"},
    {"negative_damping", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base damping -0.1",
     "damping ratio must be >= 0"},
    {"unknown_solver", "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base solver magic",
     "magic"},
    {"ldlt_with_damping",
     "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base damping 0.1 solver ldlt",
     "solver ldlt handles undamped"},
    {"tangential_without_factor",
     "pair_style granular\npair_coeff * * hooke 1000 0.5 tangential linear_history 800 0.5 0.5\n"
     "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base\nrun 0",
     "use tangential linear_history/acoustic in pair_coeff"},
    {"not_pair_granular",
     "pair_style gran/hooke/history 1000 NULL 0.5 NULL 0.5 1\npair_coeff * *\n"
     "fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base\nrun 0",
     "requires pair_style granular with a tangential <model>/acoustic sub-model"},
};

INSTANTIATE_TEST_SUITE_P(BadInput, FixErrors, ::testing::ValuesIn(kBadFixes),
                         [](const ::testing::TestParamInfo<BadFix> &info) {
                           return std::string(info.param.name);
                         });

TEST(FixErrorsModels, NormalModelWithHistory)
{
  LammpsInstance L;
  L.commands("units lj\natom_style sphere\ncomm_modify vel yes\n"
             "region box block 0 4 0 4 0 4\ncreate_box 2 box\n"
             "create_atoms 2 single 1 1 1\ncreate_atoms 1 single 1 1 1.9\ngroup base type 2\n"
             "pair_style granular\n");
  // the damping that mdr requires changed after LAMMPS 4 Feb 2025
  const std::string damping = (L.lmp->num_ver < 20260000) ? "none" : "mdr 1";
  L.command("pair_coeff * * mdr 1e4 0.3 100 0 0.5 0.5 damping " + damping +
            " tangential linear_history/acoustic 800 0.5 0.5");
  try {
    L.commands("fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base\nrun 0");
    FAIL() << "mdr accepted";
  } catch (LAMMPS_NS::LAMMPSException &e) {
    EXPECT_NE(std::string(e.what()).find("normal model mdr, whose force depends on the loading "
                                         "history and cannot be linearised"),
              std::string::npos)
        << e.what();
  }
}

TEST(FixErrors2D, DirectionOutOfPlane)
{
  LammpsInstance L;
  L.commands("units lj\ndimension 2\natom_style sphere\ncomm_modify vel yes\n"
             "region box block 0 4 0 4 -0.5 0.5\ncreate_box 2 box\ngroup base type 2\n"
             "pair_style granular\n"
             "pair_coeff * * hooke 1000 0.5 tangential linear_history/acoustic 800 0.5 0.5\n");
  try {
    L.command("fix ac all acoustic/mindlin 10 frequency 5 amplitude 1e-3 source base direction 0 1 1");
    FAIL() << "out-of-plane direction accepted in 2D";
  } catch (LAMMPS_NS::LAMMPSException &e) {
    EXPECT_NE(std::string(e.what()).find("in 2D the direction must lie in the xy plane"),
              std::string::npos)
        << e.what();
  }
}

}    // namespace
