# The graders' programs in a folder only their owner may enter (a checkout under /root, a 0700
# home): run as root, the judge cannot hand the stage server its own uid there, and must still
# grade (keeping the judge's uid for the server) rather than lose every call to "Permission denied".
# Variables: BIN (the folder of autograder-reference and its stage server), WORK.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/private")
file(CHMOD "${WORK}/private" DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
file(COPY "${BIN}/" DESTINATION "${WORK}/private/bin" USE_SOURCE_PERMISSIONS)
execute_process(COMMAND "${WORK}/private/bin/autograder-reference" --stage 01 --output "${WORK}/out"
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT status EQUAL 0 OR NOT output MATCHES "01_camera_rays +20/20" OR output MATCHES "Permission denied")
  message(FATAL_ERROR "grading from a private folder failed (exit ${status}):\n${output}\n${errors}")
endif()
