# The judge's own memory limit (--judge-memory-mb): reaching it stops the grading with status 3
# and a plain message, with no score, and no test is failed or lost for it (a test that fails
# for the grader's own bad_alloc would charge the student for the grader's fault). A limit of
# 1 MiB is reached at the first allocation after it is set.
# Variables: BIN (the folder of autograder-reference and its stage server), WORK.
file(REMOVE_RECURSE "${WORK}")
execute_process(COMMAND "${BIN}/autograder-reference" --stage 01 --judge-memory-mb 1 --output "${WORK}/out"
                        --json "${WORK}/results.json"
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT status EQUAL 3 OR NOT errors MATCHES "the grader itself ran out of memory [(]its limit is 1 MiB"
   OR output MATCHES "FAILED|LOST|/20" OR EXISTS "${WORK}/results.json")
  message(FATAL_ERROR "the judge out of its own memory (exit ${status}, expected 3, no score, no results.json):\n"
                      "${output}\n${errors}")
endif()
