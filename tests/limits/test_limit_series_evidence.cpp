// Evidence of limit and series steps (issue 23, items 3, 13 and 16): a refuted limit names
// the limit and the claimed value as such, a wrong series coefficient shows the expansion with
// the right one, the first-order form means agreement to first order (the truncated form is
// one such claim) on both roads (claim kind and .dc rule), and limits with a bounded
// oscillating part are decided where they exist and never proved where they do not.
#include <catch2/catch.hpp>

#include <string>

#include <nlohmann/json.hpp>

#include "derivations/claims/claims.hpp"
#include "derivations/reader/derivation.hpp"
#include "derivations/report/report.hpp"
#include "derivations/rules/check.hpp"

namespace {

nlohmann::ordered_json claim(const std::string& line) { return dc::check_claim_line(line, 1, "evidence.jsonl"); }

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

struct Checked {
  dc::Derivation d;
  dc::CheckSummary sum;
};

Checked check_text(const std::string& body) {
  Checked c{dc::parse_derivation(dc::SourceText{"evidence.dc", body}), {}};
  c.sum = dc::check_derivation(c.d);
  return c;
}

}  // namespace

TEST_CASE("a refuted limit names the limit and the claimed value", "[limits][evidence]") {
  auto r = claim(R"J({"kind":"limit","lhs":"(1 - cos(x))/x^2","var":"x","point":"0","rhs":"1/3"})J");
  CAPTURE(r.dump());
  REQUIRE(r.at("verdict") == "refuted");
  CHECK(r.at("lhs_label") == "limit");
  CHECK(r.at("rhs_label") == "claimed");
  CHECK(r.at("lhs_value").get<std::string>().rfind("0.5", 0) == 0);
  CHECK(r.at("rhs_value").get<std::string>().rfind("0.333", 0) == 0);

  // the .dc step: the same values under the same names, and the limit as derived
  Checked c = check_text("symbol x : real [1]\nlim: (1 - cos(x))/x^2 = 1/3\n    by limit x -> 0\n");
  const dc::StepResult& s = c.sum.results.at(0);
  REQUIRE(s.verdict.kind == dc::VerdictKind::Refuted);
  CHECK(s.derived == "1/2");
  const std::string text = dc::verdict_evidence(s.verdict, "");
  CAPTURE(text);
  CHECK(contains(text, "limit = 0.5"));
  CHECK(contains(text, "claimed = 0.333"));
  // an infinite limit against a finite claim
  r = claim(R"J({"kind":"limit","lhs":"exp(x)/x","var":"x","point":"oo","rhs":"0"})J");
  CHECK(r.at("verdict") == "refuted");
  CHECK(r.at("lhs_value") == "oo");
  CHECK(r.at("lhs_label") == "limit");
}

TEST_CASE("a wrong series coefficient shows the expansion with the right one", "[limits][series][evidence]") {
  auto r = claim(R"J({"kind":"series","lhs":"sin(x)","rhs":"x - x^3/3 + O(x^5)","var":"x","point":"0"})J");
  CAPTURE(r.dump());
  REQUIRE(r.at("verdict") == "refuted");
  CHECK(contains(r.at("detail"), "the expansion is x - x^3/6 + O(x^5)"));
  // at a shifted point and at infinity
  r = claim(R"J({"kind":"series","lhs":"log(x)","rhs":"(x - 1) + (x - 1)^2/2","var":"x","point":"1","order":3})J");
  CAPTURE(r.dump());
  REQUIRE(r.at("verdict") == "refuted");
  CHECK(contains(r.at("detail"), "the expansion is"));
  CHECK(contains(r.at("detail"), "the expansion is x - 1 - (1 - x)^2/2 + O((x - 1)^3)"));
  r = claim(R"J({"kind":"series","lhs":"exp(1/x)","rhs":"1 + 2/x","var":"x","point":"oo","order":2})J");
  CAPTURE(r.dump());
  REQUIRE(r.at("verdict") == "refuted");
  CHECK(contains(r.at("detail"), "the expansion is 1/x + 1 + O(x^-2) as x -> oo"));
  // no Laurent expansion (a square root at 0+): refuted all the same, without an expansion
  r = claim(R"J({"kind":"series","lhs":"sqrt(x)","rhs":"0","var":"x","point":"0","order":1,"dir":"+"})J");
  CHECK(r.at("verdict") == "refuted");
  CHECK(!contains(r.at("detail"), "the expansion is"));

  // the .dc step derives the expansion
  Checked c = check_text("symbol x : real [1]\nser: sin(x) = x - x^3/3 + O(x^5)\n    by series x -> 0\n");
  const dc::StepResult& s = c.sum.results.at(0);
  REQUIRE(s.verdict.kind == dc::VerdictKind::Refuted);
  CHECK(s.derived == "x - x^3/6 + O(x^5)");
  const std::string text = dc::verdict_evidence(s.verdict, "");
  CHECK(contains(text, "remainder over gauge = (lhs - rhs)/x^5 -> oo"));
}

TEST_CASE("first order means agreement to first order, on both roads", "[limits][series][first_order]") {
  // the issue's reproduction: both sides are h + O(h^2)
  auto r = claim(R"J({"kind":"series_first_order","lhs":"log(1/(1 - h))","rhs":"h/(1 - h)","var":"h","point":"0"})J");
  CAPTURE(r.dump());
  CHECK(r.at("verdict") == "proved");
  CHECK(contains(r.at("detail"), "(lhs - rhs)/h^2 -> "));
  r = claim(R"J({"kind":"series_first_order","lhs":"log(1/(1 - h))","rhs":"h*(1 + h)","var":"h","point":"0"})J");
  CHECK(r.at("verdict") == "proved");
  r = claim(R"J({"kind":"series_first_order","lhs":"log(1/(1 - h))","rhs":"1 + h","var":"h","point":"0"})J");
  CHECK(r.at("verdict") == "refuted");
  // not Laurent at the point: one-sided, as `series` does
  r = claim(R"J({"kind":"series_first_order","lhs":"atan(1/x)","rhs":"pi/2 - x","var":"x","point":"0","dir":"+"})J");
  CHECK(r.at("verdict") == "proved");
  r = claim(R"J({"kind":"series_first_order","lhs":"atan(1/x)","rhs":"pi/2 - x","var":"x","point":"0","dir":"-"})J");
  CHECK(r.at("verdict") == "refuted");
  r = claim(R"J({"kind":"series_first_order","lhs":"atan(1/x)","rhs":"pi/2 - x","var":"x","point":"0","dir":"up"})J");
  CHECK(r.at("verdict") == "error");
  // an order term other than O((x - p)^2) is an error of the line
  r = claim(R"J({"kind":"series_first_order","lhs":"sin(x)","rhs":"x + O(x^3)","var":"x","point":"0"})J");
  CHECK(r.at("verdict") == "error");
  r = claim(R"J({"kind":"series_first_order","lhs":"sin(x)","rhs":"x + O(x^2)","var":"x","point":"0"})J");
  CHECK(r.at("verdict") == "proved");

  // the .dc rule first_order with one small quantity: exact and approximate forms agree
  Checked c = check_text(
      "symbol y : positive [1]\nsymbol d : real [1]\nroot: y = sqrt(1 + d)\n    by given\n"
      "a: y = exp(d/2)\n    by first_order d of root\n"
      "b: y^2 = 1 + d\n    by first_order d of root\n"
      "c: y = 1 + d/3\n    by first_order d of root\n");
  CHECK(c.sum.results.at(1).verdict.kind == dc::VerdictKind::Proved);
  CHECK(c.sum.results.at(2).verdict.kind == dc::VerdictKind::Proved);
  CHECK(c.sum.results.at(3).verdict.kind == dc::VerdictKind::Refuted);
  // two small quantities scaled by one eps: the product term is of second order
  c = check_text(
      "symbol m, u : positive [1]\nsymbol dm, dv : real [1]\n"
      "bal: m*dv - dm*dv = u*dm\n    by given\n"
      "ok: dv = u*dm/m\n    by first_order dm, dv of bal\n"
      "exact: dv = u*dm/(m - dm)\n    by first_order dm, dv of bal\n"
      "bad: dv = u*dm/m + dm\n    by first_order dm, dv of bal\n");
  CHECK(c.sum.results.at(1).verdict.kind == dc::VerdictKind::Proved);
  CHECK(c.sum.results.at(2).verdict.kind == dc::VerdictKind::Proved);
  CHECK(c.sum.results.at(3).verdict.kind == dc::VerdictKind::Refuted);
}

TEST_CASE("limits with a bounded oscillating part: decided where they exist, never proved where they do not",
          "[limits][oscillation]") {
  struct Case {
    const char* lhs;
    const char* rhs;
    const char* verdict;
  };
  const Case cases[] = {
      {"x/(x + sin(x))", "1", "proved"},
      {"x/(x + sin(x))", "2", "refuted"},
      {"(x + abs(sin(x)))/x", "1", "proved"},
      {"sqrt(x)/(sqrt(x) + cos(x))", "1", "proved"},
      {"sin(x)/(x + sin(x))", "0", "proved"},
      {"log(x + sin(x))/log(x)", "1", "proved"},
      {"exp(sin(x))*x", "oo", "proved"},
      {"x/(3 + 2*cos(x))", "oo", "proved"},
      {"sin(x)/x", "0", "proved"},
      {"(x + sin(x))/x", "1", "proved"},
      {"x*sin(x)", "undefined", "proved"},
      {"sin(x)", "undefined", "proved"},
      {"x*sin(x)/(x + cos(x))", "undefined", "proved"},
  };
  for (const Case& k : cases) {
    auto r = claim(std::string(R"J({"kind":"limit","var":"x","point":"oo","lhs":")J") + k.lhs + R"J(","rhs":")J" + k.rhs +
                   "\"}");
    CAPTURE(k.lhs, k.rhs, r.dump());
    CHECK(r.at("verdict") == k.verdict);
  }
  // no limit: never proved equal to anything (undecided or refuted)
  const char* no_limit[] = {"x + x*sin(x)", "x*(1 + sin(x))", "x*abs(sin(x))", "x*exp(sin(x)) - x",
                            "x/(x + x*sin(x)/2)", "x*(2 + sin(x)) - 2*x", "x^2/(x + sin(x)) - x"};
  for (const char* lhs : no_limit)
    for (const char* rhs : {"oo", "-oo", "0", "1", "2"}) {
      auto r = claim(std::string(R"J({"kind":"limit","var":"x","point":"oo","lhs":")J") + lhs + R"J(","rhs":")J" + rhs +
                     "\"}");
      CAPTURE(lhs, rhs, r.dump());
      CHECK(r.at("verdict") != "proved");
      CHECK(r.at("verdict") != "holds_numerically");
    }
}
