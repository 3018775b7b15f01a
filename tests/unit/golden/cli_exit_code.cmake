# cmake -DFIXTURE_WRITER=... -DKARMA_GOLDEN=... -DWORK_DIR=... -DACTUAL=same|perturbed
#       -DEXPECTED_EXIT=N -P cli_exit_code.cmake
# Writes the fixture trajectories with golden_fixture_writer, runs
# `karma-golden compare-trajectory base.txt <ACTUAL>.txt` and checks its exit code.
foreach(var FIXTURE_WRITER KARMA_GOLDEN WORK_DIR ACTUAL EXPECTED_EXIT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "cli_exit_code.cmake: ${var} is not set")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND "${FIXTURE_WRITER}" "${WORK_DIR}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "golden_fixture_writer failed: ${rc}")
endif()

execute_process(COMMAND "${KARMA_GOLDEN}" compare-trajectory "${WORK_DIR}/base.txt" "${WORK_DIR}/${ACTUAL}.txt"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(REMOVE_RECURSE "${WORK_DIR}")
message("${out}${err}")
if(NOT rc STREQUAL "${EXPECTED_EXIT}")
  message(FATAL_ERROR "karma-golden compare-trajectory exited with '${rc}', expected ${EXPECTED_EXIT}")
endif()
