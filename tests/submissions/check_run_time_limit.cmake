# cmake -DGRADER=JUDGE -DSERVER=STAGE_SERVER -DWORK=DIR -P check_run_time_limit.cmake
# The whole run's time limit (autograder --run-timeout; run_autograder sets it from the time
# Gradescope gives a submission, so that results.json is written before the service stops the
# run): a stage 03 that loops forever meets a limit of 12 s there. The judge exits 0, the stages
# it did not reach lose their tests with the limit's name, and results.json is written.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${GRADER} --stage-server ${SERVER} --run-timeout 12 --lang en
                        --json ${WORK}/results.json --output ${WORK}/images
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the judge exited ${status} (expected 0: a grade):\n${out}\n${err}")
endif()
if(NOT out MATCHES "ran past the time limit of the whole grading run")
  message(FATAL_ERROR "no test lost to the run's time limit:\n${out}")
endif()
if(NOT EXISTS ${WORK}/results.json)
  message(FATAL_ERROR "no results.json after the run's time limit")
endif()
file(READ ${WORK}/results.json json)
string(JSON count LENGTH "${json}" tests)
math(EXPR last "${count} - 1")
string(JSON last_name GET "${json}" tests ${last} name)
string(JSON last_score GET "${json}" tests ${last} score)
string(JSON last_output GET "${json}" tests ${last} output)
if(NOT last_score EQUAL 0 OR NOT last_output MATCHES "time limit of the whole grading run")
  message(FATAL_ERROR "the last test, ${last_name}, scored ${last_score}: ${last_output}")
endif()
message(STATUS "the run stopped at its time limit; results.json has ${count} tests, ${last_name} lost to the limit")
