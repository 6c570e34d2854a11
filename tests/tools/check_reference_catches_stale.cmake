# autograder-regenerate --check must fail on stale data: a copy of the reference data with one
# stage-01 ray direction moved by 1e-5 (about 160 float ulps) and one image swapped for another
# stage's must be reported, each file by name, against what the solutions produce now: the folder
# that instructor_reference_data_is_current regenerated (its fixture), compared with --compare.
# Variables: REGENERATE, REFERENCE, REGENERATED, WORK.
cmake_minimum_required(VERSION 3.19)
file(REMOVE_RECURSE "${WORK}")
file(COPY "${REFERENCE}/" DESTINATION "${WORK}/stale")
file(READ "${WORK}/stale/01_camera_rays_cases.json" cases)
string(REGEX MATCH "\"direction\": \\[\n *(-?[0-9]+\\.[0-9]+)" found "${cases}")
if(NOT found)
  message(FATAL_ERROR "no direction in 01_camera_rays_cases.json")
endif()
set(old "${CMAKE_MATCH_1}")
# Change the 5th decimal digit (wrapping 9 to 0 so the length stays the same).
string(REGEX MATCH "^(-?[0-9]+\\.[0-9][0-9][0-9][0-9])([0-9])(.*)$" parts "${old}")
math(EXPR digit "(${CMAKE_MATCH_2} + 1) % 10")
set(new "${CMAKE_MATCH_1}${digit}${CMAKE_MATCH_3}")
string(REPLACE "${old}" "${new}" cases "${cases}")
file(WRITE "${WORK}/stale/01_camera_rays_cases.json" "${cases}")
file(COPY_FILE "${REFERENCE}/02_sphere.png" "${WORK}/stale/05_bvh.png")
if(NOT EXISTS "${REGENERATED}/01_camera_rays_cases.json")
  message(FATAL_ERROR "${REGENERATED} holds no regenerated data (instructor_reference_data_is_current writes it)")
endif()
execute_process(COMMAND "${REGENERATE}" --compare "${REGENERATED}" --check "${WORK}/stale"
                RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE errors)
if(status EQUAL 0)
  message(FATAL_ERROR "--check passed stale reference data (${old} -> ${new}, 05_bvh.png swapped)")
endif()
foreach(name 01_camera_rays_cases.json 05_bvh.png)
  if(NOT errors MATCHES "${name}")
    message(FATAL_ERROR "--check did not name ${name}:\n${errors}")
  endif()
endforeach()
message(STATUS "stale data caught (${old} -> ${new}):\n${errors}")
