// The probe: the kernel's accept/refute decision at sample points (docs/soundness.md).
//
// Points are drawn from the declared domain (every sign the domain allows; magnitudes from
// 10^-30 to 10^30; interval ends approached to 1e-9), exact rationals, constraints enforced.
// At each point both sides are enclosed in Arb balls (ball.hpp) and compared:
//   - a certified difference, or one side real and the other certainly not   -> Refuted, with
//     the point and both values: the counterexample is certified;
//   - |lhs - rhs| bounded below the tolerance, rigorously, at every point      -> HoldsNumerically;
//   - points where neither side is real, exact poles, or no decision at the precision cap are
//     not counted; too few usable points                                      -> Undecided, with why.
// No floating-point evaluation takes part in a verdict.
#pragma once
#include <string>

#include <ginac/ginac.h>

#include "derivations/kernel/ball.hpp"
#include "derivations/symbolic/symbols.hpp"
#include "derivations/symbolic/verdict.hpp"

namespace dc::kernel {

// Decide lhs = rhs numerically on the declared domain of `ctx`. `residual` is the symbolic
// residual reported with an undecided verdict.
Verdict probe(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const SymbolTable& ctx, const ProveOptions& opt,
              const std::string& residual);

// The probe's comparison at one given point (values read from `point` during the evaluation,
// never substituted): the precision raised until the balls decide, an agreement confirmed at
// four times the digits. For points a rule builds itself (a counterexample extended by the
// quantities the references determine).
PointComparison compare_point(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const GiNaC::exmap& point,
                              const ProveOptions& opt);
bool certified_counterexample(const PointComparison& c);   // Differ, LhsOnly or RhsOnly

// A symbolic proof is re-witnessed at an admissible point: the description of a certified
// disagreement there ("at x = 3/7: lhs = ..., rhs = ..."), or "" when the witness agrees or
// cannot decide. A non-empty answer means a symbolic stage is wrong.
std::string witness_contradiction(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const SymbolTable& ctx,
                                  const ProveOptions& opt);

}  // namespace dc::kernel
