# FindArb: the Arb ball-arithmetic library (Debian: libflint-arb-dev), which Debian ships
# without a pkg-config or CMake file. Defines the imported target Arb::Arb (Arb, FLINT, MPFR,
# GMP) and Arb_FOUND.
find_path(Arb_INCLUDE_DIR NAMES arb.h acb.h PATH_SUFFIXES flint arb)
find_path(Flint_INCLUDE_DIR NAMES flint.h PATH_SUFFIXES flint)
find_library(Arb_LIBRARY NAMES flint-arb arb)
find_library(Flint_LIBRARY NAMES flint)
find_library(Mpfr_LIBRARY NAMES mpfr)
find_library(Gmp_LIBRARY NAMES gmp)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Arb REQUIRED_VARS Arb_LIBRARY Arb_INCLUDE_DIR Flint_LIBRARY Flint_INCLUDE_DIR
                                  Mpfr_LIBRARY Gmp_LIBRARY)

if(Arb_FOUND AND NOT TARGET Arb::Arb)
  add_library(Arb::Arb UNKNOWN IMPORTED)
  set_target_properties(Arb::Arb PROPERTIES
    IMPORTED_LOCATION "${Arb_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${Arb_INCLUDE_DIR};${Flint_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${Flint_LIBRARY};${Mpfr_LIBRARY};${Gmp_LIBRARY}")
endif()
mark_as_advanced(Arb_INCLUDE_DIR Flint_INCLUDE_DIR Arb_LIBRARY Flint_LIBRARY Mpfr_LIBRARY Gmp_LIBRARY)
