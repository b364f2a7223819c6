/* ----------------------------------------------------------------------
   ACOUSTIC package numerics: exception type.

   Every function of namespace Acoustic reports invalid input and
   unrecoverable numerical trouble by throwing Acoustic::SolverError.  The
   message says what went wrong and how to fix it, so that an adapter (the
   LAMMPS styles) can print it unchanged in an ERROR or WARNING line.
------------------------------------------------------------------------- */

#ifndef ACOUSTIC_SOLVER_ERROR_H
#define ACOUSTIC_SOLVER_ERROR_H

#include <stdexcept>
#include <string>

namespace Acoustic {

class SolverError : public std::runtime_error {
 public:
  explicit SolverError(const std::string &message) : std::runtime_error(message) {}
};

}    // namespace Acoustic

#endif
