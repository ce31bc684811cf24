# derivcheck_add_test(NAME FILE [FILE...])
# Turns derivation files into a ctest test: `derivcheck check FILE...` must exit 0
# (every step proved or holding numerically; errata declared in the file are reported
# but do not fail the test).
function(derivcheck_add_test name)
  if(NOT TARGET derivcheck)
    message(FATAL_ERROR "derivcheck_add_test: the derivcheck target is not defined")
  endif()
  add_test(NAME ${name} COMMAND $<TARGET_FILE:derivcheck> check ${ARGN})
  set_tests_properties(${name} PROPERTIES LABELS derivation)
endfunction()
