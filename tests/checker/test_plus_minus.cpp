// ± and ∓ (rules/plus_minus.hpp): one claim for both signs. The values x = E± of a name the
// references determine are "the solutions are E+ and E-"; anything else holds for each sign,
// every ± of the step and of what it cites read alike.
#include <catch2/catch.hpp>

#include <string>

#include "derivations/reader/derivation.hpp"
#include "derivations/rules/check.hpp"
#include "support/checked.hpp"
#include "derivations/symbolic/symbols.hpp"
#include "derivations/syntax/expr.hpp"

namespace {

using test_support::Checked;

Checked check_text(const std::string& body) { return test_support::check_text(body, "pm.dc"); }

}  // namespace

TEST_CASE("plus-minus: the quadratic formula gives both roots, and only they", "[plus_minus]") {
  using K = dc::VerdictKind;
  Checked c = check_text(
      "symbol x, b, c : real [1]\n"
      "symbol a : positive [1]\n"
      "assume b^2 - 4*a*c > 0\n"
      "quad: a*x^2 + b*x + c = 0\n    by given\n"
      "roots: x = (-b \u00B1 sqrt(b^2 - 4*a*c))/(2*a)\n    by solve quad for x\n"
      "ascii: x = (-b +/- sqrt(b^2 - 4*a*c))/(2*a)\n    by solve quad for x\n"
      "no_two: x = (-b \u00B1 sqrt(b^2 - 4*a*c))/a\n    by solve quad for x\n"
      "sign_slip: x = (-b \u00B1 sqrt(b^2 + 4*a*c))/(2*a)\n    by solve quad for x\n"
      "one_root: x = (-b + sqrt(b^2 - 4*a*c))/(2*a)\n    by solve quad for x\n");
  CHECK(c.kind("roots") == K::Proved);
  CHECK(c.kind("ascii") == K::Proved);
  CHECK(c.kind("no_two") == K::Refuted);
  CHECK(c.at("no_two").derived.find("neither value of x") != std::string::npos);
  CHECK(c.kind("sign_slip") == K::Refuted);
  // without the ±, one root is not "the" solution (the other is a counterexample)
  CHECK(c.kind("one_root") == K::Refuted);
}

TEST_CASE("plus-minus: a speed of either sign from an energy balance", "[plus_minus]") {
  using K = dc::VerdictKind;
  Checked c = check_text(
      "symbol v : real [m/s]\n"
      "symbol g : positive [m/s^2]\n"
      "symbol h : positive [m]\n"
      "energy: v^2/2 = g*h\n    by given\n"
      "speed: v = \u00B1sqrt(2*g*h)\n    by solve energy for v\n"
      "speed_slip: v = \u00B1sqrt(g*h)\n    by solve energy for v\n");
  CHECK(c.kind("speed") == K::Proved);
  CHECK(c.kind("speed_slip") == K::Refuted);
}

TEST_CASE("plus-minus: identities hold for each sign, and a refutation names the sign", "[plus_minus]") {
  using K = dc::VerdictKind;
  Checked c = check_text(
      "symbol y, z : real [1]\n"
      "square: (y \u00B1 z)^2 = y^2 \u00B1 2*y*z + z^2\n    by rewrite\n"
      "square_slip: (y \u00B1 z)^2 = y^2 + 2*y*z + z^2\n    by rewrite\n"
      "opposite: (y \u00B1 z)*(y \u2213 z) = y^2 - z^2\n    by rewrite\n"
      "opposite_slip: (y \u00B1 z)*(y \u00B1 z) = y^2 - z^2\n    by rewrite\n"
      "unary: \u00B1z*\u00B1z = z^2\n    by rewrite\n");
  CHECK(c.kind("square") == K::Proved);
  CHECK(c.kind("square_slip") == K::Refuted);
  CHECK(c.at("square_slip").verdict.method.find("\u00B1 read as -") == 0);
  CHECK(c.kind("opposite") == K::Proved);
  CHECK(c.kind("opposite_slip") == K::Refuted);
  CHECK(c.kind("unary") == K::Proved);
}

TEST_CASE("plus-minus: a step citing a step with plus-minus reads both with one sign", "[plus_minus]") {
  using K = dc::VerdictKind;
  Checked c = check_text(
      "symbol x, y, a, b : real [1]\n"
      "both: x = a \u00B1 b\n    by given\n"
      "twice: y = 2*x\n    by given\n"
      "same: y = 2*a \u00B1 2*b\n    by substitute both into twice\n"
      "crossed: y = 2*a \u2213 2*b\n    by substitute both into twice\n"
      "wrong: y = 3*a \u00B1 2*b\n    by substitute both into twice\n");
  CHECK(c.kind("same") == K::Proved);
  // the signs paired the other way: an author may mean the pairing loosely, so not refuted
  CHECK(c.kind("crossed") == K::Undecided);
  CHECK(c.at("crossed").verdict.reason.find("opposite") != std::string::npos);
  // false with the signs paired either way
  CHECK(c.kind("wrong") == K::Refuted);
}

TEST_CASE("plus-minus: a value that is no solution is never proved", "[plus_minus][soundness]") {
  // (x - 1)^2 = 0 has the one solution 1: the references do imply (x - 1)(x + 1) = 0, but -1
  // satisfies nothing
  Checked c = check_text(
      "symbol x : real [1]\n"
      "double: (x - 1)^2 = 0\n    by given\n"
      "both: x = \u00B11\n    by solve double for x\n");
  CHECK_FALSE(c.at("both").verdict.holds());
}

TEST_CASE("plus-minus: outside a step's check it has no single value", "[plus_minus]") {
  dc::SymbolTable t;
  dc::SymbolInfo a;
  a.name = "a";
  t.declare(a);
  const dc::Node n = dc::parse_expression("1 \u00B1 a", dc::SourcePos{"x", 1, 1});
  CHECK(dc::to_text(n) == "1 \u00B1 a");
  CHECK_THROWS_WITH(dc::to_ginac(n, t), Catch::Contains("has two values here"));
  {
    dc::PlusMinusSign minus(-1);
    CHECK((dc::to_ginac(n, t) - (1 - t.find("a")->sym)).is_zero());
  }
  CHECK_THROWS(dc::to_ginac(n, t));
  // a declared name cannot be pm or mp
  CHECK(dc::is_reserved_name("pm"));
}

TEST_CASE("plus-minus: a reference naming another quantity that contains x in its name is not a condition on x", "[plus_minus]") {
  // v_0 mentions "v" as text, not the symbol v: the values are checked against energy only
  using K = dc::VerdictKind;
  Checked c = check_text(
      "symbol v, v_0 : real [m/s]\n"
      "symbol g : positive [m/s^2]\n"
      "symbol h : positive [m]\n"
      "start: v_0 = 2*g*h/v_0\n    by given\n"
      "energy: v^2/2 = g*h\n    by given\n"
      "speed: v = \u00B1sqrt(2*g*h)\n    by solve energy, start for v\n");
  CHECK(c.kind("speed") == K::Proved);
}
