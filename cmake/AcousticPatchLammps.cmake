# Teach a LAMMPS CMake tree (29 Sep 2021 layout) about the ACOUSTIC package:
# add it to STANDARD_PACKAGES and to the list of packages whose
# cmake/Modules/Packages/<PKG>.cmake is included.  Idempotent.
function(acoustic_patch_lammps_cmake cmake_dir)
  set(_file ${cmake_dir}/CMakeLists.txt)
  file(READ ${_file} _text)
  if(_text MATCHES "set\\(STANDARD_PACKAGES[ \t\r\n]+ACOUSTIC")
    return()
  endif()
  string(FIND "${_text}" "set(STANDARD_PACKAGES\n" _pos1)
  string(FIND "${_text}" "foreach(PKG_WITH_INCL KSPACE" _pos2)
  if(_pos1 EQUAL -1 OR _pos2 EQUAL -1)
    message(FATAL_ERROR "${_file} does not have the layout of the LAMMPS 29 Sep 2021 "
      "CMake build (STANDARD_PACKAGES, PKG_WITH_INCL); add ACOUSTIC to those lists by hand.")
  endif()
  string(REPLACE "set(STANDARD_PACKAGES\n" "set(STANDARD_PACKAGES\n  ACOUSTIC\n" _text "${_text}")
  string(REPLACE "foreach(PKG_WITH_INCL KSPACE" "foreach(PKG_WITH_INCL ACOUSTIC KSPACE" _text "${_text}")
  file(WRITE ${_file} "${_text}")
endfunction()
