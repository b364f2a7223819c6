// Helpers of the integration tests: a quiet LAMMPS instance on MPI_COMM_WORLD
// driven through its C++ interface, and a gtest main that runs under mpirun.
#ifndef ACOUSTIC_TEST_LAMMPS_FIXTURE_H
#define ACOUSTIC_TEST_LAMMPS_FIXTURE_H

#include "lammps.h"

#include <mpi.h>
#include <string>
#include <vector>

namespace AcousticTest {

class LammpsInstance {
 public:
  LammpsInstance();
  ~LammpsInstance();
  LammpsInstance(const LammpsInstance &) = delete;
  LammpsInstance &operator=(const LammpsInstance &) = delete;

  // run one command, or a block of lines
  void command(const std::string &line);
  void commands(const std::string &block);
  // per-atom quantity of all atoms ordered by atom ID, on every rank
  std::vector<double> gather(const char *name, int count);
  // natoms of the system
  long natoms() const;

  LAMMPS_NS::LAMMPS *lmp;
};

int mpi_rank();
int mpi_size();

}    // namespace AcousticTest

#endif
