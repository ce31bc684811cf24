// What a refutation shows beside its verdict: evidence a reader can act on. The values drawn for
// a declared function at the counterexample (without them the point alone does not show why
// the sides differ), and a substitution that leaves an identity said to be one, not printed as
// if it were a derived equation.
#include <catch2/catch.hpp>

#include <string>

#include <nlohmann/json.hpp>

#include "derivations/reader/derivation.hpp"
#include "derivations/report/report.hpp"
#include "derivations/rules/check.hpp"
#include "support/checked.hpp"

namespace {

using test_support::Checked;

Checked check_text(const std::string& body) { return test_support::check_text(body, "evidence.dc"); }

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("a refutation through a declared function shows the function values drawn at the point",
          "[evidence][functions]") {
  Checked c = check_text(
      "symbol x, a, b : real [1]\n"
      "function f(x) : real [1]\n"
      "g: a = f(b)\n    by given\n"
      "wrong: a = f(b) + 1\n    by rewrite g\n");
  const dc::StepResult& r = c.at("wrong");
  REQUIRE(r.verdict.kind == dc::VerdictKind::Refuted);
  CAPTURE(r.verdict.detail);
  // the value of f(b) is what makes the sides differ: it is named, with a number
  CHECK(r.verdict.function_values.rfind("f(b) = ", 0) == 0);
  CHECK(r.verdict.function_values.size() > std::string("f(b) = ").size());
  const std::string text = dc::verdict_evidence(r.verdict, "");
  CAPTURE(text);
  CHECK(contains(text, "function values drawn there: f(b) = "));
  // the JSON carries it as its own field
  const auto j = dc::verdict_json(r.verdict);
  CHECK(j.at("function_values") == r.verdict.function_values);

  // a refutation without declared functions has none
  Checked plain = check_text("symbol a, b : real [1]\ng: a = b\n    by given\nwrong: a = b + 1\n    by rewrite g\n");
  REQUIRE(plain.at("wrong").verdict.kind == dc::VerdictKind::Refuted);
  CHECK(plain.at("wrong").verdict.function_values.empty());
  CHECK_FALSE(dc::verdict_json(plain.at("wrong").verdict).contains("function_values"));
}

TEST_CASE("a substitution that leaves an identity is said to be one", "[evidence][substitute]") {
  Checked c = check_text(
      "symbol a, b : real [1]\n"
      "g: a = b^2 + 1\n    by given\n"
      "wrong: b^2 = a\n    by substitute g into g\n");
  const dc::StepResult& r = c.at("wrong");
  REQUIRE(r.verdict.kind == dc::VerdictKind::Refuted);
  CAPTURE(r.derived);
  CHECK(contains(r.derived, "an identity"));
  CHECK(contains(r.derived, "'g'"));

  // a substitution that derives something shows it plainly
  Checked d = check_text(
      "symbol a, b, c : real [1]\n"
      "g: a = b + c\n    by given\n"
      "h: c = 2*b\n    by given\n"
      "wrong: a = 4*b\n    by substitute h into g\n");
  const dc::StepResult& s = d.at("wrong");
  REQUIRE(s.verdict.kind == dc::VerdictKind::Refuted);
  CAPTURE(s.derived);
  CHECK_FALSE(contains(s.derived, "identity"));
  CHECK(contains(s.derived, "3*b"));
}
