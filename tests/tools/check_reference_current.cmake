# The checked-in reference data must be what the solutions produce now: regenerate into WORK
# and compare with autograder-regenerate --check (numbers to a few float ulps, images pixel by
# pixel: C libraries differ in their last bits). Variables: REGENERATE, REFERENCE, WORK.
cmake_minimum_required(VERSION 3.19)
file(REMOVE_RECURSE "${WORK}")
execute_process(COMMAND "${REGENERATE}" --output "${WORK}" --check "${REFERENCE}"
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${errors}")
endif()
message(STATUS "${output}")
