# The fixture of the find_package consumer test:
#   cmake -DBUILD_DIR=<derivcheck build> -DPREFIX=<dir> -DSOURCE_DIR=<derivcheck source> -P install_tree.cmake
# Installs the build into PREFIX.staging with `cmake --install`, then moves it to PREFIX: the
# consumer uses a tree that is not where it was installed (relocatable). Checks the layout,
# that no installed CMake file names the build or source directory, and that no installed
# header outside numeric/ includes Eigen, Boost or CLI11.
foreach(v BUILD_DIR PREFIX SOURCE_DIR)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "install_tree.cmake: ${v} is not set")
  endif()
endforeach()
set(staging ${PREFIX}.staging)
file(REMOVE_RECURSE ${PREFIX} ${staging})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${staging} OUTPUT_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install ${BUILD_DIR} --prefix ${staging} failed (${rc})")
endif()
file(RENAME ${staging} ${PREFIX})

file(GLOB_RECURSE config LIST_DIRECTORIES false RELATIVE ${PREFIX} ${PREFIX}/*/derivcheckConfig.cmake)
if(NOT config)
  message(FATAL_ERROR "no derivcheckConfig.cmake under ${PREFIX}")
endif()
cmake_path(GET config PARENT_PATH cmakedir)
cmake_path(GET cmakedir PARENT_PATH cmake_parent)
cmake_path(GET cmake_parent PARENT_PATH libdir)
foreach(f bin/derivcheck
          ${libdir}/libderivcheck_symbolic.a ${libdir}/libderivcheck_numeric.a
          include/derivcheck/catch2.hpp
          include/derivcheck/derivations/catch/derivcheck_catch.hpp
          include/derivcheck/derivations/decide/prove.hpp
          include/derivcheck/derivations/core/prove.hpp   # forwarder to the old path
          include/derivcheck/derivations/core/prove_detail.hpp
          include/derivcheck/numeric/evaluator.hpp
          ${cmakedir}/derivcheckConfig.cmake ${cmakedir}/derivcheckConfigVersion.cmake
          ${cmakedir}/derivcheck-targets.cmake ${cmakedir}/derivcheck-catch2-targets.cmake
          ${cmakedir}/derivcheck-numeric-targets.cmake
          ${cmakedir}/FindArb.cmake ${cmakedir}/DerivcheckTest.cmake ${cmakedir}/DerivcheckRunTest.cmake)
  if(NOT EXISTS ${PREFIX}/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()

file(GLOB_RECURSE cmake_files ${PREFIX}/${cmakedir}/*.cmake)
foreach(f IN LISTS cmake_files)
  file(READ ${f} text)
  foreach(dir ${BUILD_DIR} ${SOURCE_DIR} ${staging})
    string(FIND "${text}" "${dir}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "${f} names ${dir}: the install tree is not relocatable")
    endif()
  endforeach()
endforeach()

file(GLOB_RECURSE headers RELATIVE ${PREFIX}/include ${PREFIX}/include/*)
foreach(h IN LISTS headers)
  if(h MATCHES "^derivcheck/numeric/")
    continue()   # derivcheck::numeric: Eigen and Boost are its dependencies
  endif()
  file(STRINGS ${PREFIX}/include/${h} bad REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"](Eigen|eigen3|boost|CLI)/")
  if(bad)
    message(FATAL_ERROR "installed header ${h} includes ${bad}")
  endif()
endforeach()
list(LENGTH headers n)
message(STATUS "installed ${n} headers and the CMake package into ${PREFIX} (via ${staging})")
