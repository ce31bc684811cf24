// derivcheck's Catch2 (v2) matchers: #include <derivcheck/catch2.hpp>, link derivcheck::catch2.
//
//   using dc::catch2::EqualsSymbolically;
//   REQUIRE_THAT(E, EqualsSymbolically("1/2*k*A^2").assuming("k>0"));
//
// A forwarding header: the matchers are derivations/catch/derivcheck_catch.hpp (installed
// as include/derivcheck/derivations/catch/derivcheck_catch.hpp). docs/library.md.
#pragma once
#include "derivations/catch/derivcheck_catch.hpp"
