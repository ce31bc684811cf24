# Install rules and the CMake package (docs/library.md). Included from the top-level
# CMakeLists.txt when DERIVCHECK_INSTALL is ON (the default for a top-level build).
#
#   PREFIX/bin/derivcheck
#   PREFIX/lib/libderivcheck_symbolic.a, libderivcheck_numeric.a
#   PREFIX/lib/libderivcheck_jit.so                  the JIT module (when built), dlopen'ed
#   PREFIX/include/derivcheck/catch2.hpp            <derivcheck/catch2.hpp>, forwards to
#   PREFIX/include/derivcheck/derivations/...       the headers, tree kept ("derivations/core/x.hpp")
#   PREFIX/include/derivcheck/numeric/...
#   PREFIX/lib/cmake/derivcheck/                    derivcheckConfig.cmake and friends
#
# Everything is relative to PREFIX (relocatable): the exported targets use _IMPORT_PREFIX, the
# dependencies are found again on the consumer's machine by derivcheckConfig.cmake.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(DERIVCHECK_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/derivcheck"
    CACHE STRING "Where the derivcheck CMake package is installed (relative to the prefix)")
mark_as_advanced(DERIVCHECK_INSTALL_CMAKEDIR)

# Three export sets, so that a consumer needs only what the targets it uses need:
#   derivcheck-targets          symbolic (GiNaC, CLN, nlohmann_json, Arb) and the CLI
#   derivcheck-catch2-targets   catch2 (+ Catch2), loaded when Catch2 is found
#   derivcheck-numeric-targets  numeric (+ Eigen, Boost), loaded when those are found
install(TARGETS derivcheck_symbolic derivcheck EXPORT derivcheck-targets
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS derivcheck_numeric EXPORT derivcheck-numeric-targets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The JIT module (numeric/jit.hpp): loaded at run time from PREFIX/LIBDIR, not linked.
if(TARGET derivcheck_jit)
  install(TARGETS derivcheck_jit LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
endif()
install(EXPORT derivcheck-targets NAMESPACE derivcheck:: DESTINATION ${DERIVCHECK_INSTALL_CMAKEDIR})
install(EXPORT derivcheck-numeric-targets NAMESPACE derivcheck:: DESTINATION ${DERIVCHECK_INSTALL_CMAKEDIR})
if(TARGET derivcheck_catch2)
  install(TARGETS derivcheck_catch2 EXPORT derivcheck-catch2-targets)
  install(EXPORT derivcheck-catch2-targets NAMESPACE derivcheck:: DESTINATION ${DERIVCHECK_INSTALL_CMAKEDIR})
endif()

# Headers: the source tree's layout under include/derivcheck/ (apps/ is not a library).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/derivations/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/derivcheck/derivations
        FILES_MATCHING PATTERN "*.hpp"
        PATTERN "include" EXCLUDE      # derivations/catch/include: <derivcheck/catch2.hpp>, below
        PATTERN "internal" EXCLUDE     # headers private to a stage folder
        PATTERN "handout9" EXCLUDE)    # derivation files, no headers
install(DIRECTORY ${PROJECT_SOURCE_DIR}/numeric/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/derivcheck/numeric
        FILES_MATCHING PATTERN "*.hpp" PATTERN "internal" EXCLUDE)
# The include paths of the layout before the stage folders, as forwarders (install tree only).
include(${PROJECT_SOURCE_DIR}/cmake/DerivcheckCompatHeaders.cmake)
install(FILES ${PROJECT_SOURCE_DIR}/derivations/catch/include/derivcheck/catch2.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/derivcheck)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/derivcheckConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/derivcheckConfig.cmake
                              INSTALL_DESTINATION ${DERIVCHECK_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/derivcheckConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/derivcheckConfig.cmake ${PROJECT_BINARY_DIR}/derivcheckConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/FindArb.cmake
              ${PROJECT_SOURCE_DIR}/cmake/DerivcheckTest.cmake
              ${PROJECT_SOURCE_DIR}/cmake/DerivcheckRunTest.cmake
        DESTINATION ${DERIVCHECK_INSTALL_CMAKEDIR})
