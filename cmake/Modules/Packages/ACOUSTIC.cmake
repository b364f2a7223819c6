# Dependencies of the ACOUSTIC package.  This file is included by LAMMPS's
# CMake build when PKG_ACOUSTIC is on (copy it to
# cmake/Modules/Packages/ACOUSTIC.cmake of a LAMMPS tree, and lib/acoustic to
# the tree's lib/) and by the stand-alone ACOUSTIC build for its unit tests.
#
# Required:
#   Eigen3       dense and sparse linear algebra (header only).  Inside LAMMPS
#                found as the MACHDYN package finds it, or downloaded with
#                -D DOWNLOAD_EIGEN3=on (LAMMPS's own tarball and checksum)
#   SuiteSparse  UMFPACK (solver lu, and auto without MUMPS) and CHOLMOD
#                (solver ldlt, the shift-invert of method lanczos)
#   MPI, BLAS, LAPACK
# Optional, each with a switch (on by default; off, or not found: the
# package is built without it, and the keywords that need it stop the
# input with an ERROR that says so):
#   ACOUSTIC_WITH_MUMPS    MUMPS (Debian: libmumps-dev): solver mumps, and
#                          solver auto's LDL^T (without it auto is lu)
#   ACOUSTIC_WITH_SPECTRA  Spectra (Debian: libspectra-dev): compute
#                          vibration/modes method lanczos
#   ACOUSTIC_WITH_PETSC    PETSc with complex scalars (Debian:
#                          libpetsc-complex-dev): solver iterative
#   METIS (found when present; Debian: libmetis-dev): the nested-dissection
#                          ordering of the MUMPS factorisations (ordering metis)
#
# Result: ACOUSTIC_INCLUDE_DIRS, ACOUSTIC_LIBRARIES, ACOUSTIC_DEFINITIONS
# (ACOUSTIC_HAVE_MUMPS, _SPECTRA, _PETSC, _METIS), and, inside LAMMPS, the
# static library of the numerics (target acoustic, from lib/acoustic, with
# those dependencies) linked into the lammps target.

set(ACOUSTIC_INCLUDE_DIRS)
set(ACOUSTIC_LIBRARIES)
set(ACOUSTIC_DEFINITIONS)
set(_acoustic_missing)

if(TARGET lammps)
  find_package(Eigen3 3.3 NO_MODULE QUIET)
  if(EIGEN3_FOUND)
    set(DOWNLOAD_EIGEN3_DEFAULT OFF)
  else()
    set(DOWNLOAD_EIGEN3_DEFAULT ON)
  endif()
  option(DOWNLOAD_EIGEN3 "Download Eigen3 instead of using an already installed one" ${DOWNLOAD_EIGEN3_DEFAULT})
  if(DOWNLOAD_EIGEN3 AND NOT TARGET LAMMPS::EIGEN3)
    # as LAMMPS's MACHDYN package does (the same URL and checksum variables)
    set(EIGEN3_URL "${LAMMPS_THIRDPARTY_URL}/eigen-3.4.0.tar.gz" CACHE STRING "URL for Eigen3 tarball")
    set(EIGEN3_MD5 "4c527a9171d71a72a9d4186e65bea559" CACHE STRING "MD5 checksum of Eigen3 tarball")
    mark_as_advanced(EIGEN3_URL EIGEN3_MD5)
    include(ExternalProject)
    ExternalProject_Add(Eigen3_build URL ${EIGEN3_URL} URL_MD5 ${EIGEN3_MD5}
      CONFIGURE_COMMAND "" BUILD_COMMAND "" INSTALL_COMMAND "")
    ExternalProject_get_property(Eigen3_build SOURCE_DIR)
    add_library(LAMMPS::EIGEN3 INTERFACE IMPORTED)
    set_target_properties(LAMMPS::EIGEN3 PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${SOURCE_DIR}")
    add_dependencies(LAMMPS::EIGEN3 Eigen3_build)
  endif()
  if(DOWNLOAD_EIGEN3)
    list(APPEND ACOUSTIC_LIBRARIES LAMMPS::EIGEN3)
  elseif(EIGEN3_FOUND)
    list(APPEND ACOUSTIC_LIBRARIES Eigen3::Eigen)
  else()
    message(FATAL_ERROR "ACOUSTIC package: Eigen3 not found; help CMake find it with Eigen3_DIR, "
      "or set DOWNLOAD_EIGEN3=on to download it (Debian: apt-get install libeigen3-dev)")
  endif()
else()
  find_package(Eigen3 3.3 REQUIRED NO_MODULE)
  list(APPEND ACOUSTIC_LIBRARIES Eigen3::Eigen)
endif()

find_path(ACOUSTIC_SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse
          DOC "Directory with SuiteSparse headers (cholmod.h, umfpack.h)")
if(NOT ACOUSTIC_SUITESPARSE_INCLUDE_DIR)
  list(APPEND _acoustic_missing ACOUSTIC_SUITESPARSE_INCLUDE_DIR)
endif()
set(ACOUSTIC_SUITESPARSE_LIBRARIES)
foreach(_lib umfpack cholmod amd camd colamd ccolamd suitesparseconfig)
  find_library(ACOUSTIC_${_lib}_LIBRARY NAMES ${_lib})
  if(ACOUSTIC_${_lib}_LIBRARY)
    list(APPEND ACOUSTIC_SUITESPARSE_LIBRARIES ${ACOUSTIC_${_lib}_LIBRARY})
  else()
    list(APPEND _acoustic_missing lib${_lib})
  endif()
endforeach()
list(APPEND ACOUSTIC_INCLUDE_DIRS ${ACOUSTIC_SUITESPARSE_INCLUDE_DIR})
list(APPEND ACOUSTIC_LIBRARIES ${ACOUSTIC_SUITESPARSE_LIBRARIES})

# optional: MUMPS built for MPI (Debian: libmumps-dev), not the sequential libmumps_seq
option(ACOUSTIC_WITH_MUMPS "Build solver mumps of ACOUSTIC (and MUMPS's LDL^T in solver auto)" ON)
set(_acoustic_mumps_found)
if(ACOUSTIC_WITH_MUMPS)
  find_path(ACOUSTIC_MUMPS_INCLUDE_DIR dmumps_c.h
            DOC "Directory with the MUMPS C headers (dmumps_c.h, zmumps_c.h)")
  set(ACOUSTIC_MUMPS_LIBRARIES)
  set(_acoustic_mumps_found ${ACOUSTIC_MUMPS_INCLUDE_DIR})
  foreach(_lib dmumps zmumps mumps_common)
    find_library(ACOUSTIC_${_lib}_LIBRARY NAMES ${_lib})
    if(ACOUSTIC_${_lib}_LIBRARY)
      list(APPEND ACOUSTIC_MUMPS_LIBRARIES ${ACOUSTIC_${_lib}_LIBRARY})
    else()
      set(_acoustic_mumps_found)
    endif()
  endforeach()
endif()
if(_acoustic_mumps_found)
  message(STATUS "ACOUSTIC: MUMPS: solver mumps available, solver auto factorises with MUMPS")
  list(APPEND ACOUSTIC_INCLUDE_DIRS ${ACOUSTIC_MUMPS_INCLUDE_DIR})
  list(APPEND ACOUSTIC_LIBRARIES ${ACOUSTIC_MUMPS_LIBRARIES})
  list(APPEND ACOUSTIC_DEFINITIONS ACOUSTIC_HAVE_MUMPS)
else()
  message(STATUS "ACOUSTIC: no MUMPS (ACOUSTIC_WITH_MUMPS off, or not found; Debian: "
    "libmumps-dev): built without solver mumps, solver auto is lu")
endif()

# optional: Spectra (header only), the Lanczos eigensolver of compute vibration/modes
option(ACOUSTIC_WITH_SPECTRA "Build method lanczos of compute vibration/modes (Spectra)" ON)
if(ACOUSTIC_WITH_SPECTRA)
  find_path(ACOUSTIC_SPECTRA_INCLUDE_DIR Spectra/SymEigsShiftSolver.h
            DOC "Directory with the Spectra headers")
endif()
if(ACOUSTIC_WITH_SPECTRA AND ACOUSTIC_SPECTRA_INCLUDE_DIR)
  message(STATUS "ACOUSTIC: Spectra: method lanczos available")
  list(APPEND ACOUSTIC_INCLUDE_DIRS ${ACOUSTIC_SPECTRA_INCLUDE_DIR})
  list(APPEND ACOUSTIC_DEFINITIONS ACOUSTIC_HAVE_SPECTRA)
else()
  message(STATUS "ACOUSTIC: no Spectra (ACOUSTIC_WITH_SPECTRA off, or not found; Debian: "
    "libspectra-dev): built without method lanczos")
endif()

if(TARGET lammps AND NOT PKG_GRANULAR)
  message(FATAL_ERROR "ACOUSTIC package: needs the GRANULAR package (-D PKG_GRANULAR=on), "
    "whose pair style and sub-models it extends")
endif()
if(TARGET lammps)
  # inside LAMMPS: link LAMMPS's own MPI; the solvers need a real MPI library, so a
  # serial LAMMPS build (BUILD_MPI off) is refused
  if(NOT BUILD_MPI)
    message(FATAL_ERROR "ACOUSTIC package: needs BUILD_MPI=on (its distributed solves and MUMPS use MPI)")
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
    "Install SuiteSparse (Debian: apt-get install libsuitesparse-dev) or point CMake to it "
    "with -D<VAR>=<path>.")
endif()
list(APPEND ACOUSTIC_LIBRARIES ${_acoustic_mpi} ${LAPACK_LIBRARIES} ${BLAS_LIBRARIES})

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
  # the numerics: the library lib/acoustic (no LAMMPS include, shared with the
  # LIGGGHTS front end), built as LAMMPS builds its other package libraries
  file(GLOB ACOUSTIC_LIB_SOURCES CONFIGURE_DEPENDS ${LAMMPS_LIB_SOURCE_DIR}/acoustic/[^.]*.cpp)
  add_library(acoustic STATIC ${ACOUSTIC_LIB_SOURCES})
  set_target_properties(acoustic PROPERTIES OUTPUT_NAME lammps_acoustic${LAMMPS_MACHINE})
  target_include_directories(acoustic PUBLIC ${LAMMPS_LIB_SOURCE_DIR}/acoustic ${ACOUSTIC_INCLUDE_DIRS})
  target_compile_definitions(acoustic PUBLIC ${ACOUSTIC_DEFINITIONS})
  target_link_libraries(acoustic PUBLIC ${ACOUSTIC_LIBRARIES})
  target_link_libraries(lammps PRIVATE acoustic)
endif()
