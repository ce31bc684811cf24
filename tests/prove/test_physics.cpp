// Handout 9 claims through prove_equal: true forms are proved, realistic slips are refuted
// with a counterexample.
#include <catch2/catch.hpp>

#include "derivations/decide/prove.hpp"
#include "support.hpp"

using namespace dc;
using GiNaC::ex;
using dc::test::describe;

namespace {

struct Impact {
  test::Table T;
  ex m1, m2, v1, v2, e;
  Impact() {
    T.add("m1", Domain::positive())
        .add("m2", Domain::positive())
        .add("v1", Domain::real())
        .add("v2", Domain::real())
        .add("e", test::unit_interval());
    m1 = T["m1"], m2 = T["m2"], v1 = T["v1"], v2 = T["v2"], e = T["e"];
  }
  // general solution of (9.6) momentum and (9.7) restitution
  ex v1p() const { return ((m1 - e * m2) * v1 + (1 + e) * m2 * v2) / (m1 + m2); }
  ex v2p() const { return ((m2 - e * m1) * v2 + (1 + e) * m1 * v1) / (m1 + m2); }
};

}  // namespace

TEST_CASE("impact: (9.6) momentum and (9.7) restitution hold for the general solution", "[prove][physics]") {
  Impact I;
  Verdict mom = prove_equal(I.m1 * I.v1 + I.m2 * I.v2, I.m1 * I.v1p() + I.m2 * I.v2p(), I.T.t);
  CAPTURE(describe(mom));
  REQUIRE(mom.kind == VerdictKind::Proved);
  Verdict rest = prove_equal(I.v2p() - I.v1p(), I.e * (I.v1 - I.v2), I.T.t);
  CAPTURE(describe(rest));
  REQUIRE(rest.kind == VerdictKind::Proved);
}

TEST_CASE("impact: kinetic energy lost, general and e = 0", "[prove][physics]") {
  Impact I;
  ex half = GiNaC::numeric(1, 2);
  ex T0 = half * I.m1 * I.v1 * I.v1 + half * I.m2 * I.v2 * I.v2;
  ex T1 = half * I.m1 * GiNaC::pow(I.v1p(), 2) + half * I.m2 * GiNaC::pow(I.v2p(), 2);
  ex dT = (1 - I.e * I.e) / 2 * I.m1 * I.m2 / (I.m1 + I.m2) * GiNaC::pow(I.v1 - I.v2, 2);
  Verdict v = prove_equal(T0 - T1, dT, I.T.t);
  CAPTURE(describe(v));
  REQUIRE(v.kind == VerdictKind::Proved);
  // e = 0: common velocity and the inelastic loss
  ex vc = (I.m1 * I.v1 + I.m2 * I.v2) / (I.m1 + I.m2);
  Verdict c = prove_equal(I.v1p().subs(I.e == 0), vc, I.T.t);
  REQUIRE(c.kind == VerdictKind::Proved);
  Verdict loss = prove_equal(T0 - half * (I.m1 + I.m2) * vc * vc,
                             half * I.m1 * I.m2 / (I.m1 + I.m2) * GiNaC::pow(I.v1 - I.v2, 2), I.T.t);
  CAPTURE(describe(loss));
  REQUIRE(loss.kind == VerdictKind::Proved);
}

TEST_CASE("impact: realistic slips are refuted with a point in declaration order", "[prove][physics]") {
  Impact I;
  ex half = GiNaC::numeric(1, 2);
  SECTION("sign slip in v1'") {
    ex wrong = ((I.m1 + I.e * I.m2) * I.v1 + (1 + I.e) * I.m2 * I.v2) / (I.m1 + I.m2);
    Verdict v = prove_equal(I.v1p(), wrong, I.T.t);
    CAPTURE(describe(v));
    REQUIRE(v.kind == VerdictKind::Refuted);
    // the point names m1, m2, v1, (v2,) e in declaration order
    REQUIRE(v.point.at(0).first == "m1");
    REQUIRE(v.point.at(1).first == "m2");
    REQUIRE(v.point.back().first == "e");
    REQUIRE(v.lhs_value != v.rhs_value);
  }
  SECTION("missing factor 1/2 in the energy loss") {
    ex T0 = half * I.m1 * I.v1 * I.v1 + half * I.m2 * I.v2 * I.v2;
    ex T1 = half * I.m1 * GiNaC::pow(I.v1p(), 2) + half * I.m2 * GiNaC::pow(I.v2p(), 2);
    ex wrong = (1 - I.e * I.e) * I.m1 * I.m2 / (I.m1 + I.m2) * GiNaC::pow(I.v1 - I.v2, 2);
    Verdict v = prove_equal(T0 - T1, wrong, I.T.t);
    CAPTURE(describe(v));
    REQUIRE(v.kind == VerdictKind::Refuted);
  }
  SECTION("wall impulse without the factor 2") {
    // m2 -> oo, v2 = 0: v1' = -e v1; for e = 1 the impulse is -2 m1 v1
    Verdict v = prove_equal(I.m1 * (-I.v1) - I.m1 * I.v1, -I.m1 * I.v1, I.T.t);
    CAPTURE(describe(v));
    REQUIRE(v.kind == VerdictKind::Refuted);
  }
}

TEST_CASE("rocket and pendulum forms", "[prove][physics]") {
  test::Table T;
  T.add("u_e", Domain::positive())
      .add("m_r", Domain::positive())
      .add("m0", Domain::positive())
      .add("g", Domain::positive())
      .add("t", Domain::nonnegative())
      .add("m", Domain::positive())
      .add("M", Domain::positive())
      .add("v0", Domain::positive())
      .add("L", Domain::positive());
  ex ue = T["u_e"], mr = T["m_r"], m0 = T["m0"], g = T["g"], t = T["t"];
  // v = -u_e ln(m_r/m0) - g t = u_e ln(m0/m_r) - g t
  Verdict v = prove_equal(-ue * GiNaC::log(mr / m0) - g * t, ue * GiNaC::log(m0 / mr) - g * t, T.t);
  CAPTURE(describe(v));
  REQUIRE(v.kind == VerdictKind::Proved);
  // m0/m_r = exp((v + g t)/u_e) with v from above
  ex vv = ue * GiNaC::log(m0 / mr) - g * t;
  Verdict w = prove_equal(m0 / mr, GiNaC::exp((vv + g * t) / ue), T.t);
  CAPTURE(describe(w));
  REQUIRE(w.holds());
  // the wrong sign inside the log is refuted
  Verdict bad = prove_equal(-ue * GiNaC::log(mr / m0), ue * GiNaC::log(mr / m0), T.t);
  REQUIRE(bad.kind == VerdictKind::Refuted);
  // ballistic pendulum: dh = L(1 - cos theta) with theta = acos(1 - (m/(M+m))^2 v0^2/(2 L g))
  ex m = T["m"], M = T["M"], v0 = T["v0"], L = T["L"];
  ex theta = GiNaC::acos(1 - GiNaC::pow(m / (M + m), 2) * v0 * v0 / (2 * L * g));
  Verdict dh = prove_equal(L * (1 - GiNaC::cos(theta)), GiNaC::pow(m / (M + m), 2) * v0 * v0 / (2 * g), T.t);
  CAPTURE(describe(dh));
  REQUIRE(dh.kind == VerdictKind::Proved);
}

TEST_CASE("ballistic pendulum: the half-angle form of theta holds where it is defined", "[prove][physics]") {
  test::Table T;
  T.add("m", Domain::positive()).add("M", Domain::positive()).add("v0", Domain::positive())
      .add("L", Domain::positive()).add("g", Domain::positive());
  ex m = T["m"], M = T["M"], v0 = T["v0"], L = T["L"], g = T["g"];
  ex theta = GiNaC::acos(1 - GiNaC::pow(m / (M + m), 2) * v0 * v0 / (2 * L * g));
  ex half = 2 * GiNaC::asin(m * v0 / (2 * (M + m) * GiNaC::sqrt(L * g)));
  Verdict v = prove_equal(theta, half, T.t);
  CAPTURE(describe(v));
  REQUIRE(v.kind == VerdictKind::HoldsNumerically);
  // without the factor 2 in the half-angle form: refuted
  Verdict w = prove_equal(theta, GiNaC::asin(m * v0 / (2 * (M + m) * GiNaC::sqrt(L * g))), T.t);
  CAPTURE(describe(w));
  REQUIRE(w.kind == VerdictKind::Refuted);
}
