# Functions of the overlay trees in which ACOUSTIC builds LAMMPS and LIGGGHTS
# (cmake/LammpsWithAcoustic.cmake, cmake/LiggghtsWithAcoustic.cmake) and of
# cmake/install-into-lammps.cmake.

# a symbolic link `link` to `target`, unless `link` exists
function(_acoustic_link target link)
  if(NOT EXISTS ${link} AND NOT IS_SYMLINK ${link})
    file(CREATE_LINK ${target} ${link} SYMBOLIC)
  endif()
endfunction()

# Teach a LAMMPS CMake tree (4 Feb 2025 and 4 Jul 2026 layouts) about the
# ACOUSTIC package: add it to STANDARD_PACKAGES and to the list of packages
# whose cmake/Modules/Packages/<PKG>.cmake is included.  Idempotent.
function(acoustic_patch_lammps_cmake cmake_dir)
  set(_file ${cmake_dir}/CMakeLists.txt)
  file(READ ${_file} _text)
  if(_text MATCHES "set\\(STANDARD_PACKAGES[ \t\r\n]+ACOUSTIC")
    return()
  endif()
  # the first foreach(PKG_WITH_INCL ...) includes the modules of the packages
  # whose settings must be known before the library target is configured
  set(_loop "foreach(PKG_WITH_INCL ")
  string(FIND "${_text}" "set(STANDARD_PACKAGES\n" _pos1)
  string(FIND "${_text}" "${_loop}" _pos2)
  if(_pos1 EQUAL -1 OR _pos2 EQUAL -1)
    message(FATAL_ERROR "${_file} does not have the layout of the LAMMPS 4 Feb 2025 "
      "CMake build (STANDARD_PACKAGES, PKG_WITH_INCL); add ACOUSTIC to those lists by hand.")
  endif()
  string(LENGTH "${_loop}" _length)
  math(EXPR _after "${_pos2} + ${_length}")
  string(SUBSTRING "${_text}" 0 ${_after} _head)
  string(SUBSTRING "${_text}" ${_after} -1 _tail)
  set(_text "${_head}ACOUSTIC ${_tail}")
  string(REPLACE "set(STANDARD_PACKAGES\n" "set(STANDARD_PACKAGES\n  ACOUSTIC\n" _text "${_text}")
  file(WRITE ${_file} "${_text}")
endfunction()

# Apply a patch of LAMMPS or LIGGGHTS itself (cmake/patches/*.patch,
# liggghts/patches/*.patch; paths a/src/..., patch -p1) to the tree `tree`.  When `original` names another tree,
# `tree` is an overlay of links to it: the files the patch changes are first
# replaced by copies of their originals.  A stamp in `tree` records the patch,
# so that a second call does nothing and a changed patch is applied afresh.
function(acoustic_apply_patch patch tree original)
  get_filename_component(_name ${patch} NAME)
  file(MD5 ${patch} _md5)
  set(_stamp ${tree}/.acoustic-${_name}.md5)
  if(EXISTS ${_stamp})
    file(READ ${_stamp} _applied)
    if(_applied STREQUAL _md5)
      return()
    endif()
  endif()
  find_program(ACOUSTIC_PATCH_EXECUTABLE patch)
  if(NOT ACOUSTIC_PATCH_EXECUTABLE)
    message(FATAL_ERROR "ACOUSTIC: the program 'patch' is needed to apply ${patch} "
      "(Debian: apt-get install patch)")
  endif()
  if(original)
    file(STRINGS ${patch} _targets REGEX "^\\+\\+\\+ b/")
    foreach(_target ${_targets})
      string(REGEX REPLACE "^\\+\\+\\+ b/([^\t ]+).*" "\\1" _file "${_target}")
      _acoustic_overlay_copy(${tree} ${original} ${_file})
    endforeach()
  endif()
  execute_process(COMMAND ${ACOUSTIC_PATCH_EXECUTABLE} -p1 --forward -i ${patch}
                  WORKING_DIRECTORY ${tree} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out
                  ERROR_VARIABLE _out)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "ACOUSTIC: ${patch} does not apply to the tree ${tree}:\n${_out}")
  endif()
  file(WRITE ${_stamp} ${_md5})
  message(STATUS "ACOUSTIC: applied ${_name} to ${tree}")
endfunction()

# In the overlay `tree` of links to `original`, make `file` a copy of its
# original that can be changed: every directory on its path that is a link
# becomes a directory of links to the original's entries first, so that
# nothing in `original` is ever touched.
function(_acoustic_overlay_copy tree original file)
  get_filename_component(_dir ${file} DIRECTORY)
  string(REPLACE "/" ";" _parts "${_dir}")
  set(_path "")
  foreach(_part ${_parts})
    set(_path "${_path}${_part}")
    if(IS_SYMLINK ${tree}/${_path})
      file(REMOVE ${tree}/${_path})
      file(MAKE_DIRECTORY ${tree}/${_path})
      file(GLOB _entries RELATIVE ${original}/${_path} ${original}/${_path}/*)
      foreach(_e ${_entries})
        file(CREATE_LINK ${original}/${_path}/${_e} ${tree}/${_path}/${_e} SYMBOLIC)
      endforeach()
    endif()
    set(_path "${_path}/")
  endforeach()
  file(REMOVE ${tree}/${file})
  configure_file(${original}/${file} ${tree}/${file} COPYONLY)
endfunction()
