// Checking a derivation: every step goes through its rule (derivations/rules/, one file per
// rule) and gets a verdict with evidence. A rule never silently transforms the claim; it derives
// its own result with GiNaC and asks prove_equal (and through it the kernel,
// derivations/kernel/) whether the author's claim equals it.
#pragma once
#include <string>
#include <vector>

#include "derivations/reader/derivation.hpp"
#include "derivations/decide/prove.hpp"
#include "derivations/symbolic/verdict.hpp"

namespace dc {

struct StepResult {
  const Step* step = nullptr;
  Verdict verdict;
  std::string derived;       // what GiNaC derived, deterministic text ("" when not applicable)
  std::string dimension;     // "kg·m/s" (common dimension of the sides) or ""
  std::vector<InputError> errors;   // dimension mismatches, undefined symbols (erratum), ...
  bool erratum_reported = false;    // the printed claim's error was reported; corrected form checked
  bool premise = false;             // rule given/definition: a premise, checked only for symbols and dimensions
  bool input_error = false;         // the step's input cannot be used (contradictory references): exit code 2
  double seconds = 0;
  // A document step (Step::document_row): the justification the search found — the rule as a
  // .dc `by` line would name it ("rewrite", "follows", "limit", "given") and the steps it used.
  std::string found_rule;
  std::vector<std::string> found_rows;
  // The rule line that was checked, in .dc syntax (`by solve L5, L6 for v1p`), and the claim
  // it was checked on when that is not the row as written (a row of differentials divided by
  // dt): what `derivcheck dc` writes for the row.
  std::string found_line;
  std::string found_claim;
};

StepResult check_step(const Derivation& d, const Step& s, const ProveOptions& opt = {});

struct CheckSummary {
  std::vector<StepResult> results;
  int premises = 0;   // given/definition steps: not claims, so never counted as proved
  int proved = 0, holds_numerically = 0, refuted = 0, undecided = 0, errors = 0, errata = 0;
  int input_errors = 0;   // steps whose references contradict each other (also counted in errors)
  int exit_code(bool strict) const;   // 0 / 1 / 2 / 3 as in docs/format.md
  // Appends the result of the next step (r.step set) and counts it.
  void add(StepResult r);
};

CheckSummary check_derivation(const Derivation& d, const ProveOptions& opt = {});

}  // namespace dc
