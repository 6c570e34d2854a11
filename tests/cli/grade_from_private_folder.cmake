# The graders' programs in a folder only their owner may enter (a checkout under /root, a 0700
# home): run as root, the stage server's own uid cannot enter it, and the judge must still grade
# rather than lose every call to "Permission denied" - and must not give the server uid 0 instead,
# which the kernel exempts from the process limit (a fork bomb then takes the machine: it did).
# The server keeps its own uid plus CAP_DAC_READ_SEARCH; --verbose names the sandbox.
# Variables: BIN (the folder of autograder-reference and its stage server), WORK.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/private")
file(CHMOD "${WORK}/private" DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
file(COPY "${BIN}/" DESTINATION "${WORK}/private/bin" USE_SOURCE_PERMISSIONS)
execute_process(COMMAND "${WORK}/private/bin/autograder-reference" --stage 01 --verbose --output "${WORK}/out"
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT status EQUAL 0 OR NOT output MATCHES "01_camera_rays +20/20" OR output MATCHES "Permission denied")
  message(FATAL_ERROR "grading from a private folder failed (exit ${status}):\n${output}\n${errors}")
endif()
execute_process(COMMAND id -u OUTPUT_VARIABLE uid OUTPUT_STRIP_TRAILING_WHITESPACE)
if(uid STREQUAL "0" AND NOT output MATCHES "stage code ran sandboxed: its own user id[^\n]*CAP_DAC_READ_SEARCH")
  message(FATAL_ERROR "as root, the stage server must run under its own user id (never uid 0, which has no process limit):\n${output}")
endif()
