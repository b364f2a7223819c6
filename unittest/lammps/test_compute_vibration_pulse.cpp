// Integration tests of the walls in the vibration network and of compute
// vibration/pulse: a chain of grains between two fix wall/gran planes against
// its closed modal solution, modes against integrate through LAMMPS, a wall
// against the equivalent grain of very large radius, the fix with a
// vibrating wall against a LAMMPS run whose wall really oscillates (lock-in),
// outputs, and errors.
#include "lammps_fixture.h"

#include "atom.h"
#include "compute.h"
#include "exceptions.h"
#include "fix.h"
#include "modify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using AcousticTest::LammpsInstance;

namespace {

std::string num(double v)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.17g", v);
  return buf;
}

// N grains of diameter 1 and mass m on the z axis (or x: axis 0) between two
// walls, every contact (hooke k) overlapping by 0.01; each wall is a fix
// wall/gran of its own
std::string chain_deck(int n, double m, double k, int axis = 2)
{
  const double step = 0.99;
  std::string range[3] = {"-2 2", "-2 2", "-2 2"};
  range[axis] = "-1 " + num(n * step + 2.0);
  std::string d = "units lj\natom_style sphere\natom_modify map array\nboundary f f f\n"
                  "comm_modify vel yes\nregion box block " + range[0] + " " + range[1] + " " +
                  range[2] + "\ncreate_box 1 box\n";
  for (int j = 0; j < n; j++) {
    std::string at[3] = {"0", "0", "0"};
    at[axis] = num(0.49 + j * step);
    d += "create_atoms 1 single " + at[0] + " " + at[1] + " " + at[2] + "\n";
  }
  const std::string model = "hooke " + num(k) + " 0 tangential linear_history/acoustic " +
                            num(0.5 * k) + " 0 0.5";
  const std::string plane = std::string(1, "xyz"[axis]) + "plane";
  d += "set group all diameter 1.0\nset group all mass " + num(m) + "\n"
       "pair_style granular\npair_coeff * * " + model + "\n"
       "fix bottom all wall/gran granular " + model + " " + plane + " 0.0 NULL\n"
       "fix top all wall/gran granular " + model + " " + plane + " NULL " +
       num(0.98 + (n - 1) * step) + "\nthermo 0\n";
  return d;
}

// the force on the upper wall after a unit delta pulse of the lower one
// (initial condition A), from the closed modal solution of the chain
double chain_signal(int n, double m, double k, double t)
{
  double force = 0.0;
  for (int mode = 1; mode <= n; ++mode) {
    const double phase = M_PI * mode / (n + 1);
    const double norm = std::sqrt(2.0 / (m * (n + 1)));
    const double omega = 2.0 * std::sqrt(k / m) * std::sin(0.5 * phase);
    force += k * norm * std::sin(phase * n) * k * norm * std::sin(phase) * std::sin(omega * t) / omega;
  }
  return force;
}

LAMMPS_NS::Compute *compute_of(LammpsInstance &L, const char *id)
{
  return L.lmp->modify->get_compute_by_id(id);
}

// the largest |F_sig| of the compute's array and its largest difference from
// the closed modal solution of the chain
struct ChainMatch {
  double peak = 0.0, largest = 0.0;
};

ChainMatch match_chain(LAMMPS_NS::Compute *pulse, int samples, int n, double m, double k)
{
  pulse->compute_array();
  ChainMatch out;
  for (int s = 0; s < samples; s++) {
    out.peak = std::max(out.peak, std::fabs(pulse->array[s][1]));
    out.largest = std::max(out.largest,
                           std::fabs(pulse->array[s][1] - chain_signal(n, m, k, pulse->array[s][0])));
  }
  return out;
}

// the largest |value| of per-atom amplitudes (signed: fix acoustic/mindlin's undamped U0 q)
double largest_magnitude(const std::vector<double> &values)
{
  double largest = 0.0;
  for (double v : values) largest = std::max(largest, std::fabs(v));
  return largest;
}

TEST(PulseThroughLammps, ChainBetweenWallsIsTheClosedModalSolution)
{
  const int n = 20;
  const double m = 1.3, k = 2000.0;
  LammpsInstance L;
  L.commands(chain_deck(n, m, k));
  L.commands("compute pulse all vibration/pulse source wall bottom detector wall top duration 3.0 "
             "samples 301 method modes\nthermo_style custom step c_pulse[3]\nrun 0\n");
  auto *pulse = compute_of(L, "pulse");
  const ChainMatch match = match_chain(pulse, 301, n, m, k);
  for (int s = 0; s < 301; s++) EXPECT_NEAR(pulse->array[s][0], 0.01 * s, 1e-12);
  ASSERT_GT(match.peak, 1.0);
  EXPECT_LE(match.largest, 1e-6 * match.peak) << "peak " << match.peak;
  pulse->compute_vector();
  EXPECT_EQ(pulse->vector[2], 3.0 * n) << "free DOFs: the translations of the grains";
}

// without a direction keyword, a wall source drives along the wall's normal
// (here x, in 3D, where the default for a group source is z)
TEST(WallsInTheNetwork, DefaultDirectionIsTheSourceWallNormal)
{
  const int n = 12;
  const double m = 1.0, k = 2000.0;
  LammpsInstance L;
  L.commands(chain_deck(n, m, k, 0));
  L.commands("compute pulse all vibration/pulse source wall bottom detector wall top duration 1.0 "
             "samples 101 method modes\nthermo_style custom step c_pulse[3]\nrun 0\n");
  const ChainMatch match = match_chain(compute_of(L, "pulse"), 101, n, m, k);
  ASSERT_GT(match.peak, 1.0) << "the pulse along x reaches the detector";
  EXPECT_LE(match.largest, 1e-6 * match.peak);

  // the fix: the default drive of a wall source is the one along its normal, bitwise
  std::vector<double> amplitudes[2];
  for (int given = 0; given < 2; given++) {
    LammpsInstance F;
    F.commands(chain_deck(n, m, k, 0));
    F.command(std::string("fix ac all acoustic/mindlin 100 frequency 2.0 amplitude 1e-3 source wall "
                          "bottom") + (given ? " direction 1 0 0" : "") + "\nrun 0");
    LAMMPS_NS::Fix *fix = F.lmp->modify->get_fix_by_id("ac");
    std::vector<double> mine;
    for (int i = 0; i < F.lmp->atom->nlocal; i++) {
      mine.push_back(F.lmp->atom->tag[i]);
      mine.push_back(fix->array_atom[i][0]);
    }
    const std::vector<double> all = AcousticTest::allgather(F, mine);
    amplitudes[given].assign(n + 1, 0.0);
    for (std::size_t j = 0; j < all.size(); j += 2) amplitudes[given][static_cast<int>(all[j])] = all[j + 1];
  }
  EXPECT_GT(largest_magnitude(amplitudes[0]), 1e-3);
  for (int t = 1; t <= n; t++) EXPECT_EQ(amplitudes[0][t], amplitudes[1][t]) << "atom " << t;
}

// the chain with one wall as the plane region of a fix wall/gran/region
// (the paper-003 piston: a region moved by a variable, here at rest)
std::string chain_with_region_wall(int n, double m, double k, const std::string &which)
{
  std::string d = chain_deck(n, m, k);
  const std::string model = "hooke " + num(k) + " 0 tangential linear_history/acoustic " +
                            num(0.5 * k) + " 0 0.5";
  const std::size_t at = d.find("fix " + which + " ");
  const std::size_t end = d.find('\n', at);
  const bool top = which == "top";
  const std::string where = top ? num(0.98 + (n - 1) * 0.99) : "0.0";
  d.replace(at, end - at,
            "variable still equal 0.0*step\n"
            "region " + which + "_plane plane 0 0 " + where + " 0 0 " + (top ? "-1" : "1") +
            " move NULL NULL v_still units box\n"
            "fix " + which + " all wall/gran/region granular " + model + " region " + which +
            "_plane");
  return d;
}

TEST(WallsInTheNetwork, RegionWallIsAWallOfTheNetwork)
{
  const int n = 12;
  const double m = 1.0, k = 2000.0;
  // detector: a moving plane region
  {
    LammpsInstance L;
    L.commands(chain_with_region_wall(n, m, k, "top"));
    L.commands("compute pulse all vibration/pulse source wall bottom detector wall top duration 3.0 "
               "samples 301 method modes\nthermo_style custom step c_pulse[3]\nrun 0\n");
    const ChainMatch match = match_chain(compute_of(L, "pulse"), 301, n, m, k);
    ASSERT_GT(match.peak, 1.0) << "the pulse reaches the region wall";
    EXPECT_LE(match.largest, 1e-6 * match.peak);
  }
  // source: a region has no single normal, the direction is given
  {
    LammpsInstance L;
    L.commands(chain_with_region_wall(n, m, k, "bottom"));
    L.commands("compute pulse all vibration/pulse source wall bottom detector wall top duration 3.0 "
               "samples 301 method modes direction 0 0 1\n"
               "thermo_style custom step c_pulse[3]\nrun 0\n");
    const ChainMatch match = match_chain(compute_of(L, "pulse"), 301, n, m, k);
    ASSERT_GT(match.peak, 1.0);
    EXPECT_LE(match.largest, 1e-6 * match.peak);
  }
  {
    LammpsInstance L;
    L.commands(chain_with_region_wall(n, m, k, "bottom"));
    try {
      L.commands("fix ac all acoustic/mindlin 100 frequency 2.0 amplitude 1e-3 source wall bottom\n"
                 "run 0");
      ADD_FAILURE() << "no error for a region source without direction";
    } catch (LAMMPS_NS::LAMMPSException &e) {
      EXPECT_NE(std::string(e.what()).find("give the direction of its drive"), std::string::npos)
          << e.what();
    }
  }
  // the fix: a region source gives the factors of the same plane of fix wall/gran
  std::vector<double> amplitudes[2];
  for (int region = 0; region < 2; region++) {
    LammpsInstance F;
    F.commands(region ? chain_with_region_wall(n, m, k, "bottom") : chain_deck(n, m, k));
    F.command("fix ac all acoustic/mindlin 100 frequency 2.0 amplitude 1e-3 source wall bottom "
              "direction 0 0 1\nrun 0");
    LAMMPS_NS::Fix *fix = F.lmp->modify->get_fix_by_id("ac");
    std::vector<double> mine;
    for (int i = 0; i < F.lmp->atom->nlocal; i++) {
      mine.push_back(F.lmp->atom->tag[i]);
      mine.push_back(fix->array_atom[i][2]);    // U0 q_z
    }
    const std::vector<double> all = AcousticTest::allgather(F, mine);
    amplitudes[region].assign(n + 1, 0.0);
    for (std::size_t j = 0; j < all.size(); j += 2)
      amplitudes[region][static_cast<int>(all[j])] = all[j + 1];
  }
  EXPECT_GT(largest_magnitude(amplitudes[0]), 1e-3);
  for (int t = 1; t <= n; t++)
    EXPECT_NEAR(amplitudes[0][t], amplitudes[1][t], 1e-12 * std::fabs(amplitudes[0][t])) << "atom " << t;

  // the modes: a region wall clamps the chain as the plane does; with
  // region_walls no it is a free end (a lower first mode)
  std::vector<double> frequencies[3];
  const char *decks[3] = {"plane", "region", "region_walls no"};
  for (int c = 0; c < 3; c++) {
    LammpsInstance M;
    M.commands(c == 0 ? chain_deck(n, m, k) : chain_with_region_wall(n, m, k, "top"));
    M.commands(std::string("compute modes all vibration/modes") + (c == 2 ? " region_walls no" : "") +
               "\nthermo_style custom step c_modes[1]\nrun 0\n");
    auto *modes = compute_of(M, "modes");
    modes->compute_vector();
    frequencies[c].assign(modes->vector, modes->vector + modes->size_vector);
  }
  ASSERT_EQ(frequencies[0].size(), frequencies[1].size());
  for (std::size_t j = 0; j < frequencies[0].size(); j++)
    EXPECT_NEAR(frequencies[0][j], frequencies[1][j], 1e-9 * frequencies[0].back()) << decks[1] << " mode " << j;
  double lowest[3];
  for (int c = 0; c < 3; c++) {
    lowest[c] = 0.0;
    for (double f : frequencies[c])
      if (f > 1e-6 * frequencies[c].back()) {
        lowest[c] = f;
        break;
      }
  }
  EXPECT_LT(lowest[2], 0.7 * lowest[0]) << "a free end: the lowest mode of the chain drops";
}

TEST(PulseThroughLammps, IntegrateAgreesWithModes)
{
  LammpsInstance L;
  L.commands(chain_deck(20, 1.0, 2000.0));
  // one way across the chain and back (c = sqrt(k/m) grains per time unit)
  L.commands("compute modes all vibration/pulse source wall bottom detector wall top duration 1.0 "
             "samples 101 method modes\n"
             "compute verlet all vibration/pulse source wall bottom detector wall top duration 1.0 "
             "samples 101 method integrate\n"
             "thermo_style custom step c_modes[1] c_verlet[1]\nrun 0\n");
  auto *modes = compute_of(L, "modes");
  auto *verlet = compute_of(L, "verlet");
  modes->compute_array();
  verlet->compute_array();
  verlet->compute_vector();
  double peak = 0.0, largest = 0.0;
  for (int s = 0; s < 101; s++) {
    peak = std::max(peak, std::fabs(modes->array[s][1]));
    largest = std::max(largest, std::fabs(modes->array[s][1] - verlet->array[s][1]));
  }
  EXPECT_LE(largest, 1e-3 * peak);
  EXPECT_GT(verlet->vector[0], 0.0) << "the automatic time step";
  EXPECT_GT(verlet->vector[1], 100.0) << "steps";
}

TEST(PulseThroughLammps, DetectorGroupAndSnapshot)
{
  // the last grain clamped as the detector instead of the upper wall: the
  // force it receives from grain N-1 is the same signal for a chain one shorter
  const int n = 12;
  const double k = 2000.0;
  LammpsInstance L;
  L.commands(chain_deck(n, 1.0, k));
  L.commands("group last id " + std::to_string(n) + "\n"
             "compute pulse all vibration/pulse source wall bottom detector last duration 2.0 "
             "samples 201 method modes snapshot 1.0\n"
             "dump shot all custom 1 pulse_snapshot.dump id c_pulse[3]\nrun 0\nundump shot\n");
  auto *pulse = compute_of(L, "pulse");
  pulse->compute_array();
  double peak = 0.0, largest = 0.0;
  for (int s = 0; s < 201; s++) {
    peak = std::max(peak, std::fabs(pulse->array[s][1]));
    largest = std::max(largest, std::fabs(pulse->array[s][1] - chain_signal(n - 1, 1.0, k, pulse->array[s][0])));
  }
  EXPECT_LE(largest, 1e-6 * peak);
  // the snapshot of grain N-1 at t = 1: F_sig(1) = k u_{N-1}(1)
  pulse->compute_peratom();
  const std::vector<double> uz = [&] {
    std::vector<double> mine;
    for (int i = 0; i < L.lmp->atom->nlocal; i++)
      if (L.lmp->atom->tag[i] == n - 1) mine.push_back(pulse->array_atom[i][2]);
    return AcousticTest::allgather(L, mine);
  }();
  ASSERT_EQ(uz.size(), 1u);
  EXPECT_NEAR(k * uz[0], pulse->array[100][1], 1e-9 * peak);
  MPI_Barrier(MPI_COMM_WORLD);
  if (AcousticTest::mpi_rank() == 0) std::remove("pulse_snapshot.dump");
}

// ---------------------------------------------------------------------------
// a wall is the limit of a grain of very large radius

// a 2D hexagonal layer of 4 rows of 8 grains (nearest neighbours 1 apart,
// diameter 1.002) on a flat base: a fix wall/gran plane, or one frozen grain
// of radius R = 1e5 below the layer; every contact overlaps by 0.002.  Free
// ends in x: a periodic box would hold the large grain's images
std::string layer_on_base(bool wall)
{
  const double R = 1e5, plane = 0.8660254037844386 - 0.501 + 0.002;
  std::string d = "units lj\ndimension 2\natom_style sphere\nboundary f f p\ncomm_modify vel yes\n"
                  "neighbor 0.3 nsq\n"
                  "lattice hex 1.1547005383792517\n"
                  "region box block -0.5 8 " + num(plane - R - 2.0) + " 6 -0.5 0.5 units box\n"
                  "create_box 2 box\n"
                  "region layer block -0.1 7.9 0.5 3.6 INF INF units box\n"
                  "create_atoms 1 region layer\n"
                  "set group all diameter 1.002\nset group all density 1.0\n"
                  "group grains type 1\n";
  const std::string model = "hooke 1e4 0 tangential linear_history/acoustic 8e3 0 0.5";
  if (wall) {
    d += "pair_style granular\npair_coeff * * " + model + "\n"
         "fix base all wall/gran granular " + model + " yplane " + num(plane) + " NULL\n";
  } else {
    d += "create_atoms 2 single 3.75 " + num(plane - R) + " 0 units box\n"
         "set type 2 diameter " + num(2 * R) + "\nset type 2 density 1.0\ngroup base type 2\n"
         "pair_style granular\npair_coeff * * " + model + "\n";
  }
  d += "fix plane all enforce2d\nthermo 0\n";
  return d;
}

TEST(WallsInTheNetwork, WallIsTheLimitOfALargeGrain)
{
  std::vector<double> amplitudes[2];
  for (int k = 0; k < 2; k++) {
    const bool wall = (k == 0);
    LammpsInstance L;
    L.commands(layer_on_base(wall));
    L.command(std::string("fix ac all acoustic/mindlin 100 frequency 2.0 amplitude 1e-3 ") +
              (wall ? "source wall base" : "source base") + " direction 0 1 0\nrun 0");
    LAMMPS_NS::Fix *fix = L.lmp->modify->get_fix_by_id("ac");
    ASSERT_GT(fix->compute_vector(0), 40.0) << "contacts in the network";
    std::vector<double> mine;
    for (int i = 0; i < L.lmp->atom->nlocal; i++)
      if (L.lmp->atom->type[i] == 1) {
        mine.push_back(L.lmp->atom->tag[i]);
        mine.push_back(fix->array_atom[i][0]);
        mine.push_back(fix->array_atom[i][1]);
      }
    const std::vector<double> all = AcousticTest::allgather(L, mine);
    std::vector<double> by_tag(2 * 100, 0.0);
    for (std::size_t m = 0; m < all.size(); m += 3) {
      by_tag[2 * static_cast<int>(all[m])] = all[m + 1];
      by_tag[2 * static_cast<int>(all[m]) + 1] = all[m + 2];
    }
    amplitudes[k] = by_tag;
  }
  double largest = 0.0, difference = 0.0;
  for (std::size_t m = 0; m < amplitudes[0].size(); m++) {
    largest = std::max(largest, std::fabs(amplitudes[0][m]));
    difference = std::max(difference, std::fabs(amplitudes[0][m] - amplitudes[1][m]));
  }
  if (AcousticTest::mpi_rank() == 0)
    std::printf("[ wall / grain of radius 1e5 ] max amplitude %.4g, max difference %.3g of it\n",
                largest, difference / largest);
  ASSERT_GT(largest, 1.05e-3) << "a response that differs from the rigid motion";
  EXPECT_LE(difference, 1e-4 * largest);
}

TEST(WallsInTheNetwork, ClampedWallIsAClampedLargeGrainForTheModes)
{
  std::vector<double> frequencies[2];
  for (int k = 0; k < 2; k++) {
    LammpsInstance L;
    L.commands(layer_on_base(k == 0));
    L.commands(k == 0 ? "compute m all vibration/modes\n" : "compute m all vibration/modes fixed base\n");
    L.commands("thermo_style custom step c_m\nrun 0\n");
    auto *modes = compute_of(L, "m");
    modes->compute_vector();
    frequencies[k].assign(modes->vector, modes->vector + modes->size_vector);
  }
  ASSERT_EQ(frequencies[0].size(), frequencies[1].size());
  ASSERT_GT(frequencies[0].size(), 50u);
  double largest = 0.0;
  for (std::size_t m = 0; m < frequencies[0].size(); m++)
    largest = std::max(largest, std::fabs(frequencies[0][m] - frequencies[1][m]) /
                                    std::max(frequencies[0].back(), 1e-3));
  EXPECT_LE(largest, 1e-4);
}

// ---------------------------------------------------------------------------
// the fix with a vibrating wall against a LAMMPS run whose wall oscillates

std::string crystal_on_wall(double damp)
{
  return "units lj\ndimension 2\natom_style sphere\nboundary p fm p\ncomm_modify vel yes\n"
         "lattice hex 1.1547005383792517\n"
         "region box block 0 8 0 5 -0.5 0.5\ncreate_box 1 box\n"
         "region layer block INF INF 0.5 5.3 INF INF units box\ncreate_atoms 1 region layer\n"
         "set group all diameter 1.002\nset group all density 1.0\npair_style granular\n"
         "pair_coeff * * hooke 1e4 " + num(damp) + " damping mass_velocity tangential "
         "linear_history/acoustic 8e3 1.0 10.0\n"
         "fix plane all enforce2d\nfix integrate all nve/sphere\n"
         "fix grav all gravity 1.0 vector 0 -1 0\n"
         "timestep 1e-3\nneighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\nthermo 0\n";
}

// the plane under the lowest row (y = sqrt(3)/2), overlapping it by 0.001
std::string wall_fix(double damp, const std::string &motion)
{
  return "fix base all wall/gran granular hooke 1e4 " + num(damp) + " damping mass_velocity "
         "tangential linear_history/acoustic 8e3 1.0 10.0 yplane " +
         num(0.8660254037844386 - 0.501 + 0.001) + " NULL " + motion + "\n";
}

// lock-in sums <dx cos>, <dx sin>, <dy cos>, <dy sin> per atom ID over the
// last 20 of 60 periods of a wall wiggling with amplitude A (0: at rest)
std::vector<double> wall_lock_in(int steps_per_period, double dt, double A, int natoms)
{
  LammpsInstance L;
  L.commands(crystal_on_wall(150.0) + wall_fix(150.0, "") + "run 20000\nunfix base\n");
  const int nperiods = 60, nlock = 20, nsteps = nperiods * steps_per_period;
  const std::string motion = (A > 0.0) ? "wiggle y " + num(A) + " " + num(steps_per_period * dt) : "";
  L.commands("pair_coeff * * hooke 1e4 4 damping mass_velocity tangential "
             "linear_history/acoustic 8e3 1.0 10.0\nreset_timestep 0\ntimestep " + num(dt) + "\n" +
             wall_fix(4.0, motion) +
             "compute dsp all displace/atom\n"
             "variable ph equal 2.0*PI*step/" + std::to_string(steps_per_period) + "\n"
             "variable xc atom c_dsp[1]*cos(v_ph)\nvariable xs atom c_dsp[1]*sin(v_ph)\n"
             "variable yc atom c_dsp[2]*cos(v_ph)\nvariable ys atom c_dsp[2]*sin(v_ph)\n"
             "fix lock all ave/atom 1 " + std::to_string(nlock * steps_per_period) + " " +
             std::to_string(nsteps) + " v_xc v_xs v_yc v_ys\n");
  L.command("run " + std::to_string(nsteps));
  std::vector<double> sums(4 * (natoms + 1), 0.0);
  LAMMPS_NS::Fix *lock = L.lmp->modify->get_fix_by_id("lock");
  std::vector<double> mine;
  for (int i = 0; i < L.lmp->atom->nlocal; i++) {
    mine.push_back(L.lmp->atom->tag[i]);
    for (int k = 0; k < 4; k++) mine.push_back(lock->array_atom[i][k]);
  }
  const std::vector<double> all = AcousticTest::allgather(L, mine);
  for (std::size_t m = 0; m < all.size(); m += 5)
    for (int k = 0; k < 4; k++) sums[4 * static_cast<int>(all[m]) + k] = all[m + 1 + k];
  return sums;
}

TEST(WallsInTheNetwork, VibratingWallMatchesAnOscillatingWallByLockIn)
{
  LammpsInstance L;
  L.commands(crystal_on_wall(150.0) + wall_fix(150.0, "") + "run 20000\n");
  const int natoms = static_cast<int>(L.natoms());
  // below the lowest eigenfrequency: the compute gives it with the wall clamped.
  // Model full: with normal springs only the layer on its frictionless plane
  // has soft modes; the tangential springs hold it (mu = 10: no sliding in the DEM)
  L.commands("compute m all vibration/modes model full\nthermo_style custom step c_m\nrun 0\n");
  auto *modes = compute_of(L, "m");
  modes->compute_vector();
  const double fmin = modes->vector[static_cast<int>(modes->scalar)];
  const double f = 0.6 * fmin, period = 1.0 / f;
  const int steps_per_period = static_cast<int>(std::ceil(period / 1e-3));
  const double dt = period / steps_per_period;
  const double A = 1e-7;
  L.command("fix ac all acoustic/mindlin 1000000 frequency " + num(f) + " amplitude " + num(A) +
            " source wall base direction 0 1 0 model full\nrun 0");
  LAMMPS_NS::Fix *fix = L.lmp->modify->get_fix_by_id("ac");
  std::vector<double> predicted(2 * (natoms + 1), 0.0);
  {
    std::vector<double> mine;
    for (int i = 0; i < L.lmp->atom->nlocal; i++) {
      mine.push_back(L.lmp->atom->tag[i]);
      mine.push_back(fix->array_atom[i][0]);
      mine.push_back(fix->array_atom[i][1]);
    }
    const std::vector<double> all = AcousticTest::allgather(L, mine);
    for (std::size_t m = 0; m < all.size(); m += 3) {
      predicted[2 * static_cast<int>(all[m])] = all[m + 1];
      predicted[2 * static_cast<int>(all[m]) + 1] = all[m + 2];
    }
  }
  const std::vector<double> driven = wall_lock_in(steps_per_period, dt, A, natoms);
  const std::vector<double> still = wall_lock_in(steps_per_period, dt, 0.0, natoms);
  double max_pred = 0.0, max_err = 0.0;
  for (int t = 1; t <= natoms; t++)
    for (int k = 0; k < 2; k++) {
      // the part in phase with the wall: fix wall/gran's wiggle moves it by
      // A (1 - cos(phase)), whose oscillating part is -A cos(phase); the
      // undamped fix's amplitudes are signed displacements in phase with it
      const double c = driven[4 * t + 2 * k] - still[4 * t + 2 * k];
      const double measured = -2.0 * c;
      max_pred = std::max(max_pred, std::fabs(predicted[2 * t + k]));
      max_err = std::max(max_err, std::fabs(predicted[2 * t + k] - measured));
      if (getenv("ACOUSTIC_TEST_VERBOSE") && AcousticTest::mpi_rank() == 0)
        std::printf("atom %d %c: fix %.4g DEM %.4g\n", t, "xy"[k], predicted[2 * t + k] / A,
                    measured / A);
    }
  if (AcousticTest::mpi_rank() == 0)
    std::printf("[ wall ] f = %.4g (0.6 f_min), max |q| = %.4g A, max |DEM - fix| = %.3g of it\n", f,
                max_pred / A, max_err / max_pred);
  ASSERT_GT(max_pred, 1.05 * A) << "the response should differ from a rigid motion";
  EXPECT_LT(max_err, 0.02 * max_pred);
}

// ---------------------------------------------------------------------------
// errors

TEST(PulseErrors, ClearMessages)
{
  struct Bad {
    const char *command;
    const char *message;
  };
  const Bad bad[] = {
      {"compute p all vibration/pulse source wall bottom detector wall top",
       "give the time to follow the pulse with duration T"},
      {"compute p all vibration/pulse source wall floor detector wall top duration 1",
       "source wall floor is not a fix wall/gran"},
      {"compute p all vibration/pulse source nowhere detector wall top duration 1",
       "source group nowhere does not exist"},
      {"compute p all vibration/pulse detector wall top duration 1", "where 'source' belongs"},
      {"compute p all vibration/pulse source wall bottom detector wall top duration 1 initial kick",
       "unknown initial condition 'kick'"},
      {"compute p all vibration/pulse source wall bottom detector wall top duration 1 method fast",
       "unknown pulse method 'fast'"},
      {"compute p all vibration/pulse source wall bottom detector wall top duration 1 samples 1",
       "samples must be in [2, 1e7]"},
      {"compute p all vibration/pulse source wall bottom detector wall top duration 1 damping 0.1 "
       "method modes", "method modes needs an undamped network"},
      {"compute p all vibration/pulse source wall bottom detector wall top duration 1 snapshot 2",
       "the snapshot time 2 is after the duration 1"},
      {"compute p all vibration/pulse source wall bottom detector wall bottom duration 1\n"
       "thermo_style custom step c_p[1][2]\nrun 0", "the source and the detector are the same wall"},
      {"compute p all vibration/pulse source wall bottom detector wall top duration 1 loud 3",
       "Unknown compute vibration/pulse keyword: loud"},
  };
  for (const Bad &b : bad) {
    LammpsInstance L;
    L.commands(chain_deck(5, 1.0, 2000.0));
    try {
      L.commands(b.command);
      ADD_FAILURE() << "no error for: " << b.command;
    } catch (LAMMPS_NS::LAMMPSException &e) {
      EXPECT_NE(std::string(e.what()).find(b.message), std::string::npos)
          << "for " << b.command << ": " << e.what();
    }
  }
}

}    // namespace
