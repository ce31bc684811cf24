// The result of checking one step: its verdict with the evidence, what the rule derived, and
// for a document row the justification found. Every rule fills one (derivations/rules/), and
// the reports print it (derivations/report/).
#pragma once
#include <string>
#include <vector>

#include "derivations/reader/derivation.hpp"
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

}  // namespace dc
