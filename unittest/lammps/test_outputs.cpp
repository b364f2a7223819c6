// Every output of fix acoustic/mindlin and compute vibration/modes through the
// LAMMPS consumers made for its kind, one test per consumer: thermo,
// equal- and vector-style variables, fix ave/time (scalar and vector mode),
// fix ave/atom, compute reduce with inputs local, dump custom, dump local.
#include "lammps_fixture.h"

#include "atom.h"
#include "compute.h"
#include "fix.h"
#include "input.h"
#include "modify.h"
#include "variable.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using AcousticTest::LammpsInstance;

namespace {

// a settled 2D layer, the fix (updates every 10 steps) and the compute (dense,
// histogram of 8 bins, shape of mode 3), both with the base clamped or driven
std::string outputs_deck()
{
  return "units lj\ndimension 2\natom_style sphere\nboundary p fm p\ncomm_modify vel yes\n"
         "processors * 1 1\nlattice hex 1.1547005383792517\n"
         "region box block 0 10 0 5 -0.5 0.5\ncreate_box 2 box\n"
         "region base block INF INF -0.1 0.1 INF INF units box\n"
         "region layer block INF INF 0.5 4.3 INF INF units box\n"
         "create_atoms 2 region base\ncreate_atoms 1 region layer\n"
         "group base type 2\ngroup grains type 1\n"
         "set group all diameter 1.002\nset group all density 1.0\npair_style granular\n"
         "pair_coeff * * hertz/material 1e5 0.5 0.3 tangential mindlin/acoustic NULL 1.0 0.5\n"
         "fix integrate grains nve/sphere\nfix plane all enforce2d\n"
         "fix grav grains gravity 1.0 vector 0 -1 0\n"
         "timestep 1e-3\nneighbor 0.2 bin\nthermo 0\nrun 2000\n"
         "fix ac all acoustic/mindlin 10 frequency 3.0 amplitude 5e-4 source base\n"
         "compute m all vibration/modes fixed base bins 8 0 16 mode 3\n";
}

LAMMPS_NS::Fix *fix_of(LammpsInstance &L, const char *id)
{
  return L.lmp->modify->get_fix_by_id(id);
}

LAMMPS_NS::Compute *compute_of(LammpsInstance &L, const char *id)
{
  return L.lmp->modify->get_compute_by_id(id);
}

// Rank 0 writes the log and output files; every reader first waits for all
// ranks, so that no rank reads a file before rank 0 has closed or flushed it
// (a rank that failed an assertion on a half-written file would leave the
// other rank alone in the next collective call).
void wait_for_the_writer()
{
  MPI_Barrier(MPI_COMM_WORLD);
}

std::vector<std::vector<double>> numeric_rows(const std::string &file, std::size_t columns)
{
  wait_for_the_writer();
  std::vector<std::vector<double>> rows;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::vector<double> row;
    double value;
    while (words >> value) row.push_back(value);
    if (row.size() == columns && words.eof()) rows.push_back(row);
  }
  return rows;
}

// the last step's rows of a dump file: the lines after its last "ITEM: ATOMS" or
// "ITEM: ENTRIES" header
std::vector<std::vector<double>> last_dump_rows(const std::string &file)
{
  wait_for_the_writer();
  std::ifstream in(file);
  std::string line;
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    if (line.rfind("ITEM:", 0) == 0) {
      if (line.rfind("ITEM: ATOMS", 0) == 0 || line.rfind("ITEM: ENTRIES", 0) == 0) rows.clear();
      continue;
    }
    std::istringstream words(line);
    std::vector<double> row;
    double value;
    while (words >> value) row.push_back(value);
    rows.push_back(row);
  }
  return rows;
}

double equal_variable(LammpsInstance &L, const std::string &name)
{
  LAMMPS_NS::Variable *v = L.lmp->input->variable;
  return v->compute_equal(v->find(name.c_str()));
}

// per-atom column k of a fix or compute, by atom ID, on every rank
std::map<long, double> by_id(LammpsInstance &L, double **array, int k)
{
  std::vector<double> mine;
  for (int i = 0; i < L.lmp->atom->nlocal; i++) {
    mine.push_back(static_cast<double>(L.lmp->atom->tag[i]));
    mine.push_back(array[i][k]);
  }
  const std::vector<double> all = AcousticTest::allgather(L, mine);
  std::map<long, double> result;
  for (std::size_t m = 0; m < all.size(); m += 2) result[static_cast<long>(all[m])] = all[m + 1];
  return result;
}

void remove_file(const std::string &name)
{
  wait_for_the_writer();
  if (AcousticTest::mpi_rank() == 0) std::remove(name.c_str());
}

TEST(Outputs, Thermo)
{
  LammpsInstance L;
  L.commands(outputs_deck());
  L.commands("log outputs_thermo.log\nthermo_style custom step f_ac[2] f_ac[3] c_m c_m[1] c_m[3][2]\n"
             "thermo_modify format float %.15g\nrun 0\nlog none\n");
  auto *fix = fix_of(L, "ac");
  auto *modes = compute_of(L, "m");
  const auto rows = numeric_rows("outputs_thermo.log", 6);
  ASSERT_FALSE(rows.empty());
  const auto &row = rows.back();
  EXPECT_NEAR(row[1], fix->compute_vector(1), 1e-14);
  EXPECT_NEAR(row[2], fix->compute_vector(2), 1e-14);
  EXPECT_LT(row[1], 1.0) << "no friction reduction: the test would be empty";
  EXPECT_EQ(row[3], modes->scalar);
  EXPECT_NEAR(row[4], modes->vector[0], 1e-12 * modes->vector[0]);
  EXPECT_NEAR(row[5], modes->array[2][1], 1e-12 * modes->array[2][1]);
  EXPECT_GT(row[5], 0.0);
  remove_file("outputs_thermo.log");
}

TEST(Outputs, EqualAndVectorVariables)
{
  LammpsInstance L;
  L.commands(outputs_deck());
  L.commands("variable mean equal f_ac[2]\nvariable zero equal c_m\nvariable f1 equal c_m[1]\n"
             "variable freqs vector c_m\nvariable density vector c_m[2]\n"
             "thermo_style custom step v_mean v_zero v_f1\nrun 0\n");
  auto *fix = fix_of(L, "ac");
  auto *modes = compute_of(L, "m");
  EXPECT_EQ(equal_variable(L, "mean"), fix->compute_vector(1));
  EXPECT_EQ(equal_variable(L, "zero"), modes->scalar);
  EXPECT_EQ(equal_variable(L, "f1"), modes->vector[0]);
  LAMMPS_NS::Variable *v = L.lmp->input->variable;
  double *values = nullptr;
  const int n = v->compute_vector(v->find("freqs"), &values);
  ASSERT_EQ(n, modes->size_vector);
  ASSERT_GT(n, 50);
  for (int k = 0; k < n; k++) EXPECT_EQ(values[k], modes->vector[k]);
  const int nbins = v->compute_vector(v->find("density"), &values);
  ASSERT_EQ(nbins, 8);
  for (int b = 0; b < nbins; b++) EXPECT_EQ(values[b], modes->array[b][1]);
}

TEST(Outputs, FixAveTimeScalarAndVectorModes)
{
  LammpsInstance L;
  L.commands(outputs_deck());
  L.commands("fix stats all ave/time 10 1 10 f_ac[1] f_ac[2] f_ac[3]\n"
             "fix spectrum all ave/time 10 1 10 c_m mode vector file outputs_spectrum.dat "
             "format %24.17g\n"
             "fix histogram all ave/time 10 1 10 c_m[1] c_m[2] mode vector file "
             "outputs_histogram.dat format %24.17g\nrun 10\n");
  auto *fix = fix_of(L, "ac");
  auto *modes = compute_of(L, "m");
  auto *stats = fix_of(L, "stats");
  for (int k = 0; k < 3; k++) EXPECT_EQ(stats->compute_vector(k), fix->compute_vector(k));
  L.command("unfix spectrum\nunfix histogram");    // flush and close the files
  // mode vector on the variable-length vector of frequencies (lock_length):
  // rows "index frequency" after the header of step 10
  modes->compute_vector();
  ASSERT_GT(modes->size_vector, 50);
  // two blocks (steps 2000 and 2010) of a line "step N" and N rows: the last one
  const int n = modes->size_vector;
  auto spectrum = numeric_rows("outputs_spectrum.dat", 2);
  ASSERT_EQ(spectrum.size(), 2u * (n + 1));
  spectrum.erase(spectrum.begin(), spectrum.begin() + n + 1);
  EXPECT_EQ(spectrum[0][0], 2010.0);
  EXPECT_EQ(spectrum[0][1], static_cast<double>(n));
  for (int k = 0; k < modes->size_vector; k++) {
    EXPECT_EQ(spectrum[k + 1][0], k + 1.0);
    EXPECT_EQ(spectrum[k + 1][1], modes->vector[k]);
  }
  modes->compute_array();
  auto histogram = numeric_rows("outputs_histogram.dat", 3);
  ASSERT_EQ(histogram.size(), 16u);
  histogram.erase(histogram.begin(), histogram.begin() + 8);
  for (int b = 0; b < 8; b++) {
    EXPECT_EQ(histogram[b][1], modes->array[b][0]);
    EXPECT_EQ(histogram[b][2], modes->array[b][1]);
  }
  remove_file("outputs_spectrum.dat");
  remove_file("outputs_histogram.dat");
}

TEST(Outputs, FixAveAtom)
{
  LammpsInstance L;
  L.commands(outputs_deck());
  L.commands("fix amp all ave/atom 10 1 10 f_ac[1] f_ac[2]\n"
             "fix shape all ave/atom 10 1 10 c_m[1] c_m[2]\nrun 10\n");
  auto *fix = fix_of(L, "ac");
  auto *modes = compute_of(L, "m");
  modes->compute_peratom();
  auto *amp = fix_of(L, "amp");
  auto *shape = fix_of(L, "shape");
  for (int k = 0; k < 2; k++) {
    const auto averaged = by_id(L, amp->array_atom, k), direct = by_id(L, fix->array_atom, k);
    EXPECT_EQ(averaged, direct);
    const auto averaged_shape = by_id(L, shape->array_atom, k);
    const auto direct_shape = by_id(L, modes->array_atom, k);
    EXPECT_EQ(averaged_shape, direct_shape);
  }
  double largest = 0.0;
  for (const auto &kv : by_id(L, amp->array_atom, 1)) largest = std::max(largest, std::fabs(kv.second));
  EXPECT_GT(largest, 0.0);
}

TEST(Outputs, ComputeReduceInputsLocal)
{
  LammpsInstance L;
  L.commands(outputs_deck());
  L.commands("compute smallest all reduce min f_ac[6] inputs local\n"
             "compute contacts all reduce sum f_ac[6] inputs local\n"
             "compute maxpr all reduce max c_m[3] inputs local\n"
             "compute nmodes all reduce max c_m[1] inputs local\n"
             "thermo_style custom step c_smallest c_contacts c_maxpr c_nmodes\nrun 0\n");
  auto *fix = fix_of(L, "ac");
  auto *modes = compute_of(L, "m");
  EXPECT_EQ(compute_of(L, "smallest")->compute_scalar(), fix->compute_vector(2));
  EXPECT_NEAR(compute_of(L, "contacts")->compute_scalar(),
              fix->compute_vector(1) * fix->compute_vector(0), 1e-9 * fix->compute_vector(0));
  const double maxpr = compute_of(L, "maxpr")->compute_scalar();
  EXPECT_GT(maxpr, 0.0);
  EXPECT_LE(maxpr, 1.0);
  modes->compute_vector();
  EXPECT_EQ(compute_of(L, "nmodes")->compute_scalar(), static_cast<double>(modes->size_vector));
}

TEST(Outputs, DumpCustom)
{
  LammpsInstance L;
  L.commands(outputs_deck());
  L.commands("dump grains all custom 10 outputs.dump id f_ac[1] f_ac[2] c_m[1] c_m[2]\n"
             "dump_modify grains sort id format float %.17g\nrun 10\n");
  auto *fix = fix_of(L, "ac");
  auto *modes = compute_of(L, "m");
  modes->compute_peratom();
  const auto amp_x = by_id(L, fix->array_atom, 0), amp_y = by_id(L, fix->array_atom, 1);
  const auto shape_x = by_id(L, modes->array_atom, 0), shape_y = by_id(L, modes->array_atom, 1);
  const auto rows = last_dump_rows("outputs.dump");
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(L.natoms()));
  for (const auto &row : rows) {
    ASSERT_EQ(row.size(), 5u);
    const long id = static_cast<long>(row[0]);
    EXPECT_EQ(row[1], amp_x.at(id));
    EXPECT_EQ(row[2], amp_y.at(id));
    EXPECT_EQ(row[3], shape_x.at(id));
    EXPECT_EQ(row[4], shape_y.at(id));
  }
  remove_file("outputs.dump");
}

TEST(Outputs, DumpLocal)
{
  LammpsInstance L;
  L.commands(outputs_deck());
  L.commands("dump contacts all local 10 outputs_contacts.local f_ac[1] f_ac[2] f_ac[6]\n"
             "dump_modify contacts format float %.17g\n"
             "dump modes all local 10 outputs_modes.local c_m[1] c_m[2] c_m[3]\n"
             "dump_modify modes format float %.17g\nrun 10\n");
  auto *fix = fix_of(L, "ac");
  auto *modes = compute_of(L, "m");
  std::vector<double> mine;
  for (int r = 0; r < fix->size_local_rows; r++) mine.push_back(fix->array_local[r][5]);
  const std::vector<double> factors = AcousticTest::allgather(L, mine);
  modes->compute_vector();
  const std::vector<double> frequencies(modes->vector, modes->vector + modes->size_vector);
  const auto contact_rows = last_dump_rows("outputs_contacts.local");
  ASSERT_EQ(contact_rows.size(), factors.size());
  ASSERT_EQ(static_cast<double>(contact_rows.size()), fix->compute_vector(0));
  std::vector<double> dumped;
  for (const auto &row : contact_rows) dumped.push_back(row.at(2));
  std::vector<double> expected = factors;
  std::sort(dumped.begin(), dumped.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(dumped, expected);
  const auto mode_rows = last_dump_rows("outputs_modes.local");
  ASSERT_EQ(mode_rows.size(), frequencies.size());
  for (std::size_t m = 0; m < mode_rows.size(); m++) {
    EXPECT_EQ(mode_rows[m].at(0), static_cast<double>(m + 1));
    EXPECT_EQ(mode_rows[m].at(1), frequencies[m]);
  }
  remove_file("outputs_contacts.local");
  remove_file("outputs_modes.local");
}

}    // namespace
