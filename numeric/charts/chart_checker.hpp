// Work-precision of the checker itself (`derivcheck chart checker`, docs/charts.md): each
// verification strategy of dc::prove_equal run over the labelled claim corpus
// (tests/data/corpus.jsonl, read with dc::check_claim_line) -- time per claim against verdict
// accuracy.
//
// Strategies:
//   "symbolic only"            ProveOptions numeric = false (stages 1-3 of the cascade)
//   "probe k=K, D digits"      symbolic = false, numeric probe with K points at D digits; the
//                              agreement tolerance is 10^-(D-15) relative so that the probe
//                              really works at D digits (prove.cpp raises the precision to
//                              15 digits past the tolerance)
//   "full cascade"             the default ProveOptions (symbolic stages, then the probe)
// A claim is judged correctly when a "holds" claim is proved or holds numerically and a
// "refuted" claim is refuted. "undecided" (and "error") are not correct. A "refuted" claim
// judged proved/holds is a false accept; a "holds" claim judged refuted a false reject.
#pragma once
#include <string>
#include <vector>

#include "derivations/decide/prove.hpp"
#include "numeric/charts/chart_data.hpp"

namespace dc::chart {

struct CheckerStrategy {
  std::string name;     // "symbolic only", "probe k=4, 30 digits", "full cascade"
  std::string family;   // "symbolic", "probe 30 digits", "cascade" (one chart series each)
  ProveOptions opt;
  int k = 0, digits = 0;   // probe points and digits (0 for symbolic only)
};
// Symbolic only, the probe at every k x d, the full cascade (in that order). Throws
// std::invalid_argument for k < 1 or d < 20 (GiNaC's evalf needs about 20 digits).
std::vector<CheckerStrategy> checker_strategies(const std::vector<int>& ks, const std::vector<int>& digits);

struct CheckerOptions {
  int repeats = 3;                       // timed passes over the corpus (median, min, max)
  std::vector<int> ks = {1, 2, 4, 8};
  std::vector<int> digits = {20, 30, 50, 100};
};

struct CheckerRow {
  std::string strategy, family;
  int k = 0, digits = 0;
  int claims = 0, correct = 0, undecided = 0, errors = 0;
  int false_accepts = 0, false_rejects = 0;
  int true_undecided = 0;     // "holds" claims left undecided
  double accuracy = 0;        // correct / claims
  Stat seconds;               // per claim (a pass over the corpus / its size)
  std::vector<std::string> wrong;   // ids judged wrongly or left undecided, "id:verdict"
};

// One labelled claim: the JSON line and its expected verdict ("holds" | "refuted").
struct LabelledClaim {
  std::string id, line, expected;
};
// Reads a JSONL corpus with an "expected" field per line. Throws std::invalid_argument naming
// file and line for an unreadable file, malformed JSON or a missing/unknown label.
std::vector<LabelledClaim> read_corpus(const std::string& path);

CheckerRow run_strategy(const std::vector<LabelledClaim>& corpus, const CheckerStrategy& s, int repeats);
std::vector<CheckerRow> checker_wp(const std::string& corpus_path, const CheckerOptions& opt);
Table to_table(const std::vector<CheckerRow>& rows);

}  // namespace dc::chart
