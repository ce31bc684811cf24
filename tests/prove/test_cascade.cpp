// prove_equal: each stage of the cascade on the identities it exists for, and the traps where
// a careless prover would accept a false claim or refute a true one.
#include <catch2/catch.hpp>

#include "derivations/symbolic/functions.hpp"
#include "derivations/decide/prove.hpp"
#include "support.hpp"

using namespace dc;
using GiNaC::ex;
using dc::test::describe;

namespace {

test::Table standard_table() {
  test::Table T;
  T.add("x", Domain::real())
      .add("y", Domain::real())
      .add("xp", Domain::positive())
      .add("a", Domain::positive())
      .add("b", Domain::positive())
      .add("z", test::unit_interval())
      .add("zn", Domain::interval(-1, false, 0, true))
      .add("zr", Domain::real());
  return T;
}

}  // namespace

TEST_CASE("stage 1: normal decides rational identities", "[prove][normal]") {
  test::Table T = standard_table();
  ex a = T["a"], b = T["b"];
  Verdict v = prove_equal(GiNaC::pow(a + b, 2), a * a + 2 * a * b + b * b, T.t);
  CAPTURE(describe(v));
  REQUIRE(v.kind == VerdictKind::Proved);
  REQUIRE(v.method == "normal");
  REQUIRE(v.holds());
}

TEST_CASE("stage 2: log and exp rules on positive symbols", "[prove][transcendental]") {
  test::Table T = standard_table();
  ex a = T["a"], b = T["b"], x = T["x"], y = T["y"];
  SECTION("log(a*b) = log(a) + log(b) for positive a, b") {
    Verdict v = prove_equal(GiNaC::log(a * b), GiNaC::log(a) + GiNaC::log(b), T.t);
    CAPTURE(describe(v));
    REQUIRE(v.kind == VerdictKind::Proved);
    REQUIRE(v.method == "expand (transcendental)");
  }
  SECTION("log of quotients and powers") {
    Verdict v = prove_equal(GiNaC::log(GiNaC::pow(a, 3) / GiNaC::sqrt(b)),
                            3 * GiNaC::log(a) - GiNaC::log(b) / 2, T.t);
    CAPTURE(describe(v));
    REQUIRE(v.kind == VerdictKind::Proved);
  }
  SECTION("constant logs: log(6) = log(2) + log(3)") {
    Verdict v = prove_equal(GiNaC::log(ex(6)), GiNaC::log(ex(2)) + GiNaC::log(ex(3)), T.t);
    CAPTURE(describe(v));
    REQUIRE(v.kind == VerdictKind::Proved);
  }
  SECTION("exp of a sum, exp(2 log a) = a^2") {
    Verdict v = prove_equal(GiNaC::exp(x + 2 * GiNaC::log(a)), GiNaC::exp(x) * a * a, T.t);
    CAPTURE(describe(v));
    REQUIRE(v.kind == VerdictKind::Proved);
  }
  SECTION("log(x*y) for real x, y is not an identity: refuted where only one side is real") {
    Verdict v = prove_equal(GiNaC::log(x * y), GiNaC::log(x) + GiNaC::log(y), T.t);
    CAPTURE(describe(v));
    // at x, y < 0 the left side is real and the right side is not: a certified counterexample
    REQUIRE(v.kind == VerdictKind::Refuted);
    REQUIRE(v.point.size() == 2);
    REQUIRE(v.point[0].second.rfind('-', 0) == 0);
    REQUIRE(v.point[1].second.rfind('-', 0) == 0);
    // and the checker says which declaration makes it hold
    REQUIRE(v.hint == "holds if x, y are positive: declare x, y positive");
  }
}

TEST_CASE("stage 2: a root of a factorable sum takes out its positive factors", "[prove][transcendental]") {
  test::Table T = standard_table();
  ex a = T["a"], x = T["x"], y = T["y"];
  // numeric content: sqrt(4 x^2 + 4 y^2) = 2 sqrt(x^2 + y^2), for any real x, y
  Verdict v = prove_equal(GiNaC::sqrt(4 * x * x + 4 * y * y), 2 * GiNaC::sqrt(x * x + y * y), T.t);
  CAPTURE(describe(v));
  CHECK(v.kind == VerdictKind::Proved);
  // a positive factor: sqrt(a^2 x^2 + a^2 y^2) = a sqrt(x^2 + y^2) for a > 0
  Verdict w = prove_equal(GiNaC::sqrt(a * a * x * x + a * a * y * y), a * GiNaC::sqrt(x * x + y * y), T.t);
  CAPTURE(describe(w));
  CHECK(w.kind == VerdictKind::Proved);
  // the same with a real factor is false (x < 0): never proved
  Verdict u = prove_equal(GiNaC::sqrt(x * x * a * a + x * x * y * y), x * GiNaC::sqrt(a * a + y * y), T.t);
  CAPTURE(describe(u));
  CHECK(u.kind == VerdictKind::Refuted);
}

TEST_CASE("stage 3: side relations", "[prove][side-relations]") {
  test::Table T = standard_table();
  ex x = T["x"];
  Verdict v1 = prove_equal(GiNaC::pow(GiNaC::sin(x), 2) + GiNaC::pow(GiNaC::cos(x), 2), 1, T.t);
  CAPTURE(describe(v1));
  REQUIRE(v1.kind == VerdictKind::Proved);
  REQUIRE(v1.method == "side relations");
  Verdict v2 = prove_equal(GiNaC::pow(GiNaC::sin(x), 4) - GiNaC::pow(GiNaC::cos(x), 4),
                           GiNaC::pow(GiNaC::sin(x), 2) - GiNaC::pow(GiNaC::cos(x), 2), T.t);
  CAPTURE(describe(v2));
  REQUIRE(v2.kind == VerdictKind::Proved);
  Verdict v3 = prove_equal(GiNaC::pow(GiNaC::tan(x), 2) + 1, 1 / GiNaC::pow(GiNaC::cos(x), 2), T.t);
  CAPTURE(describe(v3));
  REQUIRE(v3.kind == VerdictKind::Proved);
}

TEST_CASE("sqrt(x^2) = x: proved for positive x, refuted for real x", "[prove][trap]") {
  test::Table T = standard_table();
  Verdict pos = prove_equal(GiNaC::sqrt(GiNaC::pow(T["xp"], 2)), T["xp"], T.t);
  CAPTURE(describe(pos));
  REQUIRE(pos.kind == VerdictKind::Proved);
  Verdict real = prove_equal(GiNaC::sqrt(GiNaC::pow(T["x"], 2)), T["x"], T.t);
  CAPTURE(describe(real));
  REQUIRE(real.kind == VerdictKind::Refuted);
  REQUIRE(real.point.size() == 1);
  REQUIRE(real.point[0].first == "x");
  REQUIRE(real.point[0].second[0] == '-');          // the counterexample is negative
  REQUIRE(real.point[0].second.find('/') != std::string::npos);  // an exact rational
  REQUIRE(real.lhs_value == real.rhs_value.substr(1));  // |x| against x
}

TEST_CASE("exp(pi*sqrt(163)) = 640320^3 + 744 is refuted (needs 50 digits)", "[prove][trap]") {
  test::Table T = standard_table();
  ex lhs = GiNaC::exp(GiNaC::Pi * GiNaC::sqrt(ex(163)));
  ex rhs = GiNaC::pow(ex(640320), 3) + 744;
  Verdict v = prove_equal(lhs, rhs, T.t);
  CAPTURE(describe(v));
  REQUIRE(v.kind == VerdictKind::Refuted);
  REQUIRE(v.point.empty());  // a constant claim: no symbols
  REQUIRE(v.lhs_value != v.rhs_value);
  REQUIRE(v.lhs_value.rfind("262537412640768743.99999999999", 0) == 0);
  // At double precision (16 digits) the two sides print the same: the naive check would pass.
  REQUIRE(GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(lhs)).to_double() ==
          GiNaC::ex_to<GiNaC::numeric>(rhs).to_double());
}

TEST_CASE("acos(1-2z^2) = 2 asin(z): holds for z in 0..1, refuted for z in -1..0", "[prove][probe]") {
  test::Table T = standard_table();
  auto claim = [&](const ex& z) { return std::make_pair(GiNaC::acos(1 - 2 * z * z), 2 * GiNaC::asin(z)); };
  auto [l1, r1] = claim(T["z"]);
  Verdict v1 = prove_equal(l1, r1, T.t);
  CAPTURE(describe(v1));
  REQUIRE(v1.kind == VerdictKind::HoldsNumerically);
  REQUIRE(v1.points >= 6);
  REQUIRE(v1.digits >= 50);
  REQUIRE(!v1.false_accept.empty());
  auto [l2, r2] = claim(T["zn"]);
  Verdict v2 = prove_equal(l2, r2, T.t);
  CAPTURE(describe(v2));
  REQUIRE(v2.kind == VerdictKind::Refuted);
  REQUIRE(v2.point.at(0).first == "zn");
  // real z: points with |z| > 1 are undefined and rejected, negative z refute
  auto [l3, r3] = claim(T["zr"]);
  Verdict v3 = prove_equal(l3, r3, T.t);
  CAPTURE(describe(v3));
  REQUIRE(v3.kind == VerdictKind::Refuted);
}

TEST_CASE("atan(x) + atan(1/x) = pi/2: holds for x > 0, refuted for real x", "[prove][probe]") {
  test::Table T = standard_table();
  Verdict pos = prove_equal(GiNaC::atan(T["xp"]) + GiNaC::atan(1 / T["xp"]), GiNaC::Pi / 2, T.t);
  CAPTURE(describe(pos));
  REQUIRE(pos.kind == VerdictKind::HoldsNumerically);
  Verdict real = prove_equal(GiNaC::atan(T["x"]) + GiNaC::atan(1 / T["x"]), GiNaC::Pi / 2, T.t);
  CAPTURE(describe(real));
  REQUIRE(real.kind == VerdictKind::Refuted);
  REQUIRE(real.point.at(0).second[0] == '-');
}

TEST_CASE("true identities with cancellation are not refuted by rounding noise", "[prove][probe]") {
  test::Table T = standard_table();
  ex x = T["x"];
  // Both sides are exactly 0 at every point, but the left side evaluates to rounding noise.
  ex lhs = GiNaC::sin(2 * x) - 2 * GiNaC::sin(x) * GiNaC::cos(x);
  Verdict v = prove_equal(lhs, 0, T.t);
  CAPTURE(describe(v));
  REQUIRE(v.kind == VerdictKind::HoldsNumerically);
  // Large terms cancelling: (x + 10^40)^2 - 10^80 - 2*10^40*x = x^2 with a transcendental twist
  ex big = GiNaC::pow(ex(10), 40);
  ex lhs2 = GiNaC::pow(GiNaC::exp(x) + big, 2) - big * big - 2 * big * GiNaC::exp(x);
  Verdict v2 = prove_equal(lhs2, GiNaC::exp(2 * x), T.t);
  CAPTURE(describe(v2));
  REQUIRE(v2.holds());
}

TEST_CASE("options: symbolic only, numeric only, probe points, digits", "[prove][options]") {
  test::Table T = standard_table();
  ex a = T["a"], b = T["b"];
  ProveOptions sym_only;
  sym_only.numeric = false;
  Verdict v = prove_equal(GiNaC::atan(a) + GiNaC::atan(1 / a), GiNaC::Pi / 2, T.t, sym_only);
  CAPTURE(describe(v));
  REQUIRE(v.kind == VerdictKind::Undecided);
  REQUIRE(!v.residual.empty());
  ProveOptions num_only;
  num_only.symbolic = false;
  num_only.probe_points = 3;
  num_only.digits = 100;
  Verdict w = prove_equal(GiNaC::pow(a + b, 2), a * a + 2 * a * b + b * b, T.t, num_only);
  CAPTURE(describe(w));
  REQUIRE(w.kind == VerdictKind::HoldsNumerically);
  REQUIRE(w.points == 3);
  REQUIRE(w.digits == 100);
}

TEST_CASE("resource limit: a runaway expansion is not attempted, the probe still decides", "[prove][limits]") {
  test::Table T = standard_table();
  ex a = T["a"], b = T["b"];
  // false: refuted at a point, without expanding
  Verdict v = prove_equal(GiNaC::pow(a + b, 100000), GiNaC::pow(a, 100000) + 100000 * GiNaC::pow(a, 99999) * b, T.t);
  CAPTURE(describe(v));
  REQUIRE(v.kind == VerdictKind::Refuted);
  // true: agrees rigorously at every point, never "proved" (nothing symbolic ran)
  Verdict w = prove_equal(GiNaC::pow(a + b, 100000), GiNaC::pow(a + b, 99999) * (b + a), T.t);
  CAPTURE(describe(w));
  REQUIRE(w.kind != VerdictKind::Proved);
  REQUIRE(w.kind != VerdictKind::Refuted);
  // with the probe off: undecided, saying why
  ProveOptions symbolic_only;
  symbolic_only.numeric = false;
  Verdict u = prove_equal(GiNaC::pow(a + b, 100000), GiNaC::pow(a + b, 100000) + 1, T.t, symbolic_only);
  REQUIRE(u.kind == VerdictKind::Undecided);
  REQUIRE(u.reason.rfind("resource limit:", 0) == 0);
  REQUIRE(estimate_expanded_terms(GiNaC::pow(a + b, 3)) == Approx(4));
  REQUIRE(estimate_expanded_terms(GiNaC::pow(a + b + T["x"], 2)) == Approx(6));
}

TEST_CASE("constraints restrict the probe, contradictory constraints leave it undecided", "[prove][constraints]") {
  test::Table T;
  T.add("u", Domain::real()).add("w", Domain::real());
  ex u = T["u"], w = T["w"];
  // sqrt((u-w)^2) = u - w holds exactly when u > w
  T.assume(u, Constraint::Op::Gt, w, "u > w");
  Verdict v = prove_equal(GiNaC::sqrt(GiNaC::pow(u - w, 2)), u - w, T.t);
  CAPTURE(describe(v));
  REQUIRE(v.kind == VerdictKind::HoldsNumerically);
  T.assume(w, Constraint::Op::Gt, u, "w > u");
  Verdict none = prove_equal(GiNaC::sqrt(GiNaC::pow(u - w, 2)), u - w, T.t);
  CAPTURE(describe(none));
  REQUIRE(none.kind == VerdictKind::Undecided);
  REQUIRE(none.reason.find("no valid sample points") != std::string::npos);
}

TEST_CASE("abstract functions: each application an independent random value", "[prove][functions]") {
  test::Table T;
  T.add("t", Domain::real()).add("m", Domain::positive());
  SymbolInfo vinfo;
  vinfo.name = "v";
  vinfo.is_function = true;
  vinfo.params = {"t"};
  T.t.declare(vinfo);
  ex t = T["t"], m = T["m"];
  ex v = apply_pool_function(T.t.function_index("v"), t);
  const auto& ts = T.sym("t");
  // (9.1) d(mv)/dt = m dv/dt for constant m: normal handles fderivatives as atoms
  Verdict p = prove_equal(GiNaC::diff(m * v, ts), m * GiNaC::diff(v, ts), T.t);
  CAPTURE(describe(p));
  REQUIRE(p.kind == VerdictKind::Proved);
  // a wrong product rule is refuted with random function values
  Verdict wrong = prove_equal(GiNaC::diff(m * v, ts), m * GiNaC::diff(v, ts) + v, T.t);
  CAPTURE(describe(wrong));
  REQUIRE(wrong.kind == VerdictKind::Refuted);
  // the probe needs random values for sin(2 v(t)) = 2 sin(v(t)) cos(v(t))
  Verdict trig = prove_equal(GiNaC::sin(2 * v), 2 * GiNaC::sin(v) * GiNaC::cos(v), T.t);
  CAPTURE(describe(trig));
  REQUIRE(trig.kind == VerdictKind::HoldsNumerically);
  Verdict trig_wrong = prove_equal(GiNaC::sin(2 * v), 2 * GiNaC::sin(v), T.t);
  CAPTURE(describe(trig_wrong));
  REQUIRE(trig_wrong.kind == VerdictKind::Refuted);
  // v(t) and v'(t) are independent: v' = v is not an identity
  Verdict dv = prove_equal(GiNaC::diff(v, ts), v, T.t);
  CAPTURE(describe(dv));
  REQUIRE(dv.kind == VerdictKind::Refuted);
}

TEST_CASE("verdict kinds print as documented", "[prove][verdict]") {
  REQUIRE(std::string(to_string(VerdictKind::Proved)) == "proved");
  REQUIRE(std::string(to_string(VerdictKind::HoldsNumerically)) == "holds_numerically");
  REQUIRE(std::string(to_string(VerdictKind::Refuted)) == "refuted");
  REQUIRE(std::string(to_string(VerdictKind::Undecided)) == "undecided");
}

TEST_CASE("DigitsGuard restores GiNaC::Digits", "[prove][digits]") {
  long before = GiNaC::Digits;
  {
    DigitsGuard g(123);
    REQUIRE(static_cast<long>(GiNaC::Digits) == 123);
    {
      DigitsGuard inner(60);
      REQUIRE(static_cast<long>(GiNaC::Digits) == 60);
    }
    REQUIRE(static_cast<long>(GiNaC::Digits) == 123);
  }
  REQUIRE(static_cast<long>(GiNaC::Digits) == before);
  // prove_equal leaves it untouched
  test::Table T = standard_table();
  prove_equal(GiNaC::atan(T["xp"]) + GiNaC::atan(1 / T["xp"]), GiNaC::Pi / 2, T.t);
  REQUIRE(static_cast<long>(GiNaC::Digits) == before);
}

TEST_CASE("a claim must hold on the whole declared domain: one side real, the other not, refutes", "[prove][probe]") {
  test::Table T = standard_table();
  ex x = T["x"], y = T["y"];
  // For x, y < 0 the right side sqrt(xy) is real and the left side is not (sqrt of a negative
  // number): a certified counterexample on an open part of the domain.
  Verdict v = prove_equal(GiNaC::sqrt(x) * GiNaC::sqrt(y), GiNaC::sqrt(x * y), T.t);
  CAPTURE(describe(v));
  REQUIRE(v.kind == VerdictKind::Refuted);
  REQUIRE(v.lhs_value.find("not real") != std::string::npos);
  REQUIRE(v.hint == "holds if x, y are positive: declare x, y positive");
  // its side conditions say where it is meaningful
  auto conds = side_conditions(GiNaC::sqrt(x) * GiNaC::sqrt(y), T.t);
  REQUIRE(conds.size() == 2);
  for (const auto& c : conds) REQUIRE(c.status == SideCondition::Status::Violated);
  // acos(x) + asin(x) = pi/2 at x > 1: the left side is not real, the constant right side is
  Verdict u = prove_equal(GiNaC::acos(T["zr"]) + GiNaC::asin(T["zr"]), GiNaC::Pi / 2, T.t);
  CAPTURE(describe(u));
  REQUIRE(u.kind == VerdictKind::Refuted);
  // log(x^3) = 3 log(x): where x < 0 neither side is real, so no point refutes it, but the
  // violated side condition x^3 > 0 still fails the claim on the declared (real) domain
  ex lx3 = GiNaC::log(GiNaC::pow(T["zr"], 3)), l3x = 3 * GiNaC::log(T["zr"]);
  Verdict w = prove_equal(lx3, l3x, T.t);
  CAPTURE(describe(w));
  REQUIRE(w.holds());
  w.side_conditions = side_conditions(lx3 - l3x, T.t);
  require_defined_on_domain(w);
  CAPTURE(describe(w));
  REQUIRE(w.kind == VerdictKind::Refuted);
  REQUIRE(!w.point.empty());
}
