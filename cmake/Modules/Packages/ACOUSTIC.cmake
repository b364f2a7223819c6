# Dependencies of the ACOUSTIC package: Eigen (dense/sparse linear algebra),
# SuiteSparse CHOLMOD + UMFPACK (sparse factorisations), Spectra (sparse
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
set(_acoustic_missing)
foreach(_dir ACOUSTIC_SUITESPARSE_INCLUDE_DIR ACOUSTIC_SPECTRA_INCLUDE_DIR)
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
find_package(BLAS REQUIRED)
find_package(LAPACK REQUIRED)

if(_acoustic_missing)
  message(FATAL_ERROR "ACOUSTIC package: missing ${_acoustic_missing}. "
    "Install SuiteSparse and Spectra (Debian: apt-get install libsuitesparse-dev "
    "libspectra-dev libeigen3-dev) or point CMake to them with -D<VAR>=<path>.")
endif()

set(ACOUSTIC_INCLUDE_DIRS ${ACOUSTIC_SUITESPARSE_INCLUDE_DIR} ${ACOUSTIC_SPECTRA_INCLUDE_DIR})
set(ACOUSTIC_LIBRARIES Eigen3::Eigen ${ACOUSTIC_SUITESPARSE_LIBRARIES}
    ${LAPACK_LIBRARIES} ${BLAS_LIBRARIES})

if(TARGET lammps)
  target_include_directories(lammps PRIVATE ${ACOUSTIC_INCLUDE_DIRS})
  target_link_libraries(lammps PRIVATE ${ACOUSTIC_LIBRARIES})
endif()
