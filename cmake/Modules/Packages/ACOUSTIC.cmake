# Dependencies of the ACOUSTIC package: Eigen (dense/sparse linear algebra),
# SuiteSparse CHOLMOD + UMFPACK (sparse factorisations), MUMPS (parallel
# sparse symmetric indefinite factorisation, on MPI), Spectra (sparse
# eigensolvers, header only); optional: PETSc with complex scalars (the
# distributed Krylov solver, solver iterative; ACOUSTIC_HAVE_PETSC) and METIS
# (nested-dissection orderings for MUMPS; ACOUSTIC_HAVE_METIS).  This file is included by LAMMPS's CMake build
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
set(ACOUSTIC_DEFINITIONS)

# optional: PETSc built with complex scalars, found through its pkg-config
# file (Debian installs the complex build's under petscdir/petsc-complex;
# ACOUSTIC_PETSC_PKG_CONFIG_DIR points elsewhere)
set(ACOUSTIC_PETSC_PKG_CONFIG_DIR "/usr/lib/petscdir/petsc-complex/lib/pkgconfig" CACHE PATH
    "Directory of the pkg-config file petsc.pc of a PETSc built with complex scalars")
option(ACOUSTIC_WITH_PETSC "Build the iterative solver of ACOUSTIC (needs complex PETSc)" ON)
if(ACOUSTIC_WITH_PETSC)
  find_package(PkgConfig QUIET)
  if(PKG_CONFIG_FOUND)
    set(_acoustic_pc_path $ENV{PKG_CONFIG_PATH})
    set(ENV{PKG_CONFIG_PATH} "${ACOUSTIC_PETSC_PKG_CONFIG_DIR}:$ENV{PKG_CONFIG_PATH}")
    pkg_check_modules(ACOUSTIC_PETSC QUIET IMPORTED_TARGET GLOBAL petsc)
    set(ENV{PKG_CONFIG_PATH} "${_acoustic_pc_path}")
  endif()
  # complex scalars and 32-bit indices, as petscconf.h says
  set(ACOUSTIC_PETSC_IS_COMPLEX OFF)
  if(ACOUSTIC_PETSC_FOUND)
    find_file(_acoustic_petscconf petscconf.h PATHS ${ACOUSTIC_PETSC_INCLUDE_DIRS} NO_DEFAULT_PATH)
    if(_acoustic_petscconf)
      file(STRINGS ${_acoustic_petscconf} _complex REGEX "^#define PETSC_USE_COMPLEX 1")
      file(STRINGS ${_acoustic_petscconf} _index64 REGEX "^#define PETSC_USE_64BIT_INDICES 1")
      if(_complex AND NOT _index64)
        set(ACOUSTIC_PETSC_IS_COMPLEX ON)
      endif()
    endif()
    unset(_acoustic_petscconf CACHE)
  endif()
  if(ACOUSTIC_PETSC_FOUND AND ACOUSTIC_PETSC_IS_COMPLEX)
    message(STATUS "ACOUSTIC: PETSc ${ACOUSTIC_PETSC_VERSION} (complex): solver iterative available")
    list(APPEND ACOUSTIC_LIBRARIES PkgConfig::ACOUSTIC_PETSC)
    list(APPEND ACOUSTIC_DEFINITIONS ACOUSTIC_HAVE_PETSC)
  else()
    message(STATUS "ACOUSTIC: no PETSc with complex scalars (Debian: libpetsc-complex-dev): "
      "built without solver iterative")
  endif()
endif()

# optional: METIS, the nested-dissection ordering of the MUMPS factorisations in 3D
find_path(ACOUSTIC_METIS_INCLUDE_DIR metis.h DOC "Directory with metis.h")
find_library(ACOUSTIC_METIS_LIBRARY NAMES metis)
if(ACOUSTIC_METIS_INCLUDE_DIR AND ACOUSTIC_METIS_LIBRARY)
  message(STATUS "ACOUSTIC: METIS orderings for MUMPS available")
  list(APPEND ACOUSTIC_INCLUDE_DIRS ${ACOUSTIC_METIS_INCLUDE_DIR})
  list(APPEND ACOUSTIC_LIBRARIES ${ACOUSTIC_METIS_LIBRARY})
  list(APPEND ACOUSTIC_DEFINITIONS ACOUSTIC_HAVE_METIS)
else()
  message(STATUS "ACOUSTIC: no METIS (Debian: libmetis-dev): MUMPS keeps its own orderings")
endif()

if(TARGET lammps)
  target_include_directories(lammps PRIVATE ${ACOUSTIC_INCLUDE_DIRS})
  target_link_libraries(lammps PRIVATE ${ACOUSTIC_LIBRARIES})
  target_compile_definitions(lammps PRIVATE ${ACOUSTIC_DEFINITIONS})
endif()
