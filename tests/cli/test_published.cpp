// The corpus transcribed from SymPy's published tests (tests/data/published/published.jsonl,
// tools/published-corpus/README.md), run through `derivcheck claims` with its budgets: no false
// claim proved or holding, no true claim refuted, at least 97 % judged right.
#include <nlohmann/json.hpp>

#include <fstream>
#include <map>

#include "cli/cli_run.hpp"

TEST_CASE("published corpus: no false accept, no false refute, >= 97 % right", "[cli][published][soundness]") {
  const std::string file = cli_test::src("tests/data/published/published.jsonl");
  std::vector<nlohmann::json> claims;
  {
    std::ifstream in(file);
    for (std::string l; std::getline(in, l);)
      if (!l.empty()) claims.push_back(nlohmann::json::parse(l));
  }
  REQUIRE(claims.size() >= 600);
  const cli_test::Run r = cli_test::run({"claims", "--no-timings", "--jobs", "2", file}, 900);
  std::map<int, nlohmann::json> by_line;
  for (const auto& l : cli_test::lines_of(r.out)) {
    const auto j = nlohmann::json::parse(l);
    by_line[j.at("line").get<int>()] = j;
  }
  int right = 0;
  std::vector<std::string> false_accepts, false_refutes, errors;
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
    if (holds && !expected_true) false_accepts.push_back(id);
    if (v == "refuted" && expected_true) false_refutes.push_back(id);
    if ((holds && expected_true) || (v == "refuted" && !expected_true)) ++right;
  }
  CAPTURE(false_accepts, false_refutes, errors, right);
  CHECK(false_accepts.empty());
  CHECK(false_refutes.empty());
  CHECK(errors.empty());
  CHECK(right >= static_cast<int>(claims.size()) * 97 / 100);
}
