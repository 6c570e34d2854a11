# cmake -DPROGRAM=raylab-reference -DSCENE=whitted.json -DOUTPUT_DIR=dir -P image_io_loading.cmake
# OpenImageIO is loaded only to write an EXR file, read an image or compare images
# (framework/src/image_io/):
#  1. `--help` does not load it (the glibc loader's LD_DEBUG=libs lists every library it maps);
#  2. a render that writes a .png or a .ppm does not load it, nor start loading it beside the
#     render (libpng writes the one, the framework the other);
#  3. a render that writes an .exr does load it (so checks 1 and 2 can see it when it is there);
#  4. pointed at a module that is not there (RAYLAB_IMAGE_IO_MODULE), a render to .exr fails with
#     a message naming the module, exit status 1 (never a crash); one to .png does not need it.
function(run_with_loader_log result_var)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env LD_DEBUG=libs ${ARGN}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${ARGN}: exit status ${status}\n${out}\n${err}")
  endif()
  set(${result_var} "${err}" PARENT_SCOPE)
endfunction()

run_with_loader_log(help_log ${PROGRAM} --help)
if(help_log MATCHES "libOpenImageIO")
  message(FATAL_ERROR "`${PROGRAM} --help` loaded OpenImageIO, which only image I/O needs")
endif()
if(NOT help_log MATCHES "libc\\.so")
  message(FATAL_ERROR "LD_DEBUG=libs printed no library at all: this check cannot see loading")
endif()

foreach(format png ppm)
  set(image ${OUTPUT_DIR}/image_io_loading.${format})
  file(REMOVE ${image})
  run_with_loader_log(render_log ${PROGRAM} render ${SCENE} -o ${image} --width 16 --height 12 -q)
  if(render_log MATCHES "[^\n]*(OpenImageIO|raylab_image_io)[^\n]*" OR NOT EXISTS ${image})
    message(FATAL_ERROR "a render to ${image} loaded the image module or OpenImageIO, or wrote no image: ${CMAKE_MATCH_0}")
  endif()
endforeach()

set(image ${OUTPUT_DIR}/image_io_loading.exr)
file(REMOVE ${image})
run_with_loader_log(render_log ${PROGRAM} render ${SCENE} -o ${image} --width 16 --height 12 -q)
if(NOT render_log MATCHES "libOpenImageIO" OR NOT EXISTS ${image})
  message(FATAL_ERROR "a render to ${image} did not load OpenImageIO or wrote no image")
endif()

set(missing ${OUTPUT_DIR}/no_such_folder/libraylab_image_io.so)
execute_process(COMMAND ${CMAKE_COMMAND} -E env RAYLAB_IMAGE_IO_MODULE=${missing}
                        ${PROGRAM} render ${SCENE} -o ${OUTPUT_DIR}/image_io_missing.exr --width 16 --height 12 -q
                RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 1 OR NOT err MATCHES "cannot load the OpenImageIO module .*no_such_folder")
  message(FATAL_ERROR "without its image module: expected exit 1 naming the module, got ${status}: ${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env RAYLAB_IMAGE_IO_MODULE=${missing}
                        ${PROGRAM} render ${SCENE} -o ${OUTPUT_DIR}/image_io_missing.png --width 16 --height 12 -q
                RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "without its image module, a render to .png: expected exit 0, got ${status}: ${err}")
endif()
message(STATUS "ok: OpenImageIO loaded only for EXR files, never for .png or .ppm; a missing module is named")
