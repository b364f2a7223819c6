// Integration tests of compute vibration/modes: the modes of LAMMPS decks
// against independent answers (the analytic spectrum of a chain, the sound
// speed of a compressed triangular lattice from paper 003, rattlers counted
// by construction), the same results on 1 and 2 MPI ranks, KPM against dense,
// no effect on the dynamics when invoked during a run, and the errors of bad
// input.
#include "lammps_fixture.h"

#include "atom.h"
#include "compute.h"
#include "exceptions.h"
#include "modify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using AcousticTest::LammpsInstance;

namespace {

const double pi = 3.14159265358979323846;

LAMMPS_NS::Compute *find_compute(LammpsInstance &L, const std::string &id)
{
  const int icompute = L.lmp->modify->find_compute(id);
  if (icompute < 0) throw std::runtime_error("no compute " + id);
  return L.lmp->modify->compute[icompute];
}

// global vector (frequencies), on every rank
std::vector<double> frequencies(LammpsInstance &L, const std::string &id)
{
  LAMMPS_NS::Compute *c = find_compute(L, id);
  c->compute_vector();
  return std::vector<double>(c->vector, c->vector + c->size_vector);
}

double zero_modes(LammpsInstance &L, const std::string &id)
{
  return find_compute(L, id)->compute_scalar();
}

// global array (histogram) as rows, on every rank
std::vector<std::vector<double>> histogram(LammpsInstance &L, const std::string &id)
{
  LAMMPS_NS::Compute *c = find_compute(L, id);
  c->compute_array();
  std::vector<std::vector<double>> rows;
  for (int b = 0; b < c->size_array_rows; b++)
    rows.emplace_back(c->array[b], c->array[b] + c->size_array_cols);
  return rows;
}

// per-atom array ordered by atom ID (row tag - 1), on every rank
std::vector<std::vector<double>> per_atom(LammpsInstance &L, const std::string &id)
{
  LAMMPS_NS::Compute *c = find_compute(L, id);
  c->compute_peratom();
  const int ncols = c->size_peratom_cols;
  std::vector<double> mine;
  for (int i = 0; i < L.lmp->atom->nlocal; i++) {
    mine.push_back(static_cast<double>(L.lmp->atom->tag[i]));
    for (int k = 0; k < ncols; k++) mine.push_back(c->array_atom[i][k]);
  }
  const std::vector<double> all = AcousticTest::allgather(L, mine);
  std::vector<std::vector<double>> rows(L.natoms());
  for (std::size_t k = 0; k < all.size(); k += ncols + 1)
    rows[static_cast<long>(all[k]) - 1].assign(all.begin() + k + 1, all.begin() + k + 1 + ncols);
  return rows;
}

void print0(const std::string &text)
{
  if (AcousticTest::mpi_rank() == 0) std::printf("%s\n", text.c_str());
}

// ---------------------------------------------------------------------------
// a layer of rows of grains on a triangular lattice of spacing a, periodic in
// x (nx grains per row), rows 0 and nrows - 1 in group wall; atom ID
// r * nx + c + 1 for row r, column c

struct HexLayer {
  int nx, nrows;
  double a;
  double x(int r, int c) const { return (c + 0.5 * (r % 2) + 0.25) * a; }
  double y(int r) const { return r * 0.5 * std::sqrt(3.0) * a; }
  int id(int r, int c) const { return r * nx + c + 1; }

  std::string commands(const std::string &units) const
  {
    const double h = y(1);
    std::string d = "units " + units + "\ndimension 2\natom_style sphere\ncomm_modify vel yes\n"
                    "boundary p f p\n";
    d += fmt_box(0.0, nx * a, -a, y(nrows - 1) + a, -0.5 * a, 0.5 * a);
    d += "create_box 1 box\n";
    for (int r = 0; r < nrows; r++)
      for (int c = 0; c < nx; c++)
        d += "create_atoms 1 single " + num(x(r, c)) + " " + num(y(r)) + " 0 units box\n";
    d += "region bottom block INF INF INF " + num(0.5 * h) + " INF INF units box\n"
         "region top block INF INF " + num(y(nrows - 1) - 0.5 * h) + " INF INF INF units box\n"
         "group wall region bottom\ngroup wall region top\n";
    return d;
  }
  // do grains (r1, c1) and (r2, c2) touch on the lattice (nearest neighbours, periodic in x)?
  bool adjacent(int r1, int c1, int r2, int c2) const
  {
    double dx = std::fabs(x(r1, c1) - x(r2, c2));
    dx = std::min(dx, nx * a - dx);
    const double dy = y(r1) - y(r2);
    return dx * dx + dy * dy < 1.01 * a * a;
  }
  static std::string num(double v)
  {
    char buf[64];
    std::snprintf(buf, sizeof(buf), "%.17g", v);
    return buf;
  }
  static std::string fmt_box(double x0, double x1, double y0, double y1, double z0, double z1)
  {
    return "region box block " + num(x0) + " " + num(x1) + " " + num(y0) + " " + num(y1) + " " +
        num(z0) + " " + num(z1) + " units box\n";
  }
};

// ---------------------------------------------------------------------------
// 1. monodisperse chain of N grains between two fixed grains, Hooke contacts:
//    omega_k = 2 sqrt(k_n/m) sin(k pi / (2 (N+1))), shapes sin(k pi i / (N+1))

const int kChainGrains = 20;
const double kChainStiffness = 1000.0, kChainMass = 2.5;

std::string chain_deck()
{
  std::string d = "units lj\natom_style sphere\ncomm_modify vel yes\nboundary f p p\n"
                  "region box block -1 22 -2 2 -2 2\ncreate_box 1 box\n";
  for (int i = 0; i <= kChainGrains + 1; i++)
    d += "create_atoms 1 single " + HexLayer::num(0.99 * i) + " 0 0\n";
  d += "set group all diameter 1.0\nset group all mass " + HexLayer::num(kChainMass) + "\n"
       "group wall id 1 " + std::to_string(kChainGrains + 2) + "\n"
       "pair_style granular\n"
       "pair_coeff * * hooke " + HexLayer::num(kChainStiffness) +
       " 0.0 tangential linear_history/acoustic 800 0.5 0.5\n";
  return d;
}

double chain_omega(int k)
{
  return 2.0 * std::sqrt(kChainStiffness / kChainMass) *
      std::sin(k * pi / (2.0 * (kChainGrains + 1)));
}

class Chain : public ::testing::TestWithParam<const char *> {};

TEST_P(Chain, AnalyticFrequenciesAndShapes)
{
  const std::string method = GetParam();
  const bool dense = (method == "dense");
  const int n = kChainGrains;
  const int shown = 3;    // mode whose shape is checked
  // dense lists every mode: the 2N transverse DOFs of the 3D chain have no stiffness
  const int first = dense ? 2 * n : 0;
  LammpsInstance L;
  L.commands(chain_deck());
  L.command("compute modes all vibration/modes fixed wall method " + method +
            (dense ? "" : " nmodes " + std::to_string(n)) + " mode " +
            std::to_string(first + shown));
  L.command("run 0");
  const std::vector<double> f = frequencies(L, "modes");
  ASSERT_EQ(static_cast<int>(f.size()), first + n);
  EXPECT_EQ(zero_modes(L, "modes"), 2.0 * n);
  double worst = 0.0;
  for (int k = 1; k <= n; k++) {
    const double expected = chain_omega(k) / (2.0 * pi);
    worst = std::max(worst, std::fabs(f[first + k - 1] - expected) / expected);
  }
  print0("[ chain " + method + " ] max relative error of the " + std::to_string(n) +
         " frequencies: " + std::to_string(worst));
  EXPECT_LE(worst, 1e-8);
  for (int k = 0; k < first; k++) EXPECT_EQ(f[k], 0.0);

  // mass-normalised shape u_i = sqrt(2 / (m (N+1))) sin(k pi i / (N+1)) along x, up to its sign
  const auto shape = per_atom(L, "modes");
  ASSERT_EQ(shape.size(), static_cast<std::size_t>(n + 2));
  const double sign = (shape[1][0] >= 0.0) ? 1.0 : -1.0;
  for (int i = 0; i <= n + 1; i++) {
    const double expected =
        std::sqrt(2.0 / (kChainMass * (n + 1))) * std::sin(shown * pi * i / (n + 1));
    EXPECT_NEAR(sign * shape[i][0], expected, 1e-8) << "grain " << i;
    EXPECT_NEAR(shape[i][1], 0.0, 1e-12);
    EXPECT_NEAR(shape[i][2], 0.0, 1e-12);
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, Chain, ::testing::Values("dense", "lanczos"),
                         [](const ::testing::TestParamInfo<const char *> &info) {
                           return std::string(info.param);
                         });

// ---------------------------------------------------------------------------
// 2. triangular lattice of Hertz spheres under pressure p: the lowest
//    longitudinal mode gives the sound speed, against paper 003 Eq. (18)
//    (frictionless) and Eq. (19) (k_t = eta k_n, eta = (1 - nu)/(2 - nu)).
//    Paper 003's conventions (see unittest/numerics/test_triangular_lattice.cpp):
//    E* = E/(1 - nu^2), rho the density of the spheres, p = sqrt(3) f_n / d^2.
//    Lattice: 4 grains per row (periodic), 40 free rows between two fixed rows.

struct LatticeCase {
  const char *name;
  const char *keywords;    // network keywords of the compute
  bool frictional;
};

void PrintTo(const LatticeCase &c, std::ostream *os) { *os << c.name; }

class TriangularLattice : public ::testing::TestWithParam<LatticeCase> {};

TEST_P(TriangularLattice, SoundSpeedMatchesPaper003)
{
  const LatticeCase tc = GetParam();
  const double youngs = 7.0e10, nu = 0.2, density = 2500.0, d = 1.0e-3, pressure = 1.0e5;
  const double eta = (1.0 - nu) / (2.0 - nu);
  const int ny = 40;
  // overlap of the Hertz law F = (4/3) E_pair sqrt(R*) delta^(3/2) that carries f_n = p d^2 / sqrt(3)
  const double fn = pressure * d * d / std::sqrt(3.0);
  const double e_pair = youngs / (2.0 * (1.0 - nu * nu));
  const double overlap = std::pow(fn / (4.0 / 3.0 * e_pair * std::sqrt(d / 4.0)), 2.0 / 3.0);
  const HexLayer layer{4, ny + 2, d - overlap};
  const double mass = density * pi * d * d * d / 6.0;

  LammpsInstance L;
  L.commands(layer.commands("si"));
  L.commands("set group all diameter " + HexLayer::num(d) + "\nset group all mass " +
             HexLayer::num(mass) + "\nneighbor 1e-4 bin\npair_style granular\n"
             "pair_coeff * * hertz/material 7e10 0.0 0.2 tangential mindlin/acoustic NULL 1.0 0.5\n");
  std::string keywords = tc.keywords;
  if (tc.frictional) keywords += " ratio " + HexLayer::num(eta);
  L.command("compute modes all vibration/modes fixed wall " + keywords);
  L.command("run 0");

  // paper 003: c / sqrt(E*/rho) = 3^(19/12) / (2^(3/2) pi^(1/2)) (p/E*)^(1/6) [sqrt(1 + eta/3)]
  const double e_star = youngs / (1.0 - nu * nu);
  double c_paper = std::sqrt(e_star / density) * std::pow(3.0, 19.0 / 12.0) /
      (std::pow(2.0, 1.5) * std::sqrt(pi)) * std::pow(pressure / e_star, 1.0 / 6.0);
  if (tc.frictional) c_paper *= std::sqrt(1.0 + eta / 3.0);
  // rows of spacing l = sqrt(3) d / 2 form a chain: omega_1 = (2 c / l) sin(pi / (2 (ny + 1)))
  const double row_spacing = 0.5 * std::sqrt(3.0) * d;
  const double sine = std::sin(pi / (2.0 * (ny + 1)));
  const double f_paper = 2.0 * c_paper / row_spacing * sine / (2.0 * pi);

  const std::vector<double> f = frequencies(L, "modes");
  int nearest = 0;
  for (std::size_t k = 1; k < f.size(); k++)
    if (std::fabs(f[k] - f_paper) < std::fabs(f[nearest] - f_paper)) nearest = static_cast<int>(k);

  // it is the longitudinal mode: u_y of each row ~ sin(pi row / (ny + 1)), u_x = 0
  L.command("compute shape all vibration/modes fixed wall " + keywords + " mode " +
            std::to_string(nearest + 1));
  L.command("run 0");
  const auto shape = per_atom(L, "shape");
  double dot = 0.0, norm_mode = 0.0, norm_target = 0.0;
  for (int r = 0; r < ny + 2; r++)
    for (int c = 0; c < layer.nx; c++) {
      const auto &u = shape[layer.id(r, c) - 1];
      const double target = std::sin(pi * r / (ny + 1));
      dot += u[1] * target;
      norm_mode += u[0] * u[0] + u[1] * u[1];
      norm_target += target * target;
    }
  const double overlap_with_target = std::fabs(dot) / std::sqrt(norm_mode * norm_target);
  EXPECT_GT(overlap_with_target, 0.999);

  const double c_measured = 2.0 * pi * f[nearest] * row_spacing / (2.0 * sine);
  print0(std::string("[ lattice 4 x (40 + 2) rows, ") + tc.name + " ] mode " +
         std::to_string(nearest + 1) + ", overlap " + std::to_string(overlap_with_target) +
         ", c / c_paper = " + HexLayer::num(c_measured / c_paper));
  EXPECT_NEAR(c_measured / c_paper, 1.0, 0.02);
}

const LatticeCase kLattices[] = {
    {"eq18_model_normal_stiffness_pair", "model normal", false},
    {"eq19_model_full_stiffness_hertz", "model full stiffness hertz 7e10 0.2", true},
};

INSTANTIATE_TEST_SUITE_P(Paper003, TriangularLattice, ::testing::ValuesIn(kLattices),
                         [](const ::testing::TestParamInfo<LatticeCase> &info) {
                           return std::string(info.param.name);
                         });

// ---------------------------------------------------------------------------
// 3. disordered packing with rattlers: triangular sites, random diameters in
//    [0.99, 1.01] (every neighbour pair overlaps), and randomly chosen
//    non-adjacent grains shrunk to 0.8 (no contact: rattlers)

struct Packing {
  HexLayer layer;
  std::string deck;
  int rattlers;
};

Packing disordered_packing(int nx, int nrows, unsigned seed)
{
  Packing p{HexLayer{nx, nrows, 0.98}, "", 0};
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<std::pair<int, int>> chosen;
  std::string ids;
  for (int r = 2; r < nrows - 2; r++)
    for (int c = 0; c < nx; c++) {
      if (uniform(random) > 0.12) continue;
      bool free_site = true;
      for (const auto &o : chosen) free_site = free_site && !p.layer.adjacent(r, c, o.first, o.second);
      if (!free_site) continue;
      chosen.emplace_back(r, c);
      ids += " " + std::to_string(p.layer.id(r, c));
    }
  p.rattlers = static_cast<int>(chosen.size());
  p.deck = p.layer.commands("lj") +
      // a pseudo-random fraction of the atom ID: the same on any number of processors
      "variable h atom 43758.5453*sin(12.9898*id+" + std::to_string(seed) + ")\n"
      "variable d atom 0.99+0.02*(v_h-floor(v_h))\n"
      "set group all diameter v_d\nset group all density 1.0\n"
      "group rattlers id" + ids + "\nset group rattlers diameter 0.8\n"
      "pair_style granular\n"
      "pair_coeff * * hertz/material 1e5 0.0 0.3 tangential mindlin/acoustic NULL 1.0 0.5\n";
  return p;
}

struct RattlerCase {
  const char *name;
  const char *keywords;
  int dofs_per_grain;
};

void PrintTo(const RattlerCase &c, std::ostream *os) { *os << c.name; }

class Rattlers : public ::testing::TestWithParam<RattlerCase> {};

TEST_P(Rattlers, ZeroModesAreRattlersTimesDofs)
{
  const RattlerCase tc = GetParam();
  const Packing p = disordered_packing(10, 14, 4321u);
  ASSERT_GE(p.rattlers, 5);
  LammpsInstance L;
  L.commands(p.deck);
  L.commands("compute contacts all contact/atom\n"
             "compute modes all vibration/modes fixed wall " + std::string(tc.keywords) + "\n"
             "run 0\n");
  // every rattler is contact-free, every other grain touches
  LAMMPS_NS::Compute *contacts = find_compute(L, "contacts");
  contacts->compute_peratom();
  int wrong = 0;
  for (int i = 0; i < L.lmp->atom->nlocal; i++) {
    const bool rattler = (L.lmp->atom->radius[i] < 0.45);
    if (rattler != (contacts->vector_atom[i] == 0.0)) wrong++;
  }
  int wrong_all = 0;
  MPI_Allreduce(&wrong, &wrong_all, 1, MPI_INT, MPI_SUM, L.lmp->world);
  EXPECT_EQ(wrong_all, 0) << "the packing is not built as intended";

  const double expected = static_cast<double>(p.rattlers) * tc.dofs_per_grain;
  print0(std::string("[ rattlers ") + tc.name + " ] " + std::to_string(p.rattlers) +
         " rattlers, zero modes " + HexLayer::num(zero_modes(L, "modes")) + ", expected " +
         HexLayer::num(expected));
  EXPECT_EQ(zero_modes(L, "modes"), expected);
  const std::vector<double> f = frequencies(L, "modes");
  if (std::string(tc.keywords).find("lanczos") == std::string::npos) {
    // dense: the zero modes come first, the next one is clearly non-zero
    const int n = static_cast<int>(expected);
    ASSERT_GT(static_cast<int>(f.size()), n);
    // zero modes: |omega^2| <= 1e-8 of the spectrum's bound, round-off in practice
    EXPECT_LT(f[n - 1], 1e-4 * f.back());
    EXPECT_GT(f[n], 1e-2 * f.back());
  } else {
    for (double value : f) EXPECT_GT(value, 0.0);
  }
}

const RattlerCase kRattlerCases[] = {
    {"dense_model_normal", "method dense", 2},
    {"dense_model_full", "method dense model full ratio 0.5", 3},
    {"lanczos_model_normal", "method lanczos nmodes 8", 2},
    {"lanczos_model_full", "method lanczos nmodes 8 model full ratio 0.5", 3},
};

INSTANTIATE_TEST_SUITE_P(Packing, Rattlers, ::testing::ValuesIn(kRattlerCases),
                         [](const ::testing::TestParamInfo<RattlerCase> &info) {
                           return std::string(info.param.name);
                         });

// dense and lanczos agree on the lowest non-zero modes
TEST(Methods, LanczosMatchesDense)
{
  const Packing p = disordered_packing(10, 14, 99u);
  LammpsInstance L;
  L.commands(p.deck);
  L.commands("compute dense all vibration/modes fixed wall model full ratio 0.4\n"
             "compute lanczos all vibration/modes fixed wall model full ratio 0.4 method lanczos "
             "nmodes 12\nrun 0\n");
  const std::vector<double> fd = frequencies(L, "dense");
  const std::vector<double> fl = frequencies(L, "lanczos");
  const int nzero = static_cast<int>(zero_modes(L, "dense"));
  EXPECT_EQ(nzero, 3 * p.rattlers);
  EXPECT_EQ(zero_modes(L, "lanczos"), nzero);
  ASSERT_EQ(fl.size(), 12u);
  for (int k = 0; k < 12; k++) EXPECT_NEAR(fl[k], fd[nzero + k], 1e-9 * fd.back()) << k;
}

// ---------------------------------------------------------------------------
// 4. the same modes on 1 and 2 MPI ranks (under mpirun -np 2 the reference
//    is computed by a serial LAMMPS on each rank)

TEST(Parallel, SameOnOneAndTwoRanks)
{
  const Packing p = disordered_packing(12, 16, 7u);
  const std::string compute =
      "compute modes all vibration/modes fixed wall model full ratio 0.5 mode 40 bins 8 0 1.5\n"
      "run 0\n";
  std::vector<double> f[2];
  std::vector<std::vector<double>> shape[2], hist[2];
  MPI_Comm comms[2] = {MPI_COMM_SELF, MPI_COMM_WORLD};
  for (int k = 0; k < 2; k++) {
    LammpsInstance L(comms[k]);
    L.commands(p.deck + compute);
    f[k] = frequencies(L, "modes");
    shape[k] = per_atom(L, "modes");
    hist[k] = histogram(L, "modes");
  }
  ASSERT_EQ(f[0].size(), f[1].size());
  const double scale = f[0].back();
  // compare omega^2: zero modes are at round-off level in omega^2
  for (std::size_t m = 0; m < f[0].size(); m++)
    EXPECT_NEAR(f[1][m] * f[1][m], f[0][m] * f[0][m], 1e-11 * scale * scale) << m;
  ASSERT_EQ(shape[0].size(), shape[1].size());
  for (std::size_t i = 0; i < shape[0].size(); i++)
    for (int c = 0; c < 6; c++) EXPECT_NEAR(shape[1][i][c], shape[0][i][c], 1e-8) << i << " " << c;
  for (int b = 0; b < 8; b++) EXPECT_NEAR(hist[1][b][1], hist[0][b][1], 1e-12);
  print0("[ parallel ] " + std::to_string(AcousticTest::mpi_size()) + " rank(s) against 1: " +
         std::to_string(f[0].size()) + " frequencies, mode 40 shape and histogram compared");
}

// ---------------------------------------------------------------------------
// 5. KPM against dense on a disordered packing (about 1 400 free DOFs)

TEST(Methods, KpmMatchesDenseHistogram)
{
  const Packing p = disordered_packing(20, 40, 11u);
  LammpsInstance L;
  L.commands(p.deck);
  const double fmax = 60.0;
  L.commands("compute dense all vibration/modes fixed wall bins 10 0 60\n"
             "compute kpm all vibration/modes fixed wall method kpm bins 10 0 60 moments 1000\n"
             "run 0\n");
  const std::vector<double> f = frequencies(L, "dense");
  ASSERT_LT(f.back(), fmax) << "the histogram must cover the whole spectrum";
  const auto exact = histogram(L, "dense");
  const auto kpm = histogram(L, "kpm");
  double l1 = 0.0, error_sum = 0.0;
  const double width = fmax / 10;
  for (int b = 0; b < 10; b++) {
    EXPECT_DOUBLE_EQ(kpm[b][0], exact[b][0]);
    EXPECT_EQ(exact[b][2], 0.0);
    l1 += std::fabs(kpm[b][1] - exact[b][1]) * width;
    error_sum += kpm[b][2] * width;
  }
  print0("[ kpm ] L1(kpm - dense) = " + std::to_string(l1) + ", summed error estimate " +
         std::to_string(error_sum));
  EXPECT_LT(l1, 0.03);
  EXPECT_GT(error_sum, 0.0);
  // KPM counts the decoupled DOFs of the rattlers as zero modes
  EXPECT_EQ(zero_modes(L, "kpm"), 2.0 * p.rattlers);
}

// ---------------------------------------------------------------------------
// 6. invoked during a run (thermo, fix ave/time, dump) the compute leaves the
//    trajectory unchanged, and recomputes on each new timestep

std::string flowing_layer()
{
  return "units lj\ndimension 2\natom_style sphere\ncomm_modify vel yes\nboundary p f p\n"
         "region box block 0 12 0 14 -0.5 0.5\ncreate_box 1 box\nlattice sq 1.0\n"
         "region fill block 0 12 0 8 -0.5 0.5\ncreate_atoms 1 region fill\n"
         "variable d atom 0.96+0.08*random(0,1,4321)\nset group all diameter v_d\n"
         "set group all density 1.0\nregion base block INF INF INF 0.9 INF INF\n"
         "group base region base\ngroup grains subtract all base\n"
         "velocity grains create 0.5 87287 loop geom\n"
         "pair_style granular\n"
         "pair_coeff * * hertz/material 1e5 0.5 0.3 tangential mindlin/acoustic NULL 1.0 0.5\n"
         "fix nve grains nve/sphere\nfix grav grains gravity 10 vector 0.2 -1.0 0.0\n"
         "fix 2d all enforce2d\ntimestep 1e-3\nneighbor 0.3 bin\n"
         "neigh_modify delay 0 every 1 check yes\n";
}

TEST(DuringRun, DynamicsUnchanged)
{
  std::vector<double> x[2], v[2];
  for (int k = 0; k < 2; k++) {
    LammpsInstance L;
    L.commands(flowing_layer());
    if (k == 1)
      L.commands("compute modes all vibration/modes fixed base bins 5 0 5 mode 3\n"
                 "compute pr all reduce max c_modes[3]\n"
                 "thermo_style custom step c_modes c_modes[10] c_modes[1][2] c_pr\nthermo 50\n"
                 "fix hist all ave/time 100 1 100 c_modes[1] c_modes[2] mode vector\n"
                 "dump shape all custom 100 /dev/null id c_modes[1] c_modes[2]\n");
    L.command("run 400");
    x[k] = L.gather("x", 3);
    v[k] = L.gather("v", 3);
    if (k == 1) {
      LAMMPS_NS::Compute *c = find_compute(L, "modes");
      EXPECT_EQ(c->invoked_scalar, 400);
      EXPECT_EQ(c->invoked_peratom, 400);
    }
  }
  double vmax = 0.0;
  for (double value : v[0]) vmax = std::max(vmax, std::fabs(value));
  ASSERT_GT(vmax, 0.05) << "the layer does not move";
  for (std::size_t m = 0; m < x[0].size(); m++) {
    ASSERT_EQ(x[0][m], x[1][m]) << m;
    ASSERT_EQ(v[0][m], v[1][m]) << m;
  }
}

// ---------------------------------------------------------------------------
// 7. errors

struct BadInput {
  const char *name;
  const char *setup;      // replaces the pair style of the chain deck if not empty
  const char *command;    // compute (and run) lines
  const char *message;
};

void PrintTo(const BadInput &b, std::ostream *os) { *os << b.name; }

class Errors : public ::testing::TestWithParam<BadInput> {};

TEST_P(Errors, Message)
{
  const BadInput bad = GetParam();
  LammpsInstance L;
  L.commands(chain_deck());
  if (*bad.setup) L.commands(bad.setup);
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
    {"unknown_keyword", "", "compute m all vibration/modes colour red",
     "Unknown compute vibration/modes keyword: colour; keywords are stiffness"},
    {"missing_value", "", "compute m all vibration/modes bins 10 0",
     "Illegal compute vibration/modes bins command: missing argument(s)"},
    {"missing_fixed_group", "", "compute m all vibration/modes fixed nowhere",
     "fixed group nowhere does not exist; define it with the group command first"},
    {"unknown_method", "", "compute m all vibration/modes method arpack",
     "unknown vibration mode method 'arpack': allowed methods are dense, lanczos, kpm"},
    {"nmodes_zero", "", "compute m all vibration/modes method lanczos nmodes 0",
     "nmodes must be > 0, got 0"},
    {"nmodes_with_dense", "", "compute m all vibration/modes nmodes 5",
     "nmodes applies to method lanczos only"},
    {"bins_zero", "", "compute m all vibration/modes bins 0 0 10",
     "the number of bins must be >= 1"},
    {"bins_empty_range", "", "compute m all vibration/modes bins 10 5 5",
     "need 0 <= fmin < fmax"},
    {"mode_zero", "", "compute m all vibration/modes mode 0", "mode must be >= 1"},
    {"mode_beyond_nmodes", "", "compute m all vibration/modes method lanczos nmodes 3 mode 5",
     "mode 5 is out of range: method lanczos computes nmodes = 3 modes; raise nmodes"},
    {"mode_beyond_dense", "", "compute m all vibration/modes fixed wall mode 61\n"
     "dump d all custom 1 /dev/null id c_m[1]\nrun 0",
     "mode 61 is out of range: method dense found 60 modes of the network (60 free DOFs)"},
    {"kpm_without_bins", "", "compute m all vibration/modes method kpm",
     "method kpm computes the density of states only; give its range with bins Nb fmin fmax"},
    {"kpm_with_mode", "", "compute m all vibration/modes method kpm bins 5 0 10 mode 1",
     "method kpm computes no individual mode"},
    {"kpm_keyword_with_dense", "", "compute m all vibration/modes moments 100",
     "moments, vectors and seed apply to method kpm only"},
    {"kpm_moments", "", "compute m all vibration/modes method kpm bins 5 0 10 moments 1",
     "moments must be >= 2"},
    {"damping", "", "compute m all vibration/modes damping 0.1",
     "keyword damping does not apply: the modes are those of the undamped network"},
    {"model", "", "compute m all vibration/modes model rigid", "unknown contact model"},
    {"stiffness_hertz_nu", "", "compute m all vibration/modes stiffness hertz 1e5 0.7",
     "stiffness hertz needs -1 < nu < 0.5"},
    {"pair_granular", "pair_style granular\npair_coeff * * hooke 1000 0.0 tangential "
     "linear_history 800 0.5 0.5",
     "compute m all vibration/modes\nthermo_style custom step c_m\nrun 0",
     "use tangential linear_history/acoustic in pair_coeff"},
    {"fixed_outside_group", "", "group inner id 2:21\n"
     "compute m inner vibration/modes fixed wall\nthermo_style custom step c_m\nrun 0",
     "fixed group wall has no atom in the compute group inner"},
    {"all_fixed", "", "compute m wall vibration/modes fixed wall\nthermo_style custom step c_m\n"
     "run 0", "no degree of freedom is left"},
};

INSTANTIATE_TEST_SUITE_P(BadInput, Errors, ::testing::ValuesIn(kBadInputs),
                         [](const ::testing::TestParamInfo<BadInput> &info) {
                           return std::string(info.param.name);
                         });

// dense on a network too large for it says to use lanczos or kpm
TEST(DenseLimit, TooManyDofsForDense)
{
  LammpsInstance L;
  L.commands("units lj\ndimension 2\natom_style sphere\ncomm_modify vel yes\n"
             "boundary f f p\nregion box block -1 101 -1 102 -0.5 0.5\ncreate_box 1 box\n"
             "lattice sq 1.0\nregion fill block 0 100 0 100.5 -0.5 0.5\n"
             "create_atoms 1 region fill\nset group all diameter 1.02\nset group all density 1.0\n"
             "pair_style granular\n"
             "pair_coeff * * hooke 1000 0.0 tangential linear_history/acoustic 800 0.5 0.5\n"
             "compute m all vibration/modes\nthermo_style custom step c_m\n");
  ASSERT_GT(L.natoms(), 10000);
  try {
    L.command("run 0");
    FAIL() << "dense accepted " << 2 * L.natoms() << " DOFs";
  } catch (LAMMPS_NS::LAMMPSException &e) {
    EXPECT_NE(std::string(e.what()).find("is too many for a dense eigensolver (limit 20000); use "
                                         "method lanczos or kpm"),
              std::string::npos)
        << e.what();
  }
}

}    // namespace
