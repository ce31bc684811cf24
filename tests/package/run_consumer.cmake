# Configures, builds and tests the consumer project (tests/package/consumer) against derivcheck:
#   cmake -DMODE=find_package -DPREFIX=<install tree> ...      find_package(derivcheck CONFIG)
#   cmake -DMODE=subdirectory -DDERIVCHECK_SOURCE_DIR=<src> ... add_subdirectory(derivcheck)
# Other variables: CONSUMER_SOURCE_DIR, CONSUMER_BINARY_DIR, GENERATOR, CXX_COMPILER,
# CXX_LAUNCHER (ccache), BUILD_TYPE, BUILD (OFF: configure and check only).
# After the build: the consumer's own ctest (its Catch2 test and its derivcheck_add_test
# tests, EXPECT holds/refuted/undecided and an input error that must fail), then the
# compiler's dependency file of the consumer's test: no Eigen, Boost or CLI11 header may be
# in the matchers' include closure.
foreach(v MODE CONSUMER_SOURCE_DIR CONSUMER_BINARY_DIR GENERATOR CXX_COMPILER BUILD_TYPE)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_consumer.cmake: ${v} is not set")
  endif()
endforeach()
if(NOT DEFINED BUILD)
  set(BUILD ON)
endif()

function(run)
  string(REPLACE ";" " " shown "${ARGN}")
  message(STATUS "run: ${shown}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${shown}")
  endif()
endfunction()

set(args -S ${CONSUMER_SOURCE_DIR} -B ${CONSUMER_BINARY_DIR} -G "${GENERATOR}" -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
         -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCONSUMER_MODE=${MODE})
if(CXX_LAUNCHER)
  list(APPEND args -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()
if(MODE STREQUAL "find_package")
  # only the install tree: a fresh build directory, the prefix and nothing else of derivcheck
  file(REMOVE_RECURSE ${CONSUMER_BINARY_DIR})
  # and without Eigen, Boost or CLI11: the matchers must not need them
  list(APPEND args -DCMAKE_PREFIX_PATH=${PREFIX} -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=TRUE
       -DCMAKE_DISABLE_FIND_PACKAGE_Boost=TRUE -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=TRUE)
elseif(MODE STREQUAL "subdirectory")
  # kept between runs: the library is rebuilt only when it changed
  list(APPEND args -DDERIVCHECK_SOURCE_DIR=${DERIVCHECK_SOURCE_DIR})
else()
  message(FATAL_ERROR "run_consumer.cmake: MODE must be find_package or subdirectory")
endif()
run(${CMAKE_COMMAND} ${args})

if(MODE STREQUAL "find_package")
  file(STRINGS ${CONSUMER_BINARY_DIR}/CMakeCache.txt dir_line REGEX "^derivcheck_DIR:")
  string(REGEX REPLACE "^[^=]*=" "" found_dir "${dir_line}")
  cmake_path(IS_PREFIX PREFIX "${found_dir}" NORMALIZE in_prefix)
  if(NOT in_prefix)
    message(FATAL_ERROR "the consumer found derivcheck in ${found_dir}, not in the install tree ${PREFIX}")
  endif()
endif()

if(NOT BUILD)
  message(STATUS "configured only: building the library a second time under add_subdirectory is off "
                 "(-DDERIVCHECK_TEST_ADD_SUBDIRECTORY_BUILD=ON turns it on; tests/package/CMakeLists.txt)")
  return()
endif()

run(${CMAKE_COMMAND} --build ${CONSUMER_BINARY_DIR} -j2)
run(${CMAKE_CTEST_COMMAND} --test-dir ${CONSUMER_BINARY_DIR} --output-on-failure)

# The headers the consumer's test actually included (the compiler's own dependency list).
file(GLOB_RECURSE depfiles ${CONSUMER_BINARY_DIR}/CMakeFiles/consumer_test.dir/*.o.d)
if(NOT depfiles)
  message(FATAL_ERROR "no dependency file for consumer_test.cpp under ${CONSUMER_BINARY_DIR}")
endif()
foreach(d IN LISTS depfiles)
  file(READ ${d} deps)
  if(NOT deps MATCHES "derivcheck/catch2\\.hpp")
    message(FATAL_ERROR "${d} does not list derivcheck/catch2.hpp")
  endif()
  string(REGEX MATCHALL "[^ \t\r\n\\\\]*(eigen3|Eigen/|boost/|CLI/)[^ \t\r\n\\\\]*" bad "${deps}")
  if(bad)
    list(REMOVE_DUPLICATES bad)
    message(FATAL_ERROR "the matchers' include closure has Eigen, Boost or CLI11 headers: ${bad}")
  endif()
  if(MODE STREQUAL "find_package")
    # the headers of the install tree, not of the source tree
    string(FIND "${deps}" "${PREFIX}/include/derivcheck/derivations/catch/derivcheck_catch.hpp" at_prefix)
    string(FIND "${deps}" "${DERIVCHECK_SOURCE_DIR}/derivations/" at_source)
    if(at_prefix EQUAL -1 OR NOT at_source EQUAL -1)
      message(FATAL_ERROR "the consumer's test did not include derivcheck's headers from ${PREFIX}: ${deps}")
    endif()
  endif()
endforeach()
message(STATUS "the consumer's test includes no Eigen, Boost or CLI11 header")
