# cmake -DPROGRAM=raylab-reference -DSCENE=scene.json -DOUTPUT_DIR=dir [-DINTEGRATOR=path] [-DROULETTE=auto]
#       -P threads_identical.cmake
# Renders SCENE with --threads 1 and --threads 2, at 1 and at 4 samples per pixel, and fails
# unless the two PNG files of each sample count are byte-identical: each pixel must depend
# only on the scene and the sample count, never on which thread drew it. INTEGRATOR (default
# the renderer's) is passed as --integrator, ROULETTE (default none) as --roulette; then the
# 4-spp picture must also differ from one rendered without --roulette (else it did nothing).
set(integrator_arguments "")
if(INTEGRATOR)
  set(integrator_arguments --integrator ${INTEGRATOR})
endif()
set(without_roulette ${integrator_arguments})
if(ROULETTE)
  list(APPEND integrator_arguments --roulette ${ROULETTE})
endif()
foreach(spp 1 4)
  foreach(threads 1 2)
    set(image "${OUTPUT_DIR}/threads_${threads}_spp_${spp}.png")
    file(REMOVE "${image}")
    execute_process(
      COMMAND "${PROGRAM}" render "${SCENE}" -o "${image}" --width 160 --height 120 -q --threads ${threads}
              --spp ${spp} ${integrator_arguments}
      RESULT_VARIABLE status ERROR_VARIABLE err)
    if(NOT status EQUAL 0 OR NOT EXISTS "${image}")
      message(FATAL_ERROR "--threads ${threads} --spp ${spp}: exit status ${status}, no ${image}\nstderr: ${err}")
    endif()
  endforeach()
  execute_process(
    COMMAND "${CMAKE_COMMAND}" -E compare_files "${OUTPUT_DIR}/threads_1_spp_${spp}.png"
            "${OUTPUT_DIR}/threads_2_spp_${spp}.png"
    RESULT_VARIABLE different)
  if(NOT different EQUAL 0)
    message(FATAL_ERROR "--spp ${spp}: --threads 1 and --threads 2 wrote different files: "
                        "${OUTPUT_DIR}/threads_1_spp_${spp}.png and ${OUTPUT_DIR}/threads_2_spp_${spp}.png")
  endif()
endforeach()
# The anti-aliased picture must differ from the 1-spp one (else --spp did nothing).
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E compare_files "${OUTPUT_DIR}/threads_1_spp_1.png" "${OUTPUT_DIR}/threads_1_spp_4.png"
  RESULT_VARIABLE spp_changed)
if(spp_changed EQUAL 0)
  message(FATAL_ERROR "--spp 4 wrote the same file as --spp 1: no anti-aliasing")
endif()
if(ROULETTE)
  set(image "${OUTPUT_DIR}/no_roulette_spp_4.png")
  execute_process(
    COMMAND "${PROGRAM}" render "${SCENE}" -o "${image}" --width 160 --height 120 -q --threads 1 --spp 4
            ${without_roulette}
    RESULT_VARIABLE status ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "without --roulette: exit status ${status}\nstderr: ${err}")
  endif()
  execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${image}" "${OUTPUT_DIR}/threads_1_spp_4.png"
                  RESULT_VARIABLE roulette_changed)
  if(roulette_changed EQUAL 0)
    message(FATAL_ERROR "--roulette ${ROULETTE} wrote the same file as no roulette: it did nothing")
  endif()
endif()
message(STATUS "ok: --threads 1 and --threads 2 give identical PNG files at --spp 1 and --spp 4")
