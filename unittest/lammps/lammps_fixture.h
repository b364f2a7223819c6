// Helpers of the integration tests: a quiet LAMMPS instance on MPI_COMM_WORLD
// driven through its C++ interface, and a gtest main that runs under mpirun.
#ifndef ACOUSTIC_TEST_LAMMPS_FIXTURE_H
#define ACOUSTIC_TEST_LAMMPS_FIXTURE_H

#include "granular_contact_walker.h"
#include "lammps.h"

#include <mpi.h>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace AcousticTest {

class LammpsInstance {
 public:
  explicit LammpsInstance(MPI_Comm comm = MPI_COMM_WORLD);
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

// the concatenation, over the ranks of the instance, of each rank's values,
// on every rank (rank order)
std::vector<double> allgather(LammpsInstance &L, const std::vector<double> &mine);

// the contacts of pair granular on this rank, as the package's walker reads them
std::vector<LAMMPS_NS::GranularContact> granular_contacts(LammpsInstance &L);

// friction factor of every contact of pair granular in the whole
// system, keyed by (lower atom ID, higher atom ID), on every rank of the
// instance; with newton off the two copies of a contact must agree (checked)
typedef std::pair<long, long> ContactKey;
std::map<ContactKey, double> friction_factors(LammpsInstance &L);

// factors known on rank 0 of MPI_COMM_WORLD (e.g. of a serial instance
// there), on every rank
std::map<ContactKey, double> broadcast_from_rank0(const std::map<ContactKey, double> &factors);

int mpi_rank();
int mpi_size();

}    // namespace AcousticTest

#endif
