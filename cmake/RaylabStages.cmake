# The stage table: stages.json is the one list of stages (docs/instructors.md). This file
# reads it when CMake configures, checks it, and gives the rest of the build:
#   RAYLAB_STAGE_IDS          the ids, in teaching order
#   RAYLAB_STAGE_FILES        the stage files, relative to assignments/ or solutions/
#   RAYLAB_SUITE_FILES        the autograder's suite files, relative to autograder/suites/
#   RAYLAB_CALL_FILES         the stages' calls between judge and stage server, relative to
#                             autograder/suites/ (autograder/runner/stage_call.h)
#   RAYLAB_STAGE_TABLE_SOURCE a generated C++ file holding the table for raylab/stage_table.h
#   RAYLAB_GENERATED_INCLUDE  a folder of generated headers: stage_messages.def, the stages' own
#                             catalogues (autograder/suites/<id>_messages.def, where a stage has
#                             one) in teaching order, which autograder/runner/messages.def includes
#   RAYLAB_GRADER_STAGE_FILES the stage files the grader has its own correct version of, under
#                             autograder/grader_stages/ (every stage some "grader_versions" names)
#   RAYLAB_SERVER_SUFFIXES    one per distinct "grader_versions" list: "-with-grader-07-08" names
#                             the stage server that links the grader's stages 07 and 08 (and the
#                             student's, or the reference's, other stages); its files are
#                             RAYLAB_SERVER_GRADER_FILES<suffix>
#   RAYLAB_SERVER_SUFFIX_OF_<id> one stage's server suffix ("" for the default server)
#
# The stage contract in the build: every stage's functions are declared once in
# framework/include/raylab/stages/ and defined twice, in assignments/ and solutions/, with
# the same file names. A stage library holds one of the two definitions.

set(RAYLAB_STAGE_TABLE ${CMAKE_SOURCE_DIR}/stages.json)
set_property(DIRECTORY ${CMAKE_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${RAYLAB_STAGE_TABLE})
file(READ ${RAYLAB_STAGE_TABLE} raylab_table_text)

# raylab_table_get(OUT WHERE PATH...): the value at PATH, or a fatal error naming WHERE.
macro(raylab_table_get out where)
  string(JSON ${out} ERROR_VARIABLE raylab_table_error GET "${raylab_table_text}" ${ARGN})
  if(raylab_table_error)
    message(FATAL_ERROR "stages.json: ${where}: ${raylab_table_error}")
  endif()
endmacro()
macro(raylab_table_type out where)
  string(JSON ${out} ERROR_VARIABLE raylab_table_error TYPE "${raylab_table_text}" ${ARGN})
  if(raylab_table_error)
    message(FATAL_ERROR "stages.json: ${where}: ${raylab_table_error}")
  endif()
endmacro()

# raylab_table_string_list(OUT WHERE PATH...): a JSON array of strings as a CMake list.
function(raylab_table_string_list out where)
  raylab_table_type(type "${where}" ${ARGN})
  if(NOT type STREQUAL "ARRAY")
    message(FATAL_ERROR "stages.json: ${where} must be an array of strings, not ${type}")
  endif()
  string(JSON count LENGTH "${raylab_table_text}" ${ARGN})
  set(values "")
  if(count GREATER 0)
    math(EXPR last "${count} - 1")
    foreach(i RANGE ${last})
      raylab_table_type(type "${where}" ${ARGN} ${i})
      if(NOT type STREQUAL "STRING")
        message(FATAL_ERROR "stages.json: ${where}[${i}] must be a string, not ${type}")
      endif()
      raylab_table_get(value "${where}" ${ARGN} ${i})
      list(APPEND values "${value}")
    endforeach()
  endif()
  set(${out} "${values}" PARENT_SCOPE)
endfunction()

# A C++ string literal for a value of the table (raw, so that no character needs escaping).
function(raylab_cxx_literal out value)
  if(value MATCHES "\\)stage\"")
    message(FATAL_ERROR "stages.json: the text '${value}' cannot be a C++ raw string")
  endif()
  set(${out} "R\"stage(${value})stage\"" PARENT_SCOPE)
endfunction()
function(raylab_cxx_literal_list out)
  set(items "")
  foreach(value IN LISTS ARGN)
    raylab_cxx_literal(literal "${value}")
    list(APPEND items "${literal}")
  endforeach()
  list(JOIN items ", " joined)
  set(${out} "{${joined}}" PARENT_SCOPE)
endfunction()

raylab_table_type(type "the top level" stages)
if(NOT type STREQUAL "ARRAY")
  message(FATAL_ERROR "stages.json: \"stages\" must be an array")
endif()
string(JSON raylab_stage_count LENGTH "${raylab_table_text}" stages)
if(raylab_stage_count EQUAL 0)
  message(FATAL_ERROR "stages.json: \"stages\" is empty")
endif()
math(EXPR raylab_last_stage "${raylab_stage_count} - 1")

set(RAYLAB_STAGE_IDS "")
set(RAYLAB_STAGE_FILES "")
set(RAYLAB_SUITE_FILES "")
set(RAYLAB_CALL_FILES "")
set(RAYLAB_GRADER_STAGE_FILES "")
set(RAYLAB_SERVER_SUFFIXES "")
set(raylab_short_ids "")
set(raylab_table_entries "")
foreach(index RANGE ${raylab_last_stage})
  set(where "stages[${index}]")
  raylab_table_get(id "${where}" stages ${index} id)
  set(where "stage ${id}")
  if(NOT id MATCHES "^[0-9][0-9][a-z]?_[a-z0-9_]+$")
    message(FATAL_ERROR "stages.json: stages[${index}]: the id \"${id}\" is not NN_name or NNx_name "
                        "(two digits, an optional letter, '_', lower-case words)")
  endif()
  if(id IN_LIST RAYLAB_STAGE_IDS)
    message(FATAL_ERROR "stages.json: the id ${id} appears twice")
  endif()
  string(REGEX REPLACE "_.*" "" short_id "${id}")
  if(short_id IN_LIST raylab_short_ids)
    message(FATAL_ERROR "stages.json: ${id}: another stage already starts with ${short_id}_ (--stage ${short_id} "
                        "must name one stage)")
  endif()
  list(APPEND raylab_short_ids "${short_id}")

  raylab_table_get(title "${where}" stages ${index} title)
  # "title_zh": the title in Simplified Chinese (the grader's table with --lang zh). Optional here
  # so that a new row builds before its translation; the test messages_are_paired asks for it.
  string(JSON title_zh ERROR_VARIABLE title_zh_missing GET "${raylab_table_text}" stages ${index} title_zh)
  if(title_zh_missing)
    set(title_zh "")
  endif()
  raylab_table_get(handout "${where}" stages ${index} handout)
  raylab_table_get(section "${where}" stages ${index} section)
  raylab_table_string_list(files "${where}: \"files\"" stages ${index} files)
  raylab_table_string_list(functions "${where}: \"functions\"" stages ${index} functions)
  raylab_table_string_list(suite "${where}: \"suite\"" stages ${index} suite)
  raylab_table_string_list(calls "${where}: \"calls\"" stages ${index} calls)
  raylab_table_string_list(grader_versions "${where}: \"grader_versions\"" stages ${index} grader_versions)
  raylab_table_string_list(also_runs "${where}: \"also_runs\"" stages ${index} also_runs)
  raylab_table_get(points "${where}" stages ${index} points)
  raylab_table_get(bonus "${where}" stages ${index} bonus)
  raylab_table_type(image_type "${where}" stages ${index} image)
  set(image_scene "")
  set(image_shows "")
  if(image_type STREQUAL "OBJECT")
    raylab_table_get(image_scene "${where}: image" stages ${index} image scene)
    raylab_table_get(image_shows "${where}: image" stages ${index} image shows)
    if(NOT EXISTS ${CMAKE_SOURCE_DIR}/${image_scene})
      message(FATAL_ERROR "stages.json: ${where}: the image test's scene ${image_scene} does not exist")
    endif()
    if(NOT image_shows MATCHES "^(ray_directions|spheres|everything)$")
      message(FATAL_ERROR "stages.json: ${where}: image \"shows\" is \"${image_shows}\"; expected ray_directions, "
                          "spheres or everything (autograder/suites/stage_image_calls.cpp renders these)")
    endif()
  elseif(NOT image_type STREQUAL "NULL")
    message(FATAL_ERROR "stages.json: ${where}: \"image\" must be null or {\"scene\": ..., \"shows\": ...}")
  endif()

  if(title STREQUAL "")
    message(FATAL_ERROR "stages.json: ${where} has an empty title")
  endif()
  if(NOT points MATCHES "^[0-9]+$" OR points EQUAL 0)
    message(FATAL_ERROR "stages.json: ${where}: \"points\" must be a positive whole number, not ${points}")
  endif()
  if(NOT bonus MATCHES "^(ON|OFF)$")  # string(JSON) gives a boolean as ON or OFF
    message(FATAL_ERROR "stages.json: ${where}: \"bonus\" must be true or false")
  endif()
  if(NOT EXISTS ${CMAKE_SOURCE_DIR}/${handout})
    message(FATAL_ERROR "stages.json: ${where}: the handout ${handout} does not exist")
  endif()
  if(NOT files OR NOT functions)
    message(FATAL_ERROR "stages.json: ${where} needs at least one file and one function")
  endif()
  foreach(file IN LISTS files)
    foreach(root assignments solutions)
      if(EXISTS ${CMAKE_SOURCE_DIR}/${root} AND NOT EXISTS ${CMAKE_SOURCE_DIR}/${root}/${file})
        message(FATAL_ERROR "stages.json: ${where}: ${root}/${file} does not exist")
      endif()
    endforeach()
    if(NOT file IN_LIST RAYLAB_STAGE_FILES)
      list(APPEND RAYLAB_STAGE_FILES ${file})
    endif()
  endforeach()
  if(NOT suite)
    message(FATAL_ERROR "stages.json: ${where}: \"suite\" lists no file (its tests live in autograder/suites/)")
  endif()
  foreach(file IN LISTS suite)
    if(NOT EXISTS ${CMAKE_SOURCE_DIR}/autograder/suites/${file})
      message(FATAL_ERROR "stages.json: ${where}: autograder/suites/${file} does not exist")
    endif()
    if(NOT file IN_LIST RAYLAB_SUITE_FILES)
      list(APPEND RAYLAB_SUITE_FILES ${file})
    endif()
  endforeach()
  if(NOT calls)
    message(FATAL_ERROR "stages.json: ${where}: \"calls\" lists no file (how the judge calls its functions in the "
                        "stage server, autograder/suites/NN_name_calls.cpp: see autograder/runner/stage_call.h)")
  endif()
  foreach(file IN LISTS calls)
    if(NOT EXISTS ${CMAKE_SOURCE_DIR}/autograder/suites/${file})
      message(FATAL_ERROR "stages.json: ${where}: autograder/suites/${file} does not exist")
    endif()
    if(NOT file IN_LIST RAYLAB_CALL_FILES)
      list(APPEND RAYLAB_CALL_FILES ${file})
    endif()
  endforeach()
  # "grader_versions": earlier stages whose functions, when this stage is graded, are the grader's
  # own correct versions (autograder/grader_stages/, the same file names), so that a mistake there
  # costs points at its own stage only. Their stage server is NAME-stage-server<suffix>.
  set(server_suffix "")
  set(grader_files "")
  foreach(version IN LISTS grader_versions)
    if(NOT version IN_LIST RAYLAB_STAGE_IDS)
      message(FATAL_ERROR "stages.json: ${where}: \"grader_versions\" names ${version}, which is not an earlier stage")
    endif()
    string(REGEX REPLACE "_.*" "" version_short "${version}")
    if(server_suffix STREQUAL "")
      set(server_suffix "-with-grader")
    endif()
    string(APPEND server_suffix "-${version_short}")
    foreach(file IN LISTS RAYLAB_FILES_OF_${version})
      if(NOT EXISTS ${CMAKE_SOURCE_DIR}/autograder/grader_stages/${file})
        message(FATAL_ERROR "stages.json: ${where}: \"grader_versions\" names ${version}, but the grader has no "
                            "version of its file: autograder/grader_stages/${file} does not exist")
      endif()
      list(APPEND grader_files ${file})
      if(NOT file IN_LIST RAYLAB_GRADER_STAGE_FILES)
        list(APPEND RAYLAB_GRADER_STAGE_FILES ${file})
      endif()
    endforeach()
  endforeach()
  if(NOT server_suffix STREQUAL "" AND NOT server_suffix IN_LIST RAYLAB_SERVER_SUFFIXES)
    list(APPEND RAYLAB_SERVER_SUFFIXES "${server_suffix}")
    set(RAYLAB_SERVER_GRADER_FILES${server_suffix} ${grader_files})
  endif()
  foreach(file IN LISTS files)
    if(file IN_LIST RAYLAB_GRADER_STAGE_FILES)
      message(FATAL_ERROR "stages.json: ${where}: its file ${file} is also an earlier stage's that the grader replaces")
    endif()
  endforeach()
  # "also_runs": earlier stages whose functions (the student's own) this stage's tests call, as
  # 06_robustness grades the rounding of stage 02's sphere and 04's box test. The self-tests grade a
  # submission at the stages that run its file (tests/submissions/CMakeLists.txt).
  foreach(earlier IN LISTS also_runs)
    if(NOT earlier IN_LIST RAYLAB_STAGE_IDS)
      message(FATAL_ERROR "stages.json: ${where}: \"also_runs\" names ${earlier}, which is not an earlier stage")
    endif()
  endforeach()
  set(RAYLAB_ALSO_RUNS_OF_${id} ${also_runs})
  set(RAYLAB_FILES_OF_${id} ${files})
  set(RAYLAB_SERVER_SUFFIX_OF_${id} "${server_suffix}")
  list(APPEND RAYLAB_STAGE_IDS ${id})

  # One C++ initializer per stage, in the order of StageDescription's fields.
  raylab_cxx_literal(id_literal "${id}")
  raylab_cxx_literal(title_literal "${title}")
  raylab_cxx_literal(title_zh_literal "${title_zh}")
  raylab_cxx_literal_list(files_literal ${files})
  raylab_cxx_literal_list(functions_literal ${functions})
  raylab_cxx_literal(handout_literal "${handout}")
  raylab_cxx_literal(section_literal "${section}")
  raylab_cxx_literal(scene_literal "${image_scene}")
  raylab_cxx_literal(shows_literal "${image_shows}")
  raylab_cxx_literal(server_suffix_literal "${server_suffix}")
  if(bonus)
    set(bonus_literal true)
  else()
    set(bonus_literal false)
  endif()
  string(APPEND raylab_table_entries
         "      {${id_literal}, ${title_literal}, ${title_zh_literal}, ${files_literal}, ${functions_literal}, ${handout_literal},\n"
         "       ${section_literal}, ${scene_literal}, ${shows_literal}, ${server_suffix_literal}, ${points}, ${bonus_literal}},\n")
endforeach()

set(RAYLAB_STAGE_TABLE_SOURCE ${CMAKE_BINARY_DIR}/generated/stage_table_data.cpp)
file(CONFIGURE OUTPUT ${RAYLAB_STAGE_TABLE_SOURCE} @ONLY CONTENT
"// Generated by cmake/RaylabStages.cmake from stages.json: edit stages.json, not this file.
#include \"raylab/stage_table.h\"

namespace raylab {

const std::vector<StageDescription>& stage_table() {
  static const std::vector<StageDescription> table = {
@raylab_table_entries@  };
  return table;
}

}  // namespace raylab
")
message(STATUS "raylab: ${raylab_stage_count} stages from stages.json (${RAYLAB_STAGE_IDS})")

set(RAYLAB_GENERATED_INCLUDE ${CMAKE_BINARY_DIR}/generated/include)
set(raylab_stage_messages "")
# A catalogue added to autograder/suites/ configures again (the folder changes).
set_property(DIRECTORY ${CMAKE_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/autograder/suites)
foreach(id IN LISTS RAYLAB_STAGE_IDS)
  if(EXISTS ${CMAKE_SOURCE_DIR}/autograder/suites/${id}_messages.def)
    # (A path relative to this file: the same text in every copy of the kit, which ccache then
    # finds without preprocessing each file that includes it.)
    # (Between the real folders: the compiler follows "../" from where a symbolic link leads.)
    get_filename_component(raylab_real_include ${RAYLAB_GENERATED_INCLUDE} REALPATH)
    get_filename_component(raylab_real_catalogue ${CMAKE_SOURCE_DIR}/autograder/suites/${id}_messages.def REALPATH)
    file(RELATIVE_PATH raylab_messages_path ${raylab_real_include} ${raylab_real_catalogue})
    string(APPEND raylab_stage_messages "#include \"${raylab_messages_path}\"\n")
  endif()
endforeach()
file(CONFIGURE OUTPUT ${RAYLAB_GENERATED_INCLUDE}/stage_messages.def @ONLY CONTENT
"// Generated by cmake/RaylabStages.cmake from stages.json: each stage's own catalogue of messages,
// autograder/suites/<id>_messages.def, in teaching order. Add a stage's file there, not here.
@raylab_stage_messages@")

# raylab_add_stage_library(NAME ROOT): the stage code under ROOT (assignments/ or solutions/),
# one OBJECT library per stage file, NAME_<file as a C identifier> (so that a stage server can
# link some stages' code and the grader's own versions of others: raylab_stage_objects), and NAME,
# which links all of them. Not STATIC: the framework calls the stage functions and the stages use
# the framework, so the stage objects go straight into each program.
function(raylab_add_stage_library name root)
  set(objects "")
  foreach(file IN LISTS RAYLAB_STAGE_FILES)
    string(MAKE_C_IDENTIFIER "${file}" id)
    add_library(${name}_${id} OBJECT ${root}/${file})
    target_link_libraries(${name}_${id} PUBLIC raylab_framework PRIVATE raylab_options)
    raylab_reuse_precompiled_headers(${name}_${id})
    list(APPEND objects $<TARGET_OBJECTS:${name}_${id}>)
  endforeach()
  add_library(${name} INTERFACE)
  target_sources(${name} INTERFACE ${objects})
  target_link_libraries(${name} INTERFACE raylab_framework)
endfunction()

# raylab_stage_objects(OUT LIBRARIES [SUFFIX]): the per-file OBJECT libraries of the stage library
# LIBRARIES (raylab_add_stage_library, or a list of them), each file's from the first library in the list
# that has it (so "stages_x;raylab_stages_reference" is file x's submission on the reference);
# with SUFFIX (one of RAYLAB_SERVER_SUFFIXES), the grader's own versions of the files it names.
function(raylab_stage_objects out libraries)
  set(suffix "${ARGV2}")
  # Every library named must have a file here: a misspelt one must not fall through to the next.
  foreach(library IN LISTS libraries)
    set(has_one OFF)
    foreach(file IN LISTS RAYLAB_STAGE_FILES)
      string(MAKE_C_IDENTIFIER "${file}" id)
      if(TARGET ${library}_${id})
        set(has_one ON)
      endif()
    endforeach()
    if(NOT has_one)
      message(FATAL_ERROR "raylab_stage_objects: no library ${library}_<stage file as a C identifier> exists")
    endif()
  endforeach()
  set(objects "")
  foreach(file IN LISTS RAYLAB_STAGE_FILES)
    string(MAKE_C_IDENTIFIER "${file}" id)
    if(NOT suffix STREQUAL "" AND file IN_LIST RAYLAB_SERVER_GRADER_FILES${suffix})
      list(APPEND objects raylab_grader_stage_${id})
      continue()
    endif()
    set(found "")
    foreach(library IN LISTS libraries)
      if(TARGET ${library}_${id})
        set(found ${library}_${id})
        break()
      endif()
    endforeach()
    if(found STREQUAL "")
      message(FATAL_ERROR "raylab_stage_objects: no library of ${libraries} has ${file}")
    endif()
    list(APPEND objects ${found})
  endforeach()
  set(${out} ${objects} PARENT_SCOPE)
endfunction()

# raylab_add_program(NAME student|reference SOURCES...): one program linked with one variant.
function(raylab_add_program name variant)
  add_executable(${name} ${ARGN})
  target_link_libraries(${name} PRIVATE raylab_stages_${variant} raylab_framework raylab_testkit raylab_options)
endfunction()
