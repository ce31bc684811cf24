// The adversarial corpus (issue 8): tests/data/adversarial.jsonl holds claims built to mislead
// a checker (nice-point agreement, overflow and lost precision, identities that hold on part of
// the declared domain only, assumptions that make a claim true, true identities that look
// false), each labelled "expect": "true" (an identity on the whole declared domain: must be
// proved or hold numerically) or "false" (false somewhere in the declared domain: must be
// refuted, at worst undecided). tests/data/adversarial/*.dc holds rule-level traps with the
// same convention by label: ok_* true, bad_* false.
//
// The first law: a false claim accepted is the worst bug, so zero false accepts is a hard
// REQUIRE; a true claim refuted is the second worst, also a hard check. Undecided on a true
// claim is allowed (honest) but counted and printed. Every mismatch is listed with its id.
//
// Lines go through dc::check_claim_line, the path of `derivcheck claims`.
// tools/gen-adversarial-corpus.py writes the corpus and checks every expectation with mpmath.
#include <catch2/catch.hpp>

#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "derivations/claims/claims.hpp"
#include "derivations/reader/derivation.hpp"
#include "derivations/report/report.hpp"
#include "derivations/rules/check.hpp"

namespace {

std::string data(const std::string& rel) { return std::string(DERIVCHECK_SOURCE_DIR) + "/tests/data/" + rel; }

bool starts_with(const std::string& s, const std::string& p) { return s.rfind(p, 0) == 0; }

struct Tally {
  std::vector<std::string> false_accepts, false_refutes, undecided_true, undecided_false, errors;
  int n = 0;

  std::string report(const std::string& what) const {
    std::string s = what + ": " + std::to_string(n) + " checked; " + std::to_string(false_accepts.size()) +
                    " false accepts, " + std::to_string(false_refutes.size()) + " false refutes, " +
                    std::to_string(undecided_true.size()) + " true claims undecided, " +
                    std::to_string(undecided_false.size()) + " false claims undecided, " +
                    std::to_string(errors.size()) + " errors\n";
    auto list = [&](const char* title, const std::vector<std::string>& v) {
      if (v.empty()) return;
      s += std::string("  ") + title + ":\n";
      for (const auto& x : v) s += "    " + x + "\n";
    };
    list("FALSE ACCEPTS (expect false, accepted)", false_accepts);
    list("FALSE REFUTES (expect true, refuted)", false_refutes);
    list("errors", errors);
    list("undecided, expect true (allowed)", undecided_true);
    list("undecided, expect false (allowed)", undecided_false);
    return s;
  }
};

std::vector<std::string> corpus_lines() {
  std::ifstream in(data("adversarial.jsonl"));
  std::vector<std::string> out;
  std::string line;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) out.push_back(line);
  return out;
}

}  // namespace

TEST_CASE("the adversarial corpus is well formed: >= 120 claims, every class with true and false members",
          "[adversarial][corpus]") {
  std::vector<std::string> lines = corpus_lines();
  REQUIRE(lines.size() >= 120);
  std::map<std::string, std::pair<int, int>> by_class;   // class -> (true, false)
  std::set<std::string> ids;
  for (const auto& line : lines) {
    nlohmann::json j = nlohmann::json::parse(line);
    CAPTURE(line);
    REQUIRE(j.contains("id"));
    REQUIRE(ids.insert(j.at("id").get<std::string>()).second);   // ids are unique
    REQUIRE(j.contains("kind"));
    REQUIRE(j.contains("class"));
    REQUIRE(j.contains("why"));
    std::string expect = j.at("expect");
    REQUIRE((expect == "true" || expect == "false"));
    auto& c = by_class[j.at("class").get<std::string>()];
    (expect == "true" ? c.first : c.second) += 1;
  }
  for (const char* cls : {"degenerate", "precision", "partial_domain", "assumptions", "suspicious_true"}) {
    CAPTURE(cls);
    REQUIRE(by_class.count(cls));
    CHECK(by_class[cls].first >= 5);
    CHECK(by_class[cls].second >= 5);
  }
}

namespace {

// Known gaps, each a false claim still accepted, listed by id so that the test fails on any
// other false accept. None at present (bad_choose_root and as_chain_allows_negative were fixed:
// derivations/rules/solve_roots.cpp, and the probe's draws inside the region the assumptions
// leave).
const std::set<std::string> kKnownGaps = {};

}  // namespace

TEST_CASE("adversarial corpus: zero false accepts, zero false refutes", "[adversarial]") {
  std::set<std::string> gaps_seen;
  std::vector<std::string> lines = corpus_lines();
  Tally t;
  int line_no = 0;
  for (const auto& line : lines) {
    ++line_no;
    nlohmann::json j = nlohmann::json::parse(line);
    std::string id = j.at("id");
    std::string expect = j.at("expect");
    std::string cls = j.at("class");
    nlohmann::ordered_json r = dc::check_claim_line(line, line_no, "adversarial.jsonl");
    ++t.n;
    std::string verdict = r.value("verdict", "");
    std::string tag = id + " [" + cls + "]: " + verdict;
    if (r.contains("method")) tag += " (" + r.at("method").get<std::string>() + ")";
    bool accepted = verdict == "proved" || verdict == "holds_numerically";
    if (verdict == "error") {
      t.errors.push_back(tag + ": " + r.value("error", ""));
    } else if (expect == "false" && accepted) {
      if (kKnownGaps.count(id)) gaps_seen.insert(id);
      else t.false_accepts.push_back(tag);
    } else if (expect == "true" && verdict == "refuted") {
      t.false_refutes.push_back(tag + ": " + r.value("detail", ""));
    } else if (verdict == "undecided") {
      (expect == "true" ? t.undecided_true : t.undecided_false).push_back(tag + ": " + r.value("reason", ""));
    }
  }
  std::string report = t.report("adversarial.jsonl");
  std::cout << report;
  INFO(report);
  CHECK(t.n >= 120);
  CHECK(t.errors.empty());
  CHECK(t.false_refutes.empty());
  REQUIRE(t.false_accepts.empty());
}

TEST_CASE("adversarial rule traps: bad_* steps never hold, ok_* steps are never refuted", "[adversarial][rules]") {
  std::string file = GENERATE(as<std::string>{}, "solve_root_domain", "rewrite_positive_only", "integrate_references");
  CAPTURE(file);
  dc::Derivation d = dc::load_derivation(data("adversarial/" + file + ".dc"));
  dc::CheckSummary sum = dc::check_derivation(d);
  Tally t;
  int ok = 0, bad = 0;
  for (std::size_t i = 0; i < d.steps.size(); ++i) {
    const dc::Step& s = d.steps[i];
    const dc::StepResult& r = sum.results[i];
    bool is_ok = starts_with(s.label, "ok_"), is_bad = starts_with(s.label, "bad_");
    if (!is_ok && !is_bad) continue;   // premises
    ++t.n;
    (is_ok ? ok : bad) += 1;
    std::string tag = file + ".dc:" + std::to_string(s.pos.line) + " " + s.label + ": " + dc::verdict_phrase(r.verdict);
    if (!r.errors.empty()) {
      std::string errors;
      for (const auto& e : r.errors) errors += e.format();
      t.errors.push_back(tag + ": " + errors);
      continue;
    }
    bool holds = r.verdict.holds();
    if (is_bad && holds && !kKnownGaps.count(s.label)) t.false_accepts.push_back(tag);
    if (is_ok && r.verdict.kind == dc::VerdictKind::Refuted) t.false_refutes.push_back(tag + ": " + r.verdict.detail);
    if (r.verdict.kind == dc::VerdictKind::Undecided)
      (is_ok ? t.undecided_true : t.undecided_false).push_back(tag + ": " + r.verdict.reason);
  }
  std::string report = t.report(file + ".dc");
  std::cout << report;
  INFO(report);
  CHECK(ok >= 1);
  CHECK(bad >= 1);
  CHECK(t.errors.empty());
  CHECK(t.false_refutes.empty());
  REQUIRE(t.false_accepts.empty());
}
