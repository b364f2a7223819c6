# A build of the numerics without the optional MUMPS and Spectra
# (ACOUSTIC_WITH_MUMPS=off, ACOUSTIC_WITH_SPECTRA=off): it must configure and
# compile, and its tests of what needs them must pass (skipped where they
# need them; the refusals and solver auto's fall-back to lu checked).
# Run by CTest: cmake -DSOURCE=<top> -DBINARY=<dir> -P build_without_optional.cmake
foreach(_var SOURCE BINARY)
  if(NOT ${_var})
    message(FATAL_ERROR "build_without_optional.cmake: give -D${_var}=...")
  endif()
endforeach()

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "${what} failed:\n${_out}")
  endif()
  set(step_output "${_out}" PARENT_SCOPE)
endfunction()

run_step("configure" ${CMAKE_COMMAND} -S ${SOURCE} -B ${BINARY} -DACOUSTIC_BUILD_LAMMPS=OFF
         -DACOUSTIC_WITH_MUMPS=OFF -DACOUSTIC_WITH_SPECTRA=OFF -DCMAKE_BUILD_TYPE=Release)
foreach(_said "no MUMPS" "no Spectra")
  string(FIND "${step_output}" "ACOUSTIC: ${_said}" _at)
  if(_at LESS 0)
    message(FATAL_ERROR "the configure step did not say 'ACOUSTIC: ${_said}':\n${step_output}")
  endif()
endforeach()
run_step("build" ${CMAKE_COMMAND} --build ${BINARY} -j 2 --target test_mumps_ldlt test_vibration_modes)
foreach(_test test_mumps_ldlt test_vibration_modes)
  run_step("${_test}" ${BINARY}/unittest/numerics/${_test})
  message("${_test}:\n${step_output}")
endforeach()
