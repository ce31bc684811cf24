# The test command of derivcheck_add_test (DerivcheckTest.cmake):
#   cmake -DDERIVCHECK=<cli> -DEXPECT=holds|refuted|undecided -P DerivcheckRunTest.cmake FILE...
# Runs `derivcheck check FILE...` (its report goes to the test's output) and fails unless the
# exit code is the expected one: holds 0, refuted 1, undecided 3. Exit 2 (an input error)
# always fails.
if(NOT DEFINED DERIVCHECK OR NOT DEFINED EXPECT)
  message(FATAL_ERROR "usage: cmake -DDERIVCHECK=<cli> -DEXPECT=holds|refuted|undecided -P ${CMAKE_CURRENT_LIST_FILE} FILE...")
endif()

# The files are the arguments after the script (cmake ... -P script FILE...).
set(files)
set(first -1)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE 1 ${last})
  if(first EQUAL -1 AND CMAKE_ARGV${i} STREQUAL "-P")
    math(EXPR first "${i} + 2")
  elseif(NOT first EQUAL -1 AND i GREATER_EQUAL first)
    list(APPEND files "${CMAKE_ARGV${i}}")
  endif()
endforeach()
if(NOT files)
  message(FATAL_ERROR "derivcheck test: no derivation file given")
endif()

set(expected_holds 0)
set(expected_refuted 1)
set(expected_undecided 3)
if(NOT DEFINED expected_${EXPECT})
  message(FATAL_ERROR "derivcheck test: EXPECT must be holds, refuted or undecided, not '${EXPECT}'")
endif()
set(want ${expected_${EXPECT}})

execute_process(COMMAND "${DERIVCHECK}" check ${files} RESULT_VARIABLE rc)

set(meaning_0 "everything holds")
set(meaning_1 "something is refuted")
set(meaning_2 "input error")
set(meaning_3 "something is undecided")
if(rc STREQUAL "2")
  message(FATAL_ERROR "derivcheck test: input error (exit 2): the derivation could not be read; "
                      "this always fails, whatever EXPECT says")
elseif(NOT rc MATCHES "^[0-9]+$")
  message(FATAL_ERROR "derivcheck test: the CLI did not finish: ${rc}")
elseif(NOT rc EQUAL want)
  if(DEFINED meaning_${rc})
    set(got "${meaning_${rc}}")
  else()
    set(got "unexpected exit code")
  endif()
  message(FATAL_ERROR "derivcheck test: expected '${EXPECT}' (exit ${want}), got exit ${rc} (${got})")
endif()
message(STATUS "derivcheck test: ${EXPECT} as expected (exit ${rc})")
