// Is a refutation found after elimination a counterexample to the step? (derivations/steps/,
// shared by the rules) The point must satisfy the references once the eliminated quantities
// are computed from it (docs/soundness.md, "Rules add their own obligations").
#pragma once
#include <string>
#include <vector>

#include "derivations/steps/context.hpp"
#include "derivations/steps/elimination.hpp"

namespace dc::rules {

// Why a point is not (shown to be) a counterexample; `elimination` is the elimination at fault
// when another choice of eliminated atom may avoid the problem.
struct Gap {
  std::string why;                     // "" when the point satisfies the references
  const Elimination* elimination = nullptr;
};

// The counterexample of a Verdict as exact values of the declared symbols (false when a name
// or value cannot be read back).
bool point_values(const StepContext& c, const Verdict& v, GiNaC::exmap& out);

// A refutation found on the reduced sides is a counterexample to the step only when the point,
// extended by the eliminated quantities computed from it, satisfies the references: every
// leftover equation holds there (or is an identity), no coefficient that was divided by
// vanishes there, an eliminated application such as sin(theta) equals the value the references
// give it, and eliminated symbols stay inside their declared domains and the assumptions.
// Quantities that neither the point nor the eliminations fix (m1 in m2 = m1 when the claim
// only involves v1, v2) do not affect the claim: any admissible value will do, so a few are
// drawn from their domains until one satisfies everything.
// Returns an empty gap when a full point is found, otherwise the first gap.
Gap counterexample_gap(StepContext& c, const Reduction& red, const std::vector<Eq>& eqs, const Verdict& v);

}  // namespace dc::rules
