// A user's own Catch2 test with derivcheck's matchers (docs/library.md).
#include <catch2/catch.hpp>
#include <derivcheck/catch2.hpp>

using dc::catch2::EqualsSymbolically;

TEST_CASE("spring energy, checked against the user's own GiNaC symbols") {
  GiNaC::symbol k("k"), A("A");
  GiNaC::ex E = GiNaC::numeric(1, 2) * k * GiNaC::pow(A, 2);
  REQUIRE_THAT(E, EqualsSymbolically("1/2*k*A^2").assuming("k>0"));
  REQUIRE_THAT(E, EqualsSymbolically(k * A * A / 2));
  REQUIRE_THAT("limit((m1 - m2)*v1/(m1 + m2), m2, oo)", EqualsSymbolically("-v1").assuming("m1>0, m2>0"));

  auto dropped_half = EqualsSymbolically("k*A^2").assuming("k>0");
  CHECK_FALSE(dropped_half.match(E));
  REQUIRE(dropped_half.verdict() != nullptr);
  CHECK(dropped_half.verdict()->kind == dc::VerdictKind::Refuted);
}
