// The adversarial calculus corpus (tests/data/adversarial_calculus.jsonl: integrals whose
// variable shares a name with a declared quantity, improper and singular integrals, limits and
// series whose answer changes at a parameter value, antiderivatives right on part of the
// domain; each label worked out by hand and checked with mpmath). Run through `derivcheck
// claims` with its budgets: no true claim refuted, no well-formed line an error, and no false
// claim proved or holding except the known gap below -- a new false accept fails the test, and
// so does closing the gap without updating this list.
#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <set>

#include "cli/cli_run.hpp"

TEST_CASE("adversarial calculus corpus: no false refute, no new false accept", "[cli][adversarial][soundness]") {
  const std::string file = cli_test::src("tests/data/adversarial_calculus.jsonl");
  std::vector<nlohmann::json> claims;
  {
    std::ifstream in(file);
    for (std::string l; std::getline(in, l);)
      if (!l.empty()) claims.push_back(nlohmann::json::parse(l));
  }
  REQUIRE(claims.size() >= 350);
  // Known gaps, by id (docs/soundness.md, "Claims false on a null set"): none at present. The
  // three claims false only at a = 0 (sfo_deg_sqrt, int_jump_param_nonneg,
  // int_jump_param_sym_nonneg) held numerically until the probes tried special values.
  const std::set<std::string> known = {};
  const cli_test::Run r = cli_test::run({"claims", "--no-timings", "--jobs", "2", file}, 900);
  std::map<int, nlohmann::json> by_line;
  for (const auto& l : cli_test::lines_of(r.out)) {
    const auto j = nlohmann::json::parse(l);
    by_line[j.at("line").get<int>()] = j;
  }
  int right = 0;
  std::set<std::string> false_accepts;
  std::vector<std::string> false_refutes, errors;
  for (std::size_t i = 0; i < claims.size(); ++i) {
    const auto& c = claims[i];
    const std::string id = c.at("id");
    const auto it = by_line.find(static_cast<int>(i + 1));
    if (it == by_line.end()) {
      errors.push_back(id + ": no result");
      continue;
    }
    const std::string v = it->second.at("verdict");
    const bool expected_true = c.at("expected") == "true";
    const bool holds = v == "proved" || v == "holds_numerically";
    if (v == "error") errors.push_back(id);
    if (holds && !expected_true) false_accepts.insert(id);
    if (v == "refuted" && expected_true) false_refutes.push_back(id);
    if ((holds && expected_true) || (v == "refuted" && !expected_true)) ++right;
  }
  CAPTURE(false_accepts, false_refutes, errors, right);
  CHECK(false_accepts == known);
  CHECK(false_refutes.empty());
  CHECK(errors.empty());
  // 265 of 364 right (the rest undecided, with reasons)
  CHECK(right >= 262);
}
