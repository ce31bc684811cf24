// The handout's key equalities as Catch2 tests written with derivcheck's matchers
// (derivations/catch/derivcheck_catch.hpp): each is a real check through dc::prove_equal.
#include <catch2/catch.hpp>

#include "derivations/catch/derivcheck_catch.hpp"

using dc::catch2::EqualsSymbolically;
using GiNaC::ex;
using GiNaC::numeric;
using GiNaC::symbol;

namespace {
// (9.6) momentum and (9.7) restitution, solved for v1', v2' with GiNaC.
struct Impact {
  symbol m1{"m1"}, m2{"m2"}, v1{"v1"}, v2{"v2"}, e{"e"}, v1p{"v1p"}, v2p{"v2p"};
  ex v1p_general, v2p_general;
  Impact() {
    GiNaC::lst eqs{m1 * v1 + m2 * v2 == m1 * v1p + m2 * v2p,     // (9.6)
                   e * (v1 - v2) == v2p - v1p};                  // (9.7)
    ex sol = GiNaC::lsolve(eqs, GiNaC::lst{v1p, v2p});
    v1p_general = sol.op(0).rhs();
    v2p_general = sol.op(1).rhs();
  }
};
}  // namespace

TEST_CASE("handout: elastic impact v'1 from the general solution", "[matchers][handout]") {
  Impact s;
  ex elastic = ((s.m1 - s.m2) * s.v1 + 2 * s.m2 * s.v2) / (s.m1 + s.m2);
  REQUIRE_THAT(s.v1p_general.subs(s.e == 1), EqualsSymbolically(elastic).assuming("m1>0, m2>0"));
  REQUIRE_THAT(s.v1p_general, EqualsSymbolically((s.m1 * s.v1 + s.m2 * s.v2 - s.e * s.m2 * (s.v1 - s.v2)) / (s.m1 + s.m2))
                                  .assuming("m1>0, m2>0, e in [0,1]"));
}

TEST_CASE("handout: general kinetic energy loss", "[matchers][handout]") {
  Impact s;
  ex before = numeric(1, 2) * s.m1 * s.v1 * s.v1 + numeric(1, 2) * s.m2 * s.v2 * s.v2;
  ex after = numeric(1, 2) * s.m1 * GiNaC::pow(s.v1p_general, 2) + numeric(1, 2) * s.m2 * GiNaC::pow(s.v2p_general, 2);
  ex handout = (1 - s.e * s.e) / 2 * s.m1 * s.m2 / (s.m1 + s.m2) * GiNaC::pow(s.v1 - s.v2, 2);
  REQUIRE_THAT(before - after, EqualsSymbolically(handout).assuming("m1>0, m2>0, e in [0,1]"));
}

TEST_CASE("handout: impact with a flat wall (m2 -> oo)", "[matchers][handout]") {
  REQUIRE_THAT("limit((m1 - m2)*v1/(m1 + m2), m2, oo)", EqualsSymbolically("-v1").assuming("m1>0, m2>0"));
  REQUIRE_THAT("limit(2*m1*v1/(m1 + m2), m2, oo)", EqualsSymbolically("0").assuming("m1>0, m2>0"));
}

TEST_CASE("handout: chain on a scale, N = 3xmg/L", "[matchers][handout]") {
  // N - (x/L) m g = mdot u with mdot = (m/L) v, u = v and v = sqrt(2 g x)
  REQUIRE_THAT("x/L*m*g + m/L*sqrt(2*g*x)*sqrt(2*g*x)",
               EqualsSymbolically("3*x*m*g/L").assuming("g>0, x>=0, L>0, m>0"));
}

TEST_CASE("matchers: a wrong claim fails with a counterexample and both sides", "[matchers]") {
  Impact s;
  // a dropped minus: (m1 + m2) instead of (m1 - m2)
  ex wrong = ((s.m1 + s.m2) * s.v1 + 2 * s.m2 * s.v2) / (s.m1 + s.m2);
  auto m = EqualsSymbolically(wrong).assuming("m1>0, m2>0");
  CHECK_FALSE(m.match(s.v1p_general.subs(s.e == 1)));
  REQUIRE(m.verdict() != nullptr);
  CHECK(m.verdict()->kind == dc::VerdictKind::Refuted);
  std::string d = m.describe();
  CHECK_THAT(d, Catch::Contains("refuted"));
  CHECK_THAT(d, Catch::Contains("counterexample:"));
  CHECK_THAT(d, Catch::Contains("lhs = "));
  CHECK_THAT(d, Catch::StartsWith("equals symbolically (2*m2*v2 + v1*(m1 + m2))/(m1 + m2) assuming m1>0, m2>0\n"));
  // the description is deterministic: the same text for a second, independent match
  auto m2 = EqualsSymbolically(wrong).assuming("m1>0, m2>0");
  CHECK_FALSE(m2.match(s.v1p_general.subs(s.e == 1)));
  CHECK(m2.describe() == d);
}

TEST_CASE("matchers: domains matter (sqrt(x^2) = x only for positive x)", "[matchers]") {
  CHECK_THAT("sqrt(x^2)", EqualsSymbolically("x").assuming("x>0"));
  auto m = EqualsSymbolically("x");
  CHECK_FALSE(m.match("sqrt(x^2)"));  // x real: refuted at a negative x
  REQUIRE(m.verdict() != nullptr);
  CHECK(m.verdict()->kind == dc::VerdictKind::Refuted);
}

TEST_CASE("matchers: malformed input is reported, not a crash", "[matchers]") {
  auto m = EqualsSymbolically("x").assuming("x >");
  CHECK_FALSE(m.match("x"));
  CHECK_THAT(m.describe(), Catch::Contains("not decided"));
  auto m2 = EqualsSymbolically("x + ");
  CHECK_FALSE(m2.match("x"));
  CHECK_THAT(m2.describe(), Catch::Contains("error"));
}

TEST_CASE("matchers: Catch prints GiNaC expressions with the deterministic printer", "[matchers]") {
  symbol a("a"), b("b");
  CHECK(Catch::StringMaker<ex>::convert(b - a) == "b - a");
  CHECK(Catch::StringMaker<ex>::convert(a * a / (a + b)) == "a^2/(a + b)");
}
