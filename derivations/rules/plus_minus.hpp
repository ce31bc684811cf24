// A step with ± (`x = (-b ± sqrt(b^2 - 4*a*c))/(2*a)`, `(a ± b)^2 = a^2 ± 2*a*b + b^2`) is one
// claim for both signs. What it claims depends on where the ± is (docs/format.md, "Both signs"):
//   - the claim's values x = E± of a name its references determine, the references free of ±
//     (rules rewrite, substitute and solve, whose claim is "follows from the references"):
//     "the solutions are E+ and E-". Shown as (1) the references imply (x - E+)(x - E-) = 0 (no
//     other solution; refuted with a point where they hold and x is neither), and (2) each
//     branch satisfies every reference that mentions x (proved as an identity; when that cannot
//     be shown the step is undecided, never refuted, since x's references may say more
//     together than one by one);
//   - otherwise (an identity, or references with ± themselves): each sign, every ± of the step
//     and of what it cites read alike, must hold by the step's rule; a refuted sign refutes the
//     step and says which. With cited ± steps, a claim that holds only with the signs paired
//     the other way is undecided, and one refuted only in one pairing too.
#pragma once
#include <functional>

#include "derivations/reader/derivation.hpp"
#include "derivations/steps/step_result.hpp"
#include "derivations/symbolic/verdict.hpp"

namespace dc::rules {

using CheckOne = std::function<StepResult(const Derivation&, const Step&, const ProveOptions&)>;

// Does the step's claim, or a step it cites, contain ±?
bool mentions_plus_minus(const Derivation& d, const Step& s);

// The step checked for both signs, each by `one` (check_step without ±).
StepResult check_both_signs(const Derivation& d, const Step& s, const ProveOptions& opt, const CheckOne& one);

// n with every ± read with `sign` (+1: ± as +, ∓ as -; -1 the other way), as a tree.
Node with_sign(const Node& n, int sign);

}  // namespace dc::rules
