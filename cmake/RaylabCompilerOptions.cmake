# Warnings, -Werror, sanitizers and -march=native as options applied to raylab's own targets.
# Every flag is spelled for the compiler that takes it (GCC and Clang, including MinGW-w64 and
# Apple's; MSVC), and the sanitizers only where a test program links with them: MinGW-w64 has
# no sanitizer runtimes, so RAYLAB_SANITIZE=ON there warns and builds without them.
add_library(raylab_options INTERFACE)
target_compile_options(raylab_options INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang,AppleClang>:-Wall -Wextra -Wpedantic -Wshadow>
  $<$<CXX_COMPILER_ID:MSVC>:/W4>)
# No fused multiply-adds the source did not write: with -march=native (or any target with
# FMA) GCC and Clang would fuse a * b + c differently in scalar and SSE code, and the
# reference's four-at-a-time triangle test (solutions/05_bvh/leaf_test.h) must give the bits
# of its scalar test. (MSVC does not contract unless asked with /fp:contract.)
target_compile_options(raylab_options INTERFACE $<$<CXX_COMPILER_ID:GNU,Clang,AppleClang>:-ffp-contract=off>)
# raylab_checking_code: code that checks, grades and reports rather than renders (the judge and
# its suites, the calls between judge and stage server, the tests, the command line and scene
# parsing) is optimised with -O1 in a Release build. Grading takes the same time (5.1-5.3 s for
# every stage of the reference either way), and these files, full of GoogleTest and JSON
# templates, build in about 3/4 of the time of -O3. The renderer, the stages and the benchmarks
# keep -O3.
# (RAYLAB_CHECKING_CODE_OPTIONS: the same for single files of other targets, framework/CMakeLists.txt.)
set(RAYLAB_CHECKING_CODE_OPTIONS "$<$<AND:$<CONFIG:Release>,$<CXX_COMPILER_ID:GNU,Clang,AppleClang>>:-O1>")
add_library(raylab_checking_code INTERFACE)
target_compile_options(raylab_checking_code INTERFACE ${RAYLAB_CHECKING_CODE_OPTIONS})

# raylab_precompile_headers(TARGET [TESTS]): with RAYLAB_PRECOMPILE_HEADERS, TARGET's files are
# compiled with GLM and the standard headers they use most precompiled (with TESTS, GoogleTest and
# nlohmann-json too: the grader's and the tests' targets). Only library headers: a file still
# has to include what it uses, which the GCC build, without this, checks.
# raylab_reuse_precompiled_headers(TARGET [SELF_TEST]): the single-file stage code targets share one
# precompiled header, raylab_stage_code_pch's (same flags: raylab_framework and raylab_options).
# With SELF_TEST (the grader's self-test submissions, tests/submissions and tests/report: about 190
# files, each compiled once) also without RAYLAB_PRECOMPILE_HEADERS, when RAYLAB_PRECOMPILE_SELF_TESTS
# is ON: each compiles in 1/3 to 1/2 of the time (0.4-0.7 s instead of 0.8-1.8 s at -O3 here). The
# stage files of assignments/, solutions/ and the grader keep GCC's plain compile, which ccache
# shares with the builds that the project's tests make again (the student release, the Gradescope kit).
set(RAYLAB_PRECOMPILED_STANDARD_HEADERS <glm/glm.hpp> <algorithm> <cmath> <cstdint> <functional> <memory>
    <optional> <string> <utility> <vector>)
function(raylab_precompile_headers target)
  if(RAYLAB_PRECOMPILE_HEADERS)
    set(headers ${RAYLAB_PRECOMPILED_STANDARD_HEADERS})
    if(ARGV1 STREQUAL "TESTS")
      list(APPEND headers <gtest/gtest.h> <nlohmann/json.hpp> <map> <sstream> <filesystem>)
    endif()
    target_precompile_headers(${target} PRIVATE ${headers})
  endif()
endfunction()
function(raylab_reuse_precompiled_headers target)
  if(RAYLAB_PRECOMPILE_HEADERS OR (ARGV1 STREQUAL "SELF_TEST" AND RAYLAB_PRECOMPILE_SELF_TESTS))
    if(NOT TARGET raylab_stage_code_pch)
      file(CONFIGURE OUTPUT ${PROJECT_BINARY_DIR}/generated/stage_code_pch.cpp CONTENT "// the precompiled header's own file\n")
      add_library(raylab_stage_code_pch OBJECT ${PROJECT_BINARY_DIR}/generated/stage_code_pch.cpp)
      target_link_libraries(raylab_stage_code_pch PUBLIC raylab_framework PRIVATE raylab_options)
      target_precompile_headers(raylab_stage_code_pch PRIVATE ${RAYLAB_PRECOMPILED_STANDARD_HEADERS})
    endif()
    target_precompile_headers(${target} REUSE_FROM raylab_stage_code_pch)
  endif()
endfunction()

if(RAYLAB_WERROR)
  target_compile_options(raylab_options INTERFACE
    $<$<CXX_COMPILER_ID:GNU,Clang,AppleClang>:-Werror> $<$<CXX_COMPILER_ID:MSVC>:/WX>)
endif()
if(RAYLAB_NATIVE)
  target_compile_options(raylab_options INTERFACE $<$<CXX_COMPILER_ID:GNU,Clang,AppleClang>:-march=native>)
  if(MSVC)
    message(WARNING "raylab: RAYLAB_NATIVE has no MSVC spelling here (choose /arch: yourself); ignored")
  endif()
endif()

if(RAYLAB_SANITIZE AND MSVC)
  message(WARNING "raylab: RAYLAB_SANITIZE is written for GCC and Clang; with MSVC use /fsanitize=address yourself. Building without")
elseif(RAYLAB_SANITIZE)
  # Check that the sanitizer runtimes link before using them: a machine without them
  # (no libasan/libubsan) gets a clear message instead of a broken build.
  include(CheckCXXSourceCompiles)
  set(CMAKE_REQUIRED_FLAGS "-fsanitize=address,undefined")
  set(CMAKE_REQUIRED_LINK_OPTIONS "-fsanitize=address,undefined")
  check_cxx_source_compiles("int main() { return 0; }" RAYLAB_SANITIZERS_LINK)
  unset(CMAKE_REQUIRED_FLAGS)
  unset(CMAKE_REQUIRED_LINK_OPTIONS)
  if(RAYLAB_SANITIZERS_LINK)
    target_compile_options(raylab_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer)
    target_link_options(raylab_options INTERFACE -fsanitize=address,undefined)
    message(STATUS "raylab: AddressSanitizer and UndefinedBehaviorSanitizer on")
  else()
    message(WARNING "raylab: RAYLAB_SANITIZE=ON but the sanitizer runtimes do not link here; building without them")
  endif()
endif()
