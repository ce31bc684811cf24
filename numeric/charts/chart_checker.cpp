#include "numeric/charts/chart_checker.hpp"

#include <chrono>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "derivations/claims/claims.hpp"
#include "derivations/syntax/io.hpp"

namespace dc::chart {

std::vector<CheckerStrategy> checker_strategies(const std::vector<int>& ks, const std::vector<int>& digits) {
  std::vector<CheckerStrategy> out;
  CheckerStrategy sym;
  sym.name = "symbolic only";
  sym.family = "symbolic";
  sym.opt.numeric = false;
  out.push_back(sym);
  for (int d : digits) {
    if (d < 20) throw std::invalid_argument("checker chart: digits = " + std::to_string(d) + " is out of bounds: need >= 20");
    for (int k : ks) {
      if (k < 1) throw std::invalid_argument("checker chart: k = " + std::to_string(k) + " is out of bounds: need k >= 1");
      CheckerStrategy s;
      s.name = "probe k=" + std::to_string(k) + ", " + std::to_string(d) + " digits";
      s.family = "probe " + std::to_string(d) + " digits";
      s.opt.symbolic = false;
      s.opt.numeric = true;
      s.opt.probe_points = k;
      s.opt.digits = d;
      s.opt.rel_tol_exponent = -(d - 15);
      s.k = k, s.digits = d;
      out.push_back(s);
    }
  }
  CheckerStrategy all;
  all.name = "full cascade";
  all.family = "cascade";
  all.k = all.opt.probe_points, all.digits = all.opt.digits;
  out.push_back(all);
  return out;
}

std::vector<LabelledClaim> read_corpus(const std::string& path) {
  std::string text;
  try {
    text = normalize_text(read_file(path));
  } catch (const InputError& e) {
    throw std::invalid_argument(e.message());   // "cannot read 'path': reason"
  }
  std::istringstream in(text);
  std::vector<LabelledClaim> out;
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(line);
    } catch (const nlohmann::json::exception&) {
      throw std::invalid_argument(path + ":" + std::to_string(n) + ": malformed JSON");
    }
    if (!j.is_object() || !j.contains("expected") || !j.at("expected").is_string())
      throw std::invalid_argument(path + ":" + std::to_string(n) + ": missing label 'expected'");
    LabelledClaim c;
    c.expected = j.at("expected").get<std::string>();
    if (c.expected != "holds" && c.expected != "refuted")
      throw std::invalid_argument(path + ":" + std::to_string(n) + ": label 'expected' must be holds or refuted, got '" +
                                  c.expected + "'");
    c.id = j.contains("id") && j.at("id").is_string() ? j.at("id").get<std::string>() : "line " + std::to_string(n);
    c.line = line;
    out.push_back(std::move(c));
  }
  if (out.empty()) throw std::invalid_argument("claim corpus '" + path + "' has no claims");
  return out;
}

CheckerRow run_strategy(const std::vector<LabelledClaim>& corpus, const CheckerStrategy& s, int repeats) {
  if (repeats < 1) throw std::invalid_argument("checker chart: repeats must be >= 1");
  CheckerRow row;
  row.strategy = s.name, row.family = s.family, row.k = s.k, row.digits = s.digits;
  row.claims = static_cast<int>(corpus.size());
  std::vector<double> per_claim;
  for (int r = 0; r < repeats; ++r) {
    std::vector<std::string> verdicts;
    verdicts.reserve(corpus.size());
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < corpus.size(); ++i)
      verdicts.push_back(check_claim_line(corpus[i].line, static_cast<int>(i + 1), "corpus", s.opt).value("verdict", "error"));
    const auto t1 = std::chrono::steady_clock::now();
    per_claim.push_back(std::chrono::duration<double>(t1 - t0).count() / static_cast<double>(corpus.size()));
    if (r > 0) continue;   // verdicts are deterministic (fixed seed); score the first pass
    for (std::size_t i = 0; i < corpus.size(); ++i) {
      const std::string& v = verdicts[i];
      const bool holds = corpus[i].expected == "holds";
      const bool accepted = v == "proved" || v == "holds_numerically";
      bool ok = false;
      if (v == "undecided") {
        ++row.undecided;
        if (holds) ++row.true_undecided;
      } else if (v == "error") {
        ++row.errors;
      } else if (holds) {
        ok = accepted;
        if (v == "refuted") ++row.false_rejects;
      } else {
        ok = v == "refuted";
        if (accepted) ++row.false_accepts;
      }
      if (ok) ++row.correct;
      else row.wrong.push_back(corpus[i].id + ":" + v);
    }
  }
  row.accuracy = static_cast<double>(row.correct) / row.claims;
  row.seconds = stat_of(per_claim);
  return row;
}

std::vector<CheckerRow> checker_wp(const std::string& corpus_path, const CheckerOptions& opt) {
  const auto corpus = read_corpus(corpus_path);
  std::vector<CheckerRow> out;
  const auto strategies = checker_strategies(opt.ks, opt.digits);
  for (std::size_t i = 0; i < strategies.size(); ++i) {
    progress("checker chart: " + strategies[i].name + " (" + std::to_string(i + 1) + "/" +
             std::to_string(strategies.size()) + ")");
    out.push_back(run_strategy(corpus, strategies[i], opt.repeats));
  }
  progress("");
  return out;
}

Table to_table(const std::vector<CheckerRow>& rows) {
  Table t;
  t.columns = {"strategy", "probe_points", "digits", "claims", "correct", "accuracy", "false_accepts", "false_rejects",
               "undecided", "true_claims_undecided", "errors", "seconds_per_claim_median", "seconds_per_claim_min",
               "seconds_per_claim_max", "misjudged"};
  for (const auto& r : rows) {
    std::string wrong;
    for (const auto& w : r.wrong) wrong += (wrong.empty() ? "" : " ") + w;
    t.rows.push_back({r.strategy, std::to_string(r.k), std::to_string(r.digits), std::to_string(r.claims),
                      std::to_string(r.correct), fmt(r.accuracy), std::to_string(r.false_accepts),
                      std::to_string(r.false_rejects), std::to_string(r.undecided), std::to_string(r.true_undecided),
                      std::to_string(r.errors), fmt(r.seconds.median), fmt(r.seconds.min), fmt(r.seconds.max), wrong});
  }
  return t;
}

}  // namespace dc::chart
