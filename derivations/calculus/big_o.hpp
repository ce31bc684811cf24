// Is a remainder O((x - point)^n) as x -> point (or O(x^-n) as x -> +-oo)? The question every
// truncated series in a textbook asks: sin(x) = x - x^3/6 + O(x^5) holds exactly when
// (sin(x) - x + x^3/6) / x^5 stays bounded near 0. It is decided through the limit engine
// (derivations/calculus/limit_entry.hpp), so Laurent and Puiseux terms, logarithms and poles need no
// series machinery of their own:
//   * the quotient R / gauge tends to a finite value L (on every side the domain allows) ->
//     proved, with L as the evidence (the next term of the expansion is L * gauge);
//   * it tends to +-oo on some side -> refuted (the remainder is not that small);
//   * anything else (no limit, e.g. a bounded oscillation x^5 sin(1/x); undecided limits) ->
//     undecided with the reason. Boundedness without a limit is never guessed.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/syntax/expr.hpp"
#include "derivations/symbolic/symbols.hpp"
#include "derivations/symbolic/verdict.hpp"

namespace dc {

// R = O((x - point)^order) as x -> point from `dir` (+1 above, -1 below, 0 every side the
// declared domain of x allows); with at_infinity = +-1, R = O(x^-order) as x -> +-oo.
// The verdict's lhs_value / rhs_value hold, when refuted, the quotient's limit.
Verdict remainder_is_big_o(const GiNaC::ex& remainder, const GiNaC::symbol& x, const GiNaC::ex& point,
                           int at_infinity, int dir, int order, const SymbolTable& ctx);

// Agreement to first order in small quantities: d = O(eps^2) after every small quantity s
// becomes eps*s, as eps -> 0+ (the gauge above in eps, each s fixed). eps is a fresh positive
// symbol of a copy of ctx (`eps`, or `eps1`, … when the name is taken), its name in *eps_name.
Verdict second_order_in_smalls(const GiNaC::ex& d, const std::vector<GiNaC::ex>& smalls, const SymbolTable& ctx,
                               std::string* eps_name = nullptr);

// "O(x^3)", "O((x - 1)^2)", "O(x^-2) as x -> oo": the gauge as text, for messages.
std::string big_o_text(const GiNaC::symbol& x, const GiNaC::ex& point, int at_infinity, int order,
                       const SymbolTable& ctx);

// The expansion of f up to the gauge: S = the terms of GiNaC's Laurent series of f in
// (x - point) (in 1/x at +-oo) below `order`, returned as an expression in x. Evidence only:
// nullopt when f has no Laurent series there (Puiseux terms, logarithms, essential
// singularities) or GiNaC fails. S is not checked here: the caller confirms f - S = O(gauge)
// (remainder_is_big_o) before showing it.
std::optional<GiNaC::ex> laurent_expansion(const GiNaC::ex& f, const GiNaC::symbol& x, const GiNaC::ex& point,
                                           int at_infinity, int order);

// A side that ends in its order term, as textbooks and other systems write a truncated series:
// `x - x^3/6 + O(x^5)` gives rest `x - x^3/6` and arg `x^5`; `O(x^2)` alone gives rest 0.
// False when the side has no top-level O(...) term.
bool split_order_term(const Node& side, Node& rest, Node& arg);

// The order N of O(g): g = (x - point)^N (x^N at point 0), or g = x^-N as x -> +-oo (O(x^-2)
// gives 2). nullopt, with `why`, for any other gauge.
std::optional<int> order_of_term(const GiNaC::ex& g, const GiNaC::symbol& x, const GiNaC::ex& point, int at_infinity,
                                 std::string* why);

}  // namespace dc
