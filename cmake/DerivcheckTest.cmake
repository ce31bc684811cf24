# derivcheck_add_test(NAME FILE [FILE...] [EXPECT holds|refuted|undecided])
#
# Turns derivation files into a ctest test that runs `derivcheck check FILE...` and compares
# its exit code with the expected outcome:
#   EXPECT holds      (the default) exit 0: every step proved or holding numerically; errata
#                     declared in the file are reported but do not fail the test
#   EXPECT refuted    exit 1: some step is refuted (or a rule could not be applied)
#   EXPECT undecided  exit 3: nothing refuted, some step undecided
# An input error (exit 2: a file that cannot be read or parsed) always fails the test, whatever
# EXPECT says, as does a crash. Relative FILE paths are taken relative to the calling
# CMakeLists.txt (CMAKE_CURRENT_SOURCE_DIR), and the CLI runs in that directory. The test gets
# the LABEL "derivation".
#
# Needs the CLI target derivcheck::derivcheck: defined by the derivcheck build itself, by
# add_subdirectory(derivcheck) and by find_package(derivcheck).
include_guard(GLOBAL)

# The runner script lives next to this file (source tree: cmake/, install tree:
# lib/cmake/derivcheck/); a global property, so the function finds it when called from any
# directory (also from a parent project of add_subdirectory).
set_property(GLOBAL PROPERTY DERIVCHECK_RUN_TEST_SCRIPT "${CMAKE_CURRENT_LIST_DIR}/DerivcheckRunTest.cmake")

function(derivcheck_add_test name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "EXPECT" "")
  if(NOT TARGET derivcheck::derivcheck)
    message(FATAL_ERROR "derivcheck_add_test: the CLI target derivcheck::derivcheck is not defined "
                        "(find_package(derivcheck) or add_subdirectory(derivcheck) first)")
  endif()
  if(NOT arg_EXPECT)
    set(arg_EXPECT holds)
  endif()
  if(NOT arg_EXPECT MATCHES "^(holds|refuted|undecided)$")
    message(FATAL_ERROR "derivcheck_add_test(${name}): EXPECT must be holds, refuted or undecided, not '${arg_EXPECT}'")
  endif()
  if(NOT arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "derivcheck_add_test(${name}): no derivation file given")
  endif()
  set(files)
  foreach(f IN LISTS arg_UNPARSED_ARGUMENTS)
    cmake_path(ABSOLUTE_PATH f BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE OUTPUT_VARIABLE abs)
    list(APPEND files "${abs}")
  endforeach()
  get_property(runner GLOBAL PROPERTY DERIVCHECK_RUN_TEST_SCRIPT)
  add_test(NAME ${name}
           COMMAND ${CMAKE_COMMAND} "-DDERIVCHECK=$<TARGET_FILE:derivcheck::derivcheck>" "-DEXPECT=${arg_EXPECT}"
                   -P "${runner}" ${files}
           WORKING_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}")
  set_tests_properties(${name} PROPERTIES LABELS derivation)
endfunction()
