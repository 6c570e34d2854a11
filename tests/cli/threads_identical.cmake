# cmake -DPROGRAM=raylab-reference -DSCENE=scene.json -DOUTPUT_DIR=dir -P threads_identical.cmake
# Renders SCENE with --threads 1 and --threads 2 and fails unless the two PNG files are
# byte-identical: each pixel must depend only on the scene, never on which thread drew it.
foreach(threads 1 2)
  set(image "${OUTPUT_DIR}/threads_${threads}.png")
  file(REMOVE "${image}")
  execute_process(
    COMMAND "${PROGRAM}" render "${SCENE}" -o "${image}" --width 160 --height 120 -q --threads ${threads}
    RESULT_VARIABLE status ERROR_VARIABLE err)
  if(NOT status EQUAL 0 OR NOT EXISTS "${image}")
    message(FATAL_ERROR "--threads ${threads}: exit status ${status}, no ${image}\nstderr: ${err}")
  endif()
endforeach()
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E compare_files "${OUTPUT_DIR}/threads_1.png" "${OUTPUT_DIR}/threads_2.png"
  RESULT_VARIABLE different)
if(NOT different EQUAL 0)
  message(FATAL_ERROR "--threads 1 and --threads 2 wrote different files: "
                      "${OUTPUT_DIR}/threads_1.png and ${OUTPUT_DIR}/threads_2.png")
endif()
message(STATUS "ok: --threads 1 and --threads 2 give identical PNG files")
