// The rules (internal to derivations/rules/): one function per rule, each in a file of its own,
// and the table that maps a rule's name to it (dispatch.cpp). Each rule derives its own result
// with GiNaC and asks prove_equal / prove_zero (through them the kernel) whether the author's
// claim equals it; no rule decides equality with `ex == ex`.
#pragma once
#include "derivations/steps/context.hpp"

namespace dc::rules {

using Rule = Verdict (*)(StepContext& c, const Relation& claim);

Verdict given(StepContext& c, const Relation& claim);            // premise.cpp
Verdict definition(StepContext& c, const Relation& claim);       // premise.cpp
Verdict rewrite(StepContext& c, const Relation& claim);          // rewrite.cpp
Verdict substitute(StepContext& c, const Relation& claim);       // substitute.cpp
Verdict solve(StepContext& c, const Relation& claim);            // solve.cpp
Verdict limit(StepContext& c, const Relation& claim);            // limit_series.cpp
Verdict series(StepContext& c, const Relation& claim);           // limit_series.cpp
Verdict first_order(StepContext& c, const Relation& claim);      // limit_series.cpp
Verdict differentiate(StepContext& c, const Relation& claim);    // differentiate.cpp
Verdict integrate(StepContext& c, const Relation& claim);        // integrate.cpp
Verdict integrate_differential(StepContext& c, const Relation& claim);   // integrate_differential.cpp
Verdict solves_ode(StepContext& c, const Relation& claim);       // solves_ode.cpp
Verdict stationary(StepContext& c, const Relation& claim);       // stationary.cpp (also maximum, minimum)
Verdict instance(StepContext& c, const Relation& claim);         // instance.cpp
Verdict coefficients(StepContext& c, const Relation& claim);     // coefficients.cpp

// Run the step's rule on `claim` (its claim, or the printed claim of an erratum). Whatever
// stops the rule becomes an undecided verdict with the reason, and an error in res when the
// input is at fault; never an exception.
Verdict run_rule(const Derivation& d, const Step& s, const Relation& claim, const ProveOptions& opt,
                 StepResult& res);

}  // namespace dc::rules
