# cmake -DGRADER=<the student's autograder> -DWORK=<dir> -P stale_grader.cmake
# The student's grader warns when a file under assignments/ is newer than its stage server (a
# failed build leaves the old one, which grades the old code), naming the files; as built, it
# does not. The stale grader is a copy whose stage server is dated 2001 (Linux `touch -d`).
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
get_filename_component(folder "${GRADER}" DIRECTORY)
get_filename_component(name "${GRADER}" NAME)
file(GLOB modules "${folder}/*.so")
file(COPY "${GRADER}" "${GRADER}-stage-server" ${modules} DESTINATION "${WORK}")
set(warning "changed after this grader was built")

execute_process(COMMAND "${GRADER}" --stage 01_camera_rays --output "${WORK}/fresh" WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
if(err MATCHES "${warning}")
  message(FATAL_ERROR "the grader as built warns that it is stale:\n${err}")
endif()

execute_process(COMMAND touch -d "2001-01-01" "${WORK}/${name}-stage-server" RESULT_VARIABLE touched)
if(NOT touched EQUAL 0)
  message(FATAL_ERROR "could not date the copied stage server")
endif()
execute_process(COMMAND "${WORK}/${name}" --stage 01_camera_rays --output "${WORK}/stale" WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT err MATCHES "assignments/01_camera_rays/camera_rays.cpp[^\n]*${warning}")
  message(FATAL_ERROR "the stale grader (exit status ${status}) does not name the newer stage file:\n${err}")
endif()
