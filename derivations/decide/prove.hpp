// prove_equal: whether two expressions are equal on the declared domain.
//
// Cascade (each stage only runs when the previous could not decide):
//   1. exact symbolic: normal(a - b) == 0                        -> Proved, method "normal"
//   2. expand with transcendental rules (log of products/powers on positive symbols,
//      exp of sums), then normal                                  -> Proved, "expand (transcendental)"
//   3. side relations: sin^2+cos^2 = 1 etc. via subs_options::algebraic, then normal
//                                                                 -> Proved, "side relations"
//      A symbolic proof is re-witnessed at a sample point by the kernel (witness_contradiction):
//      a certified disagreement there means a symbolic stage was wrong, and nothing is proved.
//   4. the kernel's probe (derivations/kernel/probe.hpp): exact rational points of the declared
//      domain, both sides enclosed in Arb balls; a certified difference -> Refuted (the point and
//      both values); every point agreeing within a rigorous bound -> HoldsNumerically (points,
//      digits, false-accept chance); otherwise Undecided with the reason.
//   5. otherwise Undecided with residual and reason (e.g. "no valid sample points: the
//      constraints exclude every point tried", "resource limit: expansion would exceed 1e6 terms").
// A false claim is never Proved or HoldsNumerically; a true claim is never Refuted.
// Both sides may contain abstract functions (v(t)) and their derivatives: the probe treats
// each distinct application as an independent random value.
#pragma once
#include <cstdint>

#include <ginac/ginac.h>

#include "derivations/syntax/expr.hpp"
#include "derivations/symbolic/symbols.hpp"
#include "derivations/symbolic/inspect.hpp"
#include "derivations/symbolic/verdict.hpp"

namespace dc {


// The domains and constraints in force (normally the derivation's SymbolTable).
Verdict prove_equal(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const SymbolTable& ctx,
                    const ProveOptions& opt = {});

// Is `e` identically zero? (prove_equal(e, 0)).
Verdict prove_zero(const GiNaC::ex& e, const SymbolTable& ctx, const ProveOptions& opt = {});

// Side conditions an expression needs to be defined (divisors != 0, log/sqrt/acos/asin
// arguments), each with whether the domains/constraints guarantee it (checked symbolically
// where the sign is evident, otherwise by sampling: Violated with a point, or Unknown).
std::vector<SideCondition> side_conditions(const GiNaC::ex& e, const SymbolTable& ctx);

// Side conditions of an expression as the author wrote it: every function application,
// power and quotient of the tree is converted on its own, so conditions that GiNaC's automatic
// simplification would erase (exp(log(x)) becomes x) are still found. Subtrees that cannot be
// converted (integral(...), an undecidable limit) are skipped; their arguments are not.
// With `free_of` = "x": only the parts free of x (a limit or series claim is about x near its
// point only; the conditions of the parts without x are claims of their own).
std::vector<SideCondition> side_conditions_of_tree(const Node& n, const SymbolTable& ctx,
                                                   const std::string& free_of = {});

// A claim must hold on the whole declared domain: when a side condition is Violated (a point
// of the domain where a side is certainly undefined), a verdict that holds becomes Refuted
// with that point as the counterexample. Conditions that are only not guaranteed stay warnings.
void require_defined_on_domain(Verdict& v);
// An ODE solution y = G proved by its residual and initial values: if a side condition of G
// that involves the independent variable `var` is not guaranteed (G may be singular inside the
// domain), the verdict becomes undecided — past a singularity G need not be the solution, and a
// G that jumps (atan(1/t) + atan(t)) passes the residual test. Conditions on the values of
// declared functions are left to the author (declared functions are taken to be smooth).
void require_solution_without_singularities(Verdict& v, const std::string& var);
// A claimed antiderivative G of f in `var`, proved by dG/dvar = f: G must be defined (and
// continuous) on the whole declared domain. A side condition of G violated at a point where f
// is defined refutes the claim (log(x) for 1/x with x negative); one that is only not
// guaranteed and involves `var` makes it undecided, as for ODE solutions.
void require_antiderivative_defined(Verdict& v, const GiNaC::ex& integrand, const std::string& var,
                                    const SymbolTable& ctx);

// Do the declared domains and constraints admit at least one point? (An empty set of
// assumptions would let anything follow.) Returns an empty string when satisfiable (a point
// was found), otherwise the reason. Defined in satisfiable.cpp; decide_satisfiable
// (satisfiable.hpp) also says whether a negative answer is certain.
std::string check_satisfiable(const SymbolTable& ctx, std::uint64_t seed = 20261121);



}  // namespace dc
