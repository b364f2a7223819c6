#include "lammps_fixture.h"

#include "atom.h"
#include "input.h"
#include "library.h"

#include <gtest/gtest.h>
#include <sstream>

namespace AcousticTest {

LammpsInstance::LammpsInstance()
{
  const char *args[] = {"acoustic_test", "-log", "none", "-echo", "none", "-screen", "none", "-nocite"};
  char **argv = const_cast<char **>(args);
  lmp = new LAMMPS_NS::LAMMPS(sizeof(args) / sizeof(args[0]), argv, MPI_COMM_WORLD);
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
