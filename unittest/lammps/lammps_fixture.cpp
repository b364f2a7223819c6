#include "lammps_fixture.h"

#include "atom.h"
#include "force.h"
#include "collective_error.h"
#include "granular_contact_walker.h"
#include "input.h"
#include "library.h"

#include <gtest/gtest.h>
#include <algorithm>
#include <sstream>

namespace AcousticTest {

LammpsInstance::LammpsInstance(MPI_Comm comm)
{
  const char *args[] = {"acoustic_test", "-log", "none", "-echo", "none", "-screen", "none", "-nocite"};
  char **argv = const_cast<char **>(args);
  lmp = new LAMMPS_NS::LAMMPS(sizeof(args) / sizeof(args[0]), argv, comm);
}

LammpsInstance::~LammpsInstance()
{
  delete lmp;
}

void LammpsInstance::command(const std::string &line)
{
  if (line.find('\n') != std::string::npos) commands(line);
  else lmp->input->one(line);
}

void LammpsInstance::commands(const std::string &block)
{
  std::istringstream in(block);
  std::string line;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    lmp->input->one(line);
  }
}

std::vector<double> LammpsInstance::gather(const char *name, int count)
{
  std::vector<double> data(static_cast<std::size_t>(natoms()) * count);
  lammps_gather_atoms(lmp, const_cast<char *>(name), 1, count, data.data());
  return data;
}

long LammpsInstance::natoms() const
{
  return static_cast<long>(lmp->atom->natoms);
}

std::vector<double> allgather(LammpsInstance &L, const std::vector<double> &mine)
{
  MPI_Comm world = L.lmp->world;
  int nprocs;
  MPI_Comm_size(world, &nprocs);
  int n = static_cast<int>(mine.size());
  std::vector<int> counts(nprocs), displs(nprocs, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
  std::vector<double> all(displs[nprocs - 1] + counts[nprocs - 1]);
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE,
                 world);
  return all;
}

std::map<ContactKey, double> broadcast_from_rank0(const std::map<ContactKey, double> &factors)
{
  std::vector<double> packed;
  for (const auto &kv : factors) {
    packed.push_back(static_cast<double>(kv.first.first));
    packed.push_back(static_cast<double>(kv.first.second));
    packed.push_back(kv.second);
  }
  int n = static_cast<int>(packed.size());
  MPI_Bcast(&n, 1, MPI_INT, 0, MPI_COMM_WORLD);
  packed.resize(n);
  MPI_Bcast(packed.data(), n, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  std::map<ContactKey, double> all;
  for (int k = 0; k < n; k += 3) all[ContactKey(long(packed[k]), long(packed[k + 1]))] = packed[k + 2];
  return all;
}

std::vector<LAMMPS_NS::GranularContact> granular_contacts(LammpsInstance &L)
{
  LAMMPS_NS::GranularContactWalker walker(L.lmp, "test");
  walker.init(true);    // with the walls of fix wall/gran/region
  std::vector<LAMMPS_NS::GranularContact> contacts;
  LAMMPS_NS::CollectiveError errors(L.lmp);
  walker.collect(contacts, 1, errors);    // group all
  errors.raise(FLERR);
  return contacts;
}

std::map<ContactKey, double> friction_factors(LammpsInstance &L)
{
  std::map<ContactKey, double> result;
  const std::vector<LAMMPS_NS::GranularContact> contacts = granular_contacts(L);
  const auto *tag = L.lmp->atom->tag;
  std::vector<double> mine;
  for (const auto &c : contacts) {
    mine.push_back(static_cast<double>(std::min(tag[c.i], tag[c.j])));
    mine.push_back(static_cast<double>(std::max(tag[c.i], tag[c.j])));
    mine.push_back(LAMMPS_NS::GranularContactWalker::friction_factor(c.factor));
  }
  const std::vector<double> all = allgather(L, mine);
  for (std::size_t k = 0; k < all.size(); k += 3) {
    const ContactKey key(static_cast<long>(all[k]), static_cast<long>(all[k + 1]));
    auto it = result.find(key);
    if (it != result.end())
      // equal up to the rounding of the periodic image's coordinates (the
      // normal enters U_t = |dq - (dq.n) n|, a difference of close numbers)
      EXPECT_NEAR(it->second, all[k + 2], 1e-10) << "two copies of contact " << key.first << "-"
                                                 << key.second << " disagree";
    result[key] = all[k + 2];
  }
  return result;
}

int mpi_rank()
{
  int me;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  return me;
}

int mpi_size()
{
  int n;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

}    // namespace AcousticTest

// every rank runs every test; only rank 0 prints
int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  if (AcousticTest::mpi_rank() != 0) {
    auto &listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  int rc = RUN_ALL_TESTS();
  int rc_all = rc;
  MPI_Allreduce(&rc, &rc_all, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return rc_all;
}
