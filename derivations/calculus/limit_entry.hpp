// Limits and first-order expansions. GiNaC has no limit(); this is the helper.
#pragma once
#include <optional>
#include <string>

#include <ginac/ginac.h>

#include "derivations/symbolic/calculus_hooks.hpp"
#include "derivations/symbolic/symbols.hpp"

namespace dc {


// lim_{x -> point} f. `point` is a finite exact value, or pass at_infinity = +1 / -1 (then
// `point` and `dir` are ignored). dir: +1 from above (x -> point+), -1 from below, 0 two-sided
// (both one-sided limits that the declared domain of x allows must agree).
// Method: Gruntz's most-rapidly-varying-subexpression algorithm (derivations/limit_engine/) on
// x = point +- 1/t or x = +-t, t -> oo, with budgets (an exhausted budget is undecided, reason
// "budget: ..."); then evaluation with Arb balls along x_k -> point: a certified
// contradiction makes the result undecided ("internal inconsistency").
LimitResult compute_limit(const GiNaC::ex& f, const GiNaC::symbol& x, const GiNaC::ex& point, int at_infinity, int dir,
                          const SymbolTable& ctx);
// Two-sided (dir = 0).
LimitResult compute_limit(const GiNaC::ex& f, const GiNaC::symbol& x, const GiNaC::ex& point, int at_infinity,
                          const SymbolTable& ctx);

// First order in the small quantities `smalls` (each scaled by eps, series to O(eps^2), eps=1):
// used for "higher-order term dm*dv neglected".
GiNaC::ex first_order(const GiNaC::ex& f, const std::vector<GiNaC::symbol>& smalls);

// f = f(point) + f'(point)(x - point) + O((x-point)^2): the first-order series of f in x.
// With `ctx`, the expansion is checked (ball arithmetic) on every side of the point that the
// declared domain of x allows; one that holds only from one side (abs(x) = x + O(x^2) at 0 for
// real x) gives nullopt with the reason.
std::optional<GiNaC::ex> series_first_order(const GiNaC::ex& f, const GiNaC::symbol& x,
                                            const GiNaC::ex& point, std::string* reason = nullptr,
                                            const SymbolTable* ctx = nullptr);

}  // namespace dc
