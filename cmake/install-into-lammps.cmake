# Install the ACOUSTIC package into an existing LAMMPS source tree (4 Feb 2025
# or later), for users who build their own LAMMPS with CMake:
#
#   cmake -D LAMMPS_DIR=/path/to/lammps -P cmake/install-into-lammps.cmake
#   cmake -S /path/to/lammps/cmake -B build -D PKG_GRANULAR=on -D PKG_ACOUSTIC=on
#
# It copies src/ACOUSTIC, lib/acoustic and the dependency module, adds ACOUSTIC to the
# package lists of LAMMPS's CMakeLists.txt and applies cmake/patches/*.patch
# (contact histories across write_restart between runs).  Running it again
# refreshes the copy.
if(NOT LAMMPS_DIR OR NOT EXISTS ${LAMMPS_DIR}/cmake/CMakeLists.txt)
  message(FATAL_ERROR "Give the top directory of a LAMMPS source tree: "
    "cmake -D LAMMPS_DIR=/path/to/lammps -P ${CMAKE_CURRENT_LIST_FILE}")
endif()
if(NOT EXISTS ${LAMMPS_DIR}/src/GRANULAR/gran_sub_mod.h)
  message(FATAL_ERROR "${LAMMPS_DIR} is older than LAMMPS 4 Feb 2025 (no granular sub-models); "
    "ACOUSTIC needs 4 Feb 2025 or later")
endif()
get_filename_component(_top ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
include(${CMAKE_CURRENT_LIST_DIR}/AcousticOverlayTree.cmake)
file(COPY ${_top}/src/ACOUSTIC DESTINATION ${LAMMPS_DIR}/src)
file(COPY ${_top}/lib/acoustic DESTINATION ${LAMMPS_DIR}/lib)
file(COPY ${_top}/cmake/Modules/Packages/ACOUSTIC.cmake
     DESTINATION ${LAMMPS_DIR}/cmake/Modules/Packages)
acoustic_patch_lammps_cmake(${LAMMPS_DIR}/cmake)
file(GLOB _patches ${_top}/cmake/patches/*.patch)
foreach(_patch ${_patches})
  acoustic_apply_patch(${_patch} ${LAMMPS_DIR} "")
endforeach()
message(STATUS "ACOUSTIC installed into ${LAMMPS_DIR}; configure LAMMPS with -D PKG_ACOUSTIC=on")
