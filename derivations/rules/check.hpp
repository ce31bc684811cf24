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
#include "derivations/steps/step_result.hpp"

namespace dc {

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
