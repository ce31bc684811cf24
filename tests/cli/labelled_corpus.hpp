// A labelled claims corpus (JSON lines with "id" and "expected": "true" | "false") run through
// `derivcheck claims` with its budgets, and scored: which false claims were accepted (proved or
// holding numerically), which true ones refuted, which lines were errors, and how many verdicts
// were right. Shared by the published-tests corpus and the adversarial calculus corpus.
#pragma once
#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "cli/cli_run.hpp"

namespace cli_test {

struct CorpusScore {
  std::size_t claims = 0;
  int right = 0;
  std::set<std::string> false_accepts;
  std::vector<std::string> false_refutes, errors;
};

inline CorpusScore score_corpus(const std::string& file) {
  std::vector<nlohmann::json> claims;
  {
    std::ifstream in(file);
    for (std::string l; std::getline(in, l);)
      if (!l.empty()) claims.push_back(nlohmann::json::parse(l));
  }
  CorpusScore s;
  s.claims = claims.size();
  const Run r = run({"claims", "--no-timings", "--jobs", "2", file}, 900);
  std::map<int, nlohmann::json> by_line;
  for (const auto& l : lines_of(r.out)) {
    const auto j = nlohmann::json::parse(l);
    by_line[j.at("line").get<int>()] = j;
  }
  for (std::size_t i = 0; i < claims.size(); ++i) {
    const std::string id = claims[i].at("id");
    const auto it = by_line.find(static_cast<int>(i + 1));
    if (it == by_line.end()) {
      s.errors.push_back(id + ": no result");
      continue;
    }
    const std::string v = it->second.at("verdict");
    const bool expected_true = claims[i].at("expected") == "true";
    const bool holds = v == "proved" || v == "holds_numerically";
    if (v == "error") s.errors.push_back(id);
    if (holds && !expected_true) s.false_accepts.insert(id);
    if (v == "refuted" && expected_true) s.false_refutes.push_back(id);
    if ((holds && expected_true) || (v == "refuted" && !expected_true)) ++s.right;
  }
  return s;
}

}  // namespace cli_test
