// Integration tests of the solvers of fix acoustic/mindlin that work in
// LAMMPS's domain decomposition: solver iterative (the Krylov solve) gives
// the friction factors of the direct solvers on damped 2D and 3D layers, on
// 1 and 2 ranks, the same bits twice, the warning and the kept factors of an
// undamped network driven inside its band, reuse of the last solution;
// solver mumps (distributed input) gives those of the gathered network.
#include "lammps_fixture.h"

#include "compute.h"
#include "fix.h"
#include "modify.h"

#include <gtest/gtest.h>

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

// entries of the fix's global vector (f_ID[k] is entry k-1)
constexpr int RESIDUAL = 4, NREUSES = 12, NITERATIONS = 14;

LAMMPS_NS::Fix *find_fix(LammpsInstance &L, const char *id)
{
  return L.lmp->modify->get_fix_by_id(id);
}

// a 2D layer of Hertz grains on a row of base grains, settled under gravity
const char kLayer2D[] = R"(
units lj
dimension 2
atom_style sphere
boundary p fm p
comm_modify vel yes
processors * 1 1
lattice hex 1.1547005383792517
region box block 0 16 0 6 -0.5 0.5
create_box 2 box
region base block INF INF -0.1 0.1 INF INF units box
region layer block INF INF 0.5 6.3 INF INF units box
create_atoms 2 region base
create_atoms 1 region layer
group base type 2
group grains type 1
variable dia atom 0.90+0.10*((id*7919)%1000)/1000
set group grains diameter v_dia
set group base diameter 1.0
set group all density 1.0
pair_style granular
pair_coeff * * hertz/material 1e5 0.5 0.3 tangential mindlin/acoustic NULL 1.0 0.5
fix integrate grains nve/sphere
fix plane all enforce2d
fix grav grains gravity 1.0 vector 0 -1 0
timestep 1e-3
neighbor 0.2 bin
neigh_modify delay 0 every 1 check yes
thermo 0
run 4000
)";

// a 3D layer: grains of diameters 0.9-1.1 (by atom ID) on a square base,
// settled from a loose fcc stack (nearest neighbours 1.41 apart) under gravity
const char kLayer3D[] = R"(
units lj
atom_style sphere
boundary p p fm
comm_modify vel yes
processors * * 1
region box block 0 8 0 8 -0.5 9 units box
create_box 2 box
lattice sc 1.0
region base block INF INF INF INF -0.1 0.1 units box
create_atoms 2 region base
lattice fcc 0.5
region layer block INF INF INF INF 0.9 8.5 units box
create_atoms 1 region layer
group base type 2
group grains type 1
variable dia atom 0.9+0.2*((id*7919)%1000)/1000
set group grains diameter v_dia
set group base diameter 1.0
set group all density 1.0
pair_style granular
pair_coeff * * hertz/material 1e5 0.5 0.3 tangential mindlin/acoustic NULL 1.0 0.5
fix integrate grains nve/sphere
fix grav grains gravity 1.0 vector 0 0 -1
fix drag grains viscous 0.5
timestep 1e-3
neighbor 0.2 bin
neigh_modify delay 0 every 1 check yes
thermo 0
run 6000
unfix drag
)";

std::string file_text(const std::string &name)
{
  std::ifstream in(name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Solved {
  std::map<ContactKey, double> factors;
  double residual = 0.0;
  double iterations = 0.0;
};

Solved solve(const std::string &deck, const std::string &fix)
{
  LammpsInstance L;
  L.commands(deck);
  L.command(fix);
  L.command("run 0");
  Solved s;
  s.factors = AcousticTest::friction_factors(L);
  LAMMPS_NS::Fix *f = find_fix(L, "ac");
  s.residual = f->compute_vector(RESIDUAL);
  s.iterations = f->compute_vector(NITERATIONS);
  return s;
}

double largest_difference(const std::map<ContactKey, double> &a, const std::map<ContactKey, double> &b,
                          int &reduced)
{
  EXPECT_EQ(a.size(), b.size());
  double largest = 0.0;
  reduced = 0;
  for (const auto &kv : a) {
    const auto it = b.find(kv.first);
    if (it == b.end()) {
      ADD_FAILURE() << "contact " << kv.first.first << "-" << kv.first.second << " missing";
      continue;
    }
    largest = std::max(largest, std::fabs(kv.second - it->second));
    reduced += (kv.second < 1.0);
  }
  return largest;
}

}    // namespace

struct Case {
  const char *name;
  const char *deck;
  const char *fix;    // keywords after the source
};

void PrintTo(const Case &c, std::ostream *os) { *os << c.name; }

class IterativeMatchesDirect : public ::testing::TestWithParam<Case> {};

// the factors of solver iterative equal those of the direct solver (MUMPS)
// to 1e-6 with the default tolerance (1e-9), for damping ratios 0.05 and 0.01, on
// the ranks of the test (1, or 2 under mpirun -np 2)
TEST_P(IterativeMatchesDirect, FactorsAgreeTo1e6)
{
  const Case &c = GetParam();
  const std::string fix = std::string("fix ac all acoustic/mindlin 100 frequency 2.0 amplitude 2e-3 source base ") + c.fix;
  const Solved direct = solve(c.deck, fix + " solver auto");
  const Solved iterative = solve(c.deck, fix + " solver iterative");
  int reduced = 0;
  const double largest = largest_difference(direct.factors, iterative.factors, reduced);
  if (AcousticTest::mpi_rank() == 0)
    std::printf("[ %s, %d ranks ] %zu contacts, %d reduced, %g iterations, residual %.3g, "
                "max |s_iterative - s_direct| = %.3g\n",
                c.name, AcousticTest::mpi_size(), direct.factors.size(), reduced, iterative.iterations,
                iterative.residual, largest);
  EXPECT_GT(reduced, 10) << "the drive must reduce friction for the comparison to mean something";
  EXPECT_LE(largest, 1e-6);
  EXPECT_LE(iterative.residual, 1e-9);
  EXPECT_GT(iterative.iterations, 0.0);
}

const Case kCases[] = {
    {"Normal2DDamping005", kLayer2D, "damping 0.05"},
    {"Full2DDamping005", kLayer2D, "model full damping 0.05"},
    {"Full2DDamping001", kLayer2D, "model full damping 0.01"},
    {"Normal3DDamping005", kLayer3D, "damping 0.05"},
    {"Full3DDamping001", kLayer3D, "model full damping 0.01"},
    {"Normal3DUnpreconditioned", kLayer3D, "damping 0.05 preconditioner none"},
};

INSTANTIATE_TEST_SUITE_P(Layers, IterativeMatchesDirect, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case> &info) { return std::string(info.param.name); });

TEST(DistributedMumps, MatchesTheGatheredFactorisation)
{
  // solver mumps (each rank its own entries, MUMPS on every rank) against
  // solver auto (the network gathered and factorised on rank 0), undamped
  // and damped, 2D and 3D
  for (const char *deck : {kLayer2D, kLayer3D}) {
    for (const std::string damping : {"", " damping 0.05"}) {
      SCOPED_TRACE(std::string(deck == kLayer2D ? "2D" : "3D") + damping);
      const std::string fix = "fix ac all acoustic/mindlin 100 frequency 2.0 amplitude 2e-3 source base model full" + damping;
      const Solved gathered = solve(deck, fix + " solver auto");
      const Solved distributed = solve(deck, fix + " solver mumps");
      int reduced = 0;
      EXPECT_LE(largest_difference(gathered.factors, distributed.factors, reduced), 1e-9);
      EXPECT_GT(reduced, 10);
      EXPECT_LE(distributed.residual, 1e-10);
    }
  }
}

TEST(IterativeSolver, OneAndTwoRanksGiveTheSameFactors)
{
  // one packing, written by rank 0 alone, solved by rank 0 alone and by
  // every rank together: the iterative solves agree to 1e-6
  const std::string file = "fix_iterative_ranks.data";
  const std::string fix = "pair_style granular\n"
                          "pair_coeff * * hertz/material 1e5 0.5 0.3 tangential mindlin/acoustic NULL 1.0 0.5\n"
                          "comm_modify vel yes\nneighbor 0.2 bin\nthermo 0\ngroup base type 2\n"
                          "fix ac all acoustic/mindlin 100 frequency 2.0 amplitude 2e-3 source base "
                          "damping 0.05 solver iterative\nrun 0\n";
  const std::string read = "units lj\natom_style sphere\nboundary p p fm\nprocessors * * 1\nread_data " + file + "\n";
  std::map<ContactKey, double> serial;
  if (AcousticTest::mpi_rank() == 0) {
    {
      LammpsInstance W(MPI_COMM_SELF);
      W.commands(kLayer3D);
      W.command("write_data " + file);
    }
    LammpsInstance S(MPI_COMM_SELF);
    S.commands(read + fix);
    serial = AcousticTest::friction_factors(S);
  }
  serial = AcousticTest::broadcast_from_rank0(serial);

  LammpsInstance P;
  P.commands(read + fix);
  int reduced = 0;
  const double largest = largest_difference(serial, AcousticTest::friction_factors(P), reduced);
  if (AcousticTest::mpi_rank() == 0)
    std::printf("[ 1 vs %d ranks ] %zu contacts, max |s(1) - s(N)| = %.3g\n", AcousticTest::mpi_size(),
                serial.size(), largest);
  EXPECT_GT(reduced, 10);
  EXPECT_LE(largest, 1e-6);
  MPI_Barrier(MPI_COMM_WORLD);
  if (AcousticTest::mpi_rank() == 0) std::remove(file.c_str());
}

TEST(IterativeSolver, TheSameRunTwiceGivesTheSameBits)
{
  // a tilted 2D layer that flows under updates every 20 steps: positions
  // after 400 steps identical bit for bit in two runs on the same ranks
  std::vector<double> first;
  for (int repeat = 0; repeat < 2; ++repeat) {
    LammpsInstance L;
    L.commands(kLayer2D);
    L.commands("fix grav grains gravity 1.0 vector 1 -1 0\n"
               "fix ac all acoustic/mindlin 20 frequency 2.0 amplitude 2e-3 source base model full "
               "damping 0.05 solver iterative\nrun 400\n");
    const std::vector<double> x = L.gather("x", 3);
    if (repeat == 0) {
      first = x;
      continue;
    }
    ASSERT_EQ(x.size(), first.size());
    for (std::size_t k = 0; k < x.size(); ++k) EXPECT_EQ(x[k], first[k]) << "coordinate " << k;
  }
}

TEST(IterativeSolver, UndampedInsideTheBandWarnsAndKeepsTheFactors)
{
  // a damped solve sets the factors of a 40 x 10 layer, which a restart file
  // keeps in the contact histories; the layer read back is driven at the same
  // frequency without damping, inside its band, with 100 iterations allowed:
  // the solve does not converge, warns that this is the direct solvers' job,
  // and the factors stay those of the damped solve (no NaN)
  std::string wide = kLayer2D;
  wide.replace(wide.find("block 0 16 0 6"), 14, "block 0 40 0 10");
  wide.replace(wide.find("0.5 6.3"), 7, "0.5 10.3");
  const std::string file = "fix_iterative_undamped.restart";
  std::map<ContactKey, double> damped;
  {
    LammpsInstance L;
    L.commands(wide);
    L.command("fix ac all acoustic/mindlin 100 frequency 2.0 amplitude 2e-3 source base damping 0.05 "
              "solver iterative");
    L.command("run 0");
    damped = AcousticTest::friction_factors(L);
    L.command("unfix integrate");
    L.command("write_restart " + file);
  }
  LammpsInstance L;
  L.command("read_restart " + file);
  L.command("comm_modify vel yes");
  L.command("neighbor 0.2 bin");
  L.command("log fix_iterative_warning.log");
  L.command("fix ac all acoustic/mindlin 100 frequency 2.0 amplitude 2e-3 source base solver iterative "
            "max_iterations 100");
  L.command("run 0");
  L.command("log none");
  const std::map<ContactKey, double> after = AcousticTest::friction_factors(L);
  int reduced = 0;
  EXPECT_EQ(largest_difference(damped, after, reduced), 0.0);
  EXPECT_GT(reduced, 10);
  for (const auto &kv : after) EXPECT_TRUE(std::isfinite(kv.second));
  LAMMPS_NS::Fix *ac = find_fix(L, "ac");
  EXPECT_EQ(ac->compute_vector(NITERATIONS), 100.0);
  EXPECT_GT(ac->compute_vector(RESIDUAL), 1e-9);
  const std::string log = file_text("fix_iterative_warning.log");
  if (AcousticTest::mpi_rank() == 0) {
    EXPECT_NE(log.find("WARNING: fix acoustic/mindlin: the iterative Helmholtz solve at f = 2 failed"),
              std::string::npos)
        << log;
    EXPECT_NE(log.find("use solver auto"), std::string::npos) << log;
  }
  MPI_Barrier(MPI_COMM_WORLD);
  if (AcousticTest::mpi_rank() == 0) {
    std::remove("fix_iterative_warning.log");
    std::remove(file.c_str());
  }
}

TEST(IterativeSolver, ReuseStartsFromTheLastSolution)
{
  // reuse yes: a second update of the same packing is answered by the last
  // solution (no iteration), a first one is not
  LammpsInstance L;
  L.commands(kLayer2D);
  L.command("unfix integrate");    // the packing stays as it is
  L.command("fix ac all acoustic/mindlin 10 frequency 2.0 amplitude 2e-3 source base damping 0.05 "
            "solver iterative reuse yes");
  L.command("run 0");
  LAMMPS_NS::Fix *fix = find_fix(L, "ac");
  EXPECT_GT(fix->compute_vector(NITERATIONS), 0.0);
  EXPECT_EQ(fix->compute_vector(NREUSES), 0.0);
  const std::map<ContactKey, double> first = AcousticTest::friction_factors(L);
  L.command("run 10");    // the update of step 10, the same network
  EXPECT_EQ(fix->compute_vector(NITERATIONS), 0.0);
  EXPECT_EQ(fix->compute_vector(NREUSES), 1.0);
  int reduced = 0;
  EXPECT_EQ(largest_difference(first, AcousticTest::friction_factors(L), reduced), 0.0);
}
