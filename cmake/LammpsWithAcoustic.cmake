# Build LAMMPS from LAMMPS_SOURCE_DIR with MPI, GRANULAR and ACOUSTIC, as an
# external project of this build.  The LAMMPS tree is not modified: a thin
# overlay tree in the build directory links to it, holds a patched copy of its
# cmake/ directory and of the files that cmake/patches/*.patch change, and
# links src/ACOUSTIC and lib/acoustic to this repository's package and library.
include(ExternalProject)
include(${CMAKE_CURRENT_LIST_DIR}/AcousticOverlayTree.cmake)

if(NOT EXISTS ${LAMMPS_SOURCE_DIR}/cmake/CMakeLists.txt OR NOT EXISTS ${LAMMPS_SOURCE_DIR}/src/GRANULAR/gran_sub_mod.h)
  message(FATAL_ERROR "LAMMPS_SOURCE_DIR='${LAMMPS_SOURCE_DIR}' is not a LAMMPS source tree of "
    "4 Feb 2025 or later (expected cmake/CMakeLists.txt and src/GRANULAR/gran_sub_mod.h). Run "
    "./run.sh, which fetches Debian's LAMMPS source, or pass -D LAMMPS_SOURCE_DIR=/path/to/lammps.")
endif()

set(ACOUSTIC_LAMMPS_TREE ${CMAKE_BINARY_DIR}/lammps-tree)
set(ACOUSTIC_LAMMPS_BUILD ${CMAKE_BINARY_DIR}/lammps)

# lib was a link to LAMMPS's lib/ in build trees made before lib/acoustic existed
if(IS_SYMLINK ${ACOUSTIC_LAMMPS_TREE}/lib)
  file(REMOVE ${ACOUSTIC_LAMMPS_TREE}/lib)
endif()
file(MAKE_DIRECTORY ${ACOUSTIC_LAMMPS_TREE}/src ${ACOUSTIC_LAMMPS_TREE}/lib)
file(GLOB _entries RELATIVE ${LAMMPS_SOURCE_DIR} ${LAMMPS_SOURCE_DIR}/*)
foreach(_e ${_entries})
  if(NOT _e STREQUAL "cmake" AND NOT _e STREQUAL "src" AND NOT _e STREQUAL "lib")
    _acoustic_link(${LAMMPS_SOURCE_DIR}/${_e} ${ACOUSTIC_LAMMPS_TREE}/${_e})
  endif()
endforeach()
foreach(_sub src lib)
  file(GLOB _entries RELATIVE ${LAMMPS_SOURCE_DIR}/${_sub} ${LAMMPS_SOURCE_DIR}/${_sub}/*)
  foreach(_e ${_entries})
    _acoustic_link(${LAMMPS_SOURCE_DIR}/${_sub}/${_e} ${ACOUSTIC_LAMMPS_TREE}/${_sub}/${_e})
  endforeach()
endforeach()
_acoustic_link(${PROJECT_SOURCE_DIR}/src/ACOUSTIC ${ACOUSTIC_LAMMPS_TREE}/src/ACOUSTIC)
_acoustic_link(${PROJECT_SOURCE_DIR}/lib/acoustic ${ACOUSTIC_LAMMPS_TREE}/lib/acoustic)
if(NOT EXISTS ${ACOUSTIC_LAMMPS_TREE}/cmake/CMakeLists.txt)
  file(COPY ${LAMMPS_SOURCE_DIR}/cmake DESTINATION ${ACOUSTIC_LAMMPS_TREE})
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/Modules/Packages/ACOUSTIC.cmake
               ${ACOUSTIC_LAMMPS_TREE}/cmake/Modules/Packages/ACOUSTIC.cmake COPYONLY)
acoustic_patch_lammps_cmake(${ACOUSTIC_LAMMPS_TREE}/cmake)
file(GLOB _patches ${PROJECT_SOURCE_DIR}/cmake/patches/*.patch)
foreach(_patch ${_patches})
  acoustic_apply_patch(${_patch} ${ACOUSTIC_LAMMPS_TREE} ${LAMMPS_SOURCE_DIR})
endforeach()

# a new or removed file in src/ACOUSTIC changes the style headers, one in
# lib/acoustic the library's sources: reconfigure LAMMPS
file(GLOB _pkg_files CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/ACOUSTIC/*.cpp
     ${PROJECT_SOURCE_DIR}/src/ACOUSTIC/*.h ${PROJECT_SOURCE_DIR}/lib/acoustic/*.cpp
     ${PROJECT_SOURCE_DIR}/lib/acoustic/*.h)
string(MD5 _pkg_files_hash "${_pkg_files}")

ExternalProject_Add(lammps
  SOURCE_DIR ${ACOUSTIC_LAMMPS_TREE}/cmake
  BINARY_DIR ${ACOUSTIC_LAMMPS_BUILD}
  CMAKE_ARGS --no-warn-unused-cli -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}
             "-DCMAKE_C_FLAGS_RELEASE=${CMAKE_C_FLAGS_RELEASE}"
             "-DCMAKE_CXX_FLAGS_RELEASE=${CMAKE_CXX_FLAGS_RELEASE}"
             -DBUILD_MPI=on -DBUILD_SHARED_LIBS=on -DBUILD_OMP=off
             -DPKG_GRANULAR=on -DPKG_ACOUSTIC=on
             -DACOUSTIC_PACKAGE_FILES=${_pkg_files_hash}
  INSTALL_COMMAND ""
  BUILD_ALWAYS TRUE
  USES_TERMINAL_BUILD TRUE)

set(ACOUSTIC_LMP ${ACOUSTIC_LAMMPS_BUILD}/lmp)
set(ACOUSTIC_LIBLAMMPS_DIR ${ACOUSTIC_LAMMPS_BUILD})
set(ACOUSTIC_LAMMPS_PYTHON ${ACOUSTIC_LAMMPS_TREE}/python)
