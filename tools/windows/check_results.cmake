# One grading run of tools/windows-check, checked from its results.json:
#   cmake -DRESULTS=results.json -DEXPECT=full|zero|stage|loses -DSTAGE=<id> -DREASON=<regex>
#         "-DALSO_AFFECTED=<regex of 'stage: Test' names>" -P check_results.cmake
# This build has no OpenImageIO (tools/windows-check), so the picture tests (*ImageMatchesReference)
# must score 0 (for the reference: with the message that says why, and for no other reason;
# elsewhere they may also fail for the stage code they render with); every other test is checked:
#   full   every test at full marks
#   zero   every test at 0 (the stubs)
#   stage  every test of STAGE at 0, at least one of them failing with REASON; every test of
#          the other stages at full marks, except those matching ALSO_AFFECTED (tests of later
#          stages that call the same function), which may lose points
#   loses  as stage, but STAGE need only lose points (code that crashes on some inputs only):
#          at least one of its tests at 0 with REASON
# Prints "score/max" of the tests checked; fails with every problem it found.
cmake_minimum_required(VERSION 3.19)
file(READ "${RESULTS}" text)
string(JSON count LENGTH "${text}" tests)
set(problems "")
set(checked_points 0)
set(checked_max 0)
set(picture_tests 0)
set(reason_seen OFF)
math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
  string(JSON name GET "${text}" tests ${i} name)
  string(JSON score GET "${text}" tests ${i} score)
  string(JSON max GET "${text}" tests ${i} max_score)
  string(JSON output GET "${text}" tests ${i} output)
  string(REGEX REPLACE ":.*" "" stage "${name}")
  if(name MATCHES "ImageMatchesReference$")
    math(EXPR picture_tests "${picture_tests} + 1")
    if(NOT score EQUAL 0)
      list(APPEND problems "${name}: scored ${score} without image I/O")
    elseif(EXPECT STREQUAL "full" AND NOT output MATCHES "no OpenImageIO")
      list(APPEND problems "${name}: failed for another reason than the missing image I/O: ${output}")
    endif()
    continue()
  endif()
  math(EXPR checked_points "${checked_points} + ${score}")
  math(EXPR checked_max "${checked_max} + ${max}")
  if(EXPECT STREQUAL "zero" OR ((EXPECT STREQUAL "stage" OR EXPECT STREQUAL "loses") AND stage STREQUAL STAGE))
    if(NOT score EQUAL 0 AND NOT EXPECT STREQUAL "loses")
      list(APPEND problems "${name}: ${score} of ${max} points, expected 0")
    endif()
    if(NOT EXPECT STREQUAL "zero" AND score EQUAL 0 AND output MATCHES "${REASON}")
      set(reason_seen ON)
    endif()
  elseif(NOT score EQUAL max)
    if(NOT (ALSO_AFFECTED AND name MATCHES "${ALSO_AFFECTED}"))
      list(APPEND problems "${name}: ${score} of ${max} points, expected full marks: ${output}")
    endif()
  endif()
endforeach()
if(picture_tests EQUAL 0)
  list(APPEND problems "no picture test found (renamed? update tools/windows/check_results.cmake)")
endif()
if((EXPECT STREQUAL "stage" OR EXPECT STREQUAL "loses") AND NOT reason_seen)
  list(APPEND problems "no test of ${STAGE} names the reason '${REASON}'")
endif()
if(problems)
  list(JOIN problems "\n  " problems_text)
  message(FATAL_ERROR "${RESULTS}:\n  ${problems_text}")
endif()
message("${checked_points}/${checked_max} points on the tests without pictures (${picture_tests} picture tests not gradable here)")
