// `by coefficients A for x, t` (rules/coefficients.cpp): a relation that holds for every x and
// t gives one equation per coefficient of its numerator.
#include <catch2/catch.hpp>

#include <string>

#include "support/checked.hpp"

namespace {

using test_support::Checked;
using K = dc::VerdictKind;

Checked check_text(const std::string& body) { return test_support::check_text(body, "coefficients.dc"); }

}  // namespace

TEST_CASE("coefficients: the Lorentz factor from the invariance of the interval", "[coefficients]") {
  Checked c = check_text(
      "symbol x, xp : real [m]\n"
      "symbol t, tp : real [s]\n"
      "symbol c : positive [m/s]\n"
      "symbol v : real [m/s]\n"
      "symbol gamma : positive [1]\n"
      "assume v^2 < c^2\n"
      "xform: xp = gamma*(x - v*t)\n    by given\n"
      "tform: tp = gamma*(t - v*x/c^2)\n    by given\n"
      "invariant: xp^2 - c^2*tp^2 = x^2 - c^2*t^2\n    by given\n"
      "events: gamma^2*(x - v*t)^2 - c^2*gamma^2*(t - v*x/c^2)^2 = x^2 - c^2*t^2\n"
      "    by substitute xform, tform into invariant\n"
      "factor: gamma^2*(1 - v^2/c^2) = 1\n    by coefficients events for x, t\n"
      "factor_slip: gamma^2*(1 + v^2/c^2) = 1\n    by coefficients events for x, t\n"
      "lorentz: gamma = 1/sqrt(1 - v^2/c^2)\n    by coefficients events for x, t\n"
      "lorentz_slip: gamma = 1/sqrt(1 - v/c)\n    by coefficients events for x, t\n");
  CHECK(c.kind("events") == K::Proved);
  CHECK(c.kind("factor") == K::Proved);
  CHECK(c.kind("factor_slip") == K::Refuted);
  CHECK(c.at("factor_slip").derived.find("coefficient by coefficient") != std::string::npos);
  CHECK(c.kind("lorentz") == K::Proved);
  CHECK(c.kind("lorentz_slip") == K::Refuted);
}

TEST_CASE("coefficients: a polynomial identity in one variable, and with a denominator", "[coefficients]") {
  Checked c = check_text(
      "symbol x : real [1]\n"
      "symbol a, b, p, q : real [1]\n"
      "match: a*x^2 + b*x + 1 = (p*x + 1)^2\n    by given\n"
      "a_is: a = p^2\n    by coefficients match for x\n"
      "b_is: b = 2*p\n    by coefficients match for x\n"
      "b_slip: b = p\n    by coefficients match for x\n"
      "frac: (a*x + b)/(x^2 + 1) = (2*x + 3)/(x^2 + 1)\n    by given\n"
      "both: a + b = 5\n    by coefficients frac for x\n"
      "qdef: q = a + 2\n    by given\n"
      "with_ref: q = 2*a\n    by coefficients frac, qdef for x\n");
  CHECK(c.kind("a_is") == K::Proved);
  CHECK(c.kind("b_is") == K::Proved);
  CHECK(c.kind("b_slip") == K::Refuted);
  CHECK(c.kind("both") == K::Proved);
  CHECK(c.kind("with_ref") == K::Proved);
}

TEST_CASE("coefficients: what has no coefficients is an input error", "[coefficients]") {
  Checked c = check_text(
      "symbol x, a : real [1]\n"
      "trig: a*sin(x) = 2*sin(x)\n    by given\n"
      "from_trig: a = 2\n    by coefficients trig for x\n"
      "never: a*x + 1 = a*x + 2\n    by given\n"
      "from_never: a = 0\n    by coefficients never for x\n");
  CHECK(c.has_error("from_trig", "is not a polynomial in x"));
  CHECK(c.has_error("from_never", "cannot hold for every x"));
}
