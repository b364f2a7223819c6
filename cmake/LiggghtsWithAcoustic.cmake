# Build LIGGGHTS-PUBLIC 3.8.0 from LIGGGHTS_SOURCE_DIR with the ACOUSTIC
# styles for LIGGGHTS (liggghts/), with LIGGGHTS's own make.  As for LAMMPS,
# the source tree is not modified: an overlay tree in the build directory
# holds links to its src/ files, patched copies of the files that
# liggghts/patches/*.patch change, links to liggghts/src/, the contact-model
# whitelist liggghts/style_contact_model.whitelist (LIGGGHTS compiles one
# template instance per listed combination: the short list keeps the build
# short) and the machine makefile MAKE/Makefile.acoustic.  Left out:
# dump_mesh_vtk.* (VTK 6 only; see liggghts/MAKE/Makefile.acoustic.in).
#
# Result: ${ACOUSTIC_LIGGGHTS} (lmp_acoustic) and liblmp_acoustic.so next to it.

include(${CMAKE_CURRENT_LIST_DIR}/AcousticOverlayTree.cmake)

if(NOT EXISTS ${LIGGGHTS_SOURCE_DIR}/src/Make.sh OR NOT EXISTS ${LIGGGHTS_SOURCE_DIR}/src/tangential_model_history.h)
  message(FATAL_ERROR "LIGGGHTS_SOURCE_DIR='${LIGGGHTS_SOURCE_DIR}' is not a LIGGGHTS-PUBLIC 3.8 tree "
    "(expected src/Make.sh and src/tangential_model_history.h). Run ./run.sh, which fetches "
    "Debian's liggghts source, or pass -D LIGGGHTS_SOURCE_DIR=/path/to/LIGGGHTS-PUBLIC.")
endif()
find_program(ACOUSTIC_LIGGGHTS_CXX NAMES mpic++ mpicxx DOC "MPI C++ compiler wrapper for LIGGGHTS")
if(NOT ACOUSTIC_LIGGGHTS_CXX)
  message(FATAL_ERROR "ACOUSTIC: LIGGGHTS is built with an MPI compiler wrapper (mpic++); "
    "none found (Debian: apt-get install libopenmpi-dev)")
endif()

set(ACOUSTIC_LIGGGHTS_TREE ${CMAKE_BINARY_DIR}/liggghts-tree)
set(_src ${ACOUSTIC_LIGGGHTS_TREE}/src)
file(MAKE_DIRECTORY ${_src}/MAKE)

# links to LIGGGHTS's files (its package directories and MAKE/ excepted: the
# build uses no package of LIGGGHTS and a machine makefile of its own)
file(GLOB _entries RELATIVE ${LIGGGHTS_SOURCE_DIR}/src ${LIGGGHTS_SOURCE_DIR}/src/*)
foreach(_e ${_entries})
  if(IS_DIRECTORY ${LIGGGHTS_SOURCE_DIR}/src/${_e} OR _e MATCHES "^dump_mesh_vtk\\.")
    continue()
  endif()
  _acoustic_link(${LIGGGHTS_SOURCE_DIR}/src/${_e} ${_src}/${_e})
endforeach()
file(GLOB _patches ${PROJECT_SOURCE_DIR}/liggghts/patches/*.patch)
foreach(_patch ${_patches})
  acoustic_apply_patch(${_patch} ${ACOUSTIC_LIGGGHTS_TREE} ${LIGGGHTS_SOURCE_DIR})
endforeach()

# the ACOUSTIC styles; a link removed from liggghts/src leaves a dangling link
file(GLOB _styles CONFIGURE_DEPENDS RELATIVE ${PROJECT_SOURCE_DIR}/liggghts/src
     ${PROJECT_SOURCE_DIR}/liggghts/src/*.h ${PROJECT_SOURCE_DIR}/liggghts/src/*.cpp)
foreach(_e ${_styles})
  _acoustic_link(${PROJECT_SOURCE_DIR}/liggghts/src/${_e} ${_src}/${_e})
endforeach()
file(GLOB _links LIST_DIRECTORIES false ${_src}/*)
foreach(_l ${_links})
  if(IS_SYMLINK ${_l} AND NOT EXISTS ${_l})
    file(REMOVE ${_l})
  endif()
endforeach()
configure_file(${PROJECT_SOURCE_DIR}/liggghts/style_contact_model.whitelist
               ${_src}/style_contact_model.whitelist COPYONLY)

# the styles include the C++98 facade of lib/acoustic and link its shared
# library (cmake/AcousticLiggghtsLibrary.cmake), found again at run time
set(ACOUSTIC_LIGGGHTS_INC "-I${PROJECT_SOURCE_DIR}/lib/acoustic")
set(ACOUSTIC_LIGGGHTS_LIB "-L${CMAKE_BINARY_DIR} -lacoustic_liggghts -Wl,-rpath,${CMAKE_BINARY_DIR}")
configure_file(${PROJECT_SOURCE_DIR}/liggghts/MAKE/Makefile.acoustic.in ${_src}/MAKE/Makefile.acoustic @ONLY)

set(ACOUSTIC_LIGGGHTS ${_src}/lmp_acoustic)
# LIGGGHTS's make decides what to rebuild; $(MAKE) passes on the job server
add_custom_target(liggghts ALL
  COMMAND $(MAKE) -C ${_src} acoustic
  COMMENT "Building LIGGGHTS with the ACOUSTIC styles (${ACOUSTIC_LIGGGHTS})")
add_dependencies(liggghts acoustic_liggghts)
