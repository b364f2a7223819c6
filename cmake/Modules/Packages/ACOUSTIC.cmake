# Dependencies of the ACOUSTIC package: Eigen (dense/sparse linear algebra),
# SuiteSparse CHOLMOD + UMFPACK (sparse factorisations), MUMPS (parallel
# sparse symmetric indefinite factorisation, on MPI), Spectra (sparse
# eigensolvers, header only).  This file is included by LAMMPS's CMake build
# when PKG_ACOUSTIC is on (copy it to cmake/Modules/Packages/ACOUSTIC.cmake of
# a LAMMPS tree) and by the stand-alone ACOUSTIC build for its unit tests.
#
# Result: ACOUSTIC_INCLUDE_DIRS, ACOUSTIC_LIBRARIES, and, inside LAMMPS, the
# lammps target linked against them.

find_package(Eigen3 3.3 REQUIRED NO_MODULE)

find_path(ACOUSTIC_SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse
          DOC "Directory with SuiteSparse headers (cholmod.h, umfpack.h)")
find_path(ACOUSTIC_SPECTRA_INCLUDE_DIR Spectra/SymEigsShiftSolver.h
          DOC "Directory with the Spectra headers")
find_path(ACOUSTIC_MUMPS_INCLUDE_DIR dmumps_c.h
          DOC "Directory with the MUMPS C headers (dmumps_c.h, zmumps_c.h)")
set(_acoustic_missing)
foreach(_dir ACOUSTIC_SUITESPARSE_INCLUDE_DIR ACOUSTIC_SPECTRA_INCLUDE_DIR ACOUSTIC_MUMPS_INCLUDE_DIR)
  if(NOT ${_dir})
    list(APPEND _acoustic_missing ${_dir})
  endif()
endforeach()

set(ACOUSTIC_SUITESPARSE_LIBRARIES)
foreach(_lib umfpack cholmod amd camd colamd ccolamd suitesparseconfig)
  find_library(ACOUSTIC_${_lib}_LIBRARY NAMES ${_lib})
  if(ACOUSTIC_${_lib}_LIBRARY)
    list(APPEND ACOUSTIC_SUITESPARSE_LIBRARIES ${ACOUSTIC_${_lib}_LIBRARY})
  else()
    list(APPEND _acoustic_missing lib${_lib})
  endif()
endforeach()
# MUMPS built for MPI (Debian: libmumps-dev), not the sequential libmumps_seq
set(ACOUSTIC_MUMPS_LIBRARIES)
foreach(_lib dmumps zmumps mumps_common)
  find_library(ACOUSTIC_${_lib}_LIBRARY NAMES ${_lib})
  if(ACOUSTIC_${_lib}_LIBRARY)
    list(APPEND ACOUSTIC_MUMPS_LIBRARIES ${ACOUSTIC_${_lib}_LIBRARY})
  else()
    list(APPEND _acoustic_missing lib${_lib})
  endif()
endforeach()
if(TARGET lammps AND NOT PKG_GRANULAR)
  message(FATAL_ERROR "ACOUSTIC package: needs the GRANULAR package (-D PKG_GRANULAR=on), "
    "whose pair style and sub-models it extends")
endif()
if(TARGET lammps)
  # inside LAMMPS: link LAMMPS's own MPI; MUMPS needs a real MPI library, so a
  # serial LAMMPS build (BUILD_MPI off) is refused
  if(NOT BUILD_MPI)
    message(FATAL_ERROR "ACOUSTIC package: needs BUILD_MPI=on (MUMPS factorises with MPI)")
  endif()
  set(_acoustic_mpi MPI::MPI_CXX)
else()
  find_package(MPI REQUIRED COMPONENTS C)
  set(_acoustic_mpi MPI::MPI_C)
endif()
find_package(BLAS REQUIRED)
find_package(LAPACK REQUIRED)

if(_acoustic_missing)
  message(FATAL_ERROR "ACOUSTIC package: missing ${_acoustic_missing}. "
    "Install SuiteSparse, MUMPS and Spectra (Debian: apt-get install libsuitesparse-dev "
    "libmumps-dev libspectra-dev libeigen3-dev) or point CMake to them with -D<VAR>=<path>.")
endif()

set(ACOUSTIC_INCLUDE_DIRS ${ACOUSTIC_SUITESPARSE_INCLUDE_DIR} ${ACOUSTIC_SPECTRA_INCLUDE_DIR}
    ${ACOUSTIC_MUMPS_INCLUDE_DIR})
set(ACOUSTIC_LIBRARIES Eigen3::Eigen ${ACOUSTIC_SUITESPARSE_LIBRARIES} ${ACOUSTIC_MUMPS_LIBRARIES}
    ${_acoustic_mpi} ${LAPACK_LIBRARIES} ${BLAS_LIBRARIES})

if(TARGET lammps)
  target_include_directories(lammps PRIVATE ${ACOUSTIC_INCLUDE_DIRS})
  target_link_libraries(lammps PRIVATE ${ACOUSTIC_LIBRARIES})
endif()
