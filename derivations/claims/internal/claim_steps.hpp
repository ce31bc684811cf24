// A claim of the bank, and `derivcheck equal`, as the one-step derivation a .dc author would
// write for it (docs/cli.md, "A claim is a one-step derivation"). The derivation is built in
// memory and checked by check_step, the code of the .dc rules, so a claim and its .dc form
// cannot disagree. Nothing is decided here: each function only translates.
//
//   equal               lhs = rhs  by rewrite            (by integrate when a side has integral(...))
//   limit               lhs = rhs  by limit x -> p[+|-]  (rhs may be oo, -oo, undefined)
//   series              lhs = rhs  by series x -> p[+|-] to order N
//   series_first_order  lhs = rhs  by series x -> p[+|-]   (first order: lhs - rhs = O((x - p)^2))
//   antiderivative      integral(lhs, x) = rhs  by integrate
//   solves_ode          ode: LHS = RHS  by given         (y, yp, ypp as y(x), diff(y(x), x), diff(y(x), x, 2))
//                       claim: y(x) = solution  by solves_ode ode wrt x with y(a) = v, y'(b) = w
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "derivations/reader/derivation.hpp"
#include "derivations/rules/check.hpp"

namespace dc::claims {

// Where a limit or series claim goes: x -> point from `dir` (+1 above, -1 below, 0 both).
struct Approach {
  Node var;      // the variable, a Symbol node
  Node point;    // a value, or `oo` / `-oo`
  int dir = 0;
};

// `y(at) = value` (order 0) or `y'(at) = value` (order 1): an initial value of an ODE claim.
struct InitialValue {
  Node at, value;
  int order = 0;
};

// Each returns the derivation, indexed, whose last step is the claim. `file` names the source
// (positions in the nodes point into the claim's fields).
Derivation equal_derivation(const std::string& file, const SymbolTable& table, const Node& lhs, const Node& rhs);
// rhs: a value, or `oo`, `-oo`, `undefined` (which the limit rule reads as limit values).
Derivation limit_derivation(const std::string& file, const SymbolTable& table, const Node& lhs, const Node& rhs,
                            const Approach& a);
// order: `to order N` (nullopt: the first-order form of the rule); order_term: the O(...) term
// the claim's rhs ended in (already taken off rhs), kept for printing as the reader keeps it.
Derivation series_derivation(const std::string& file, const SymbolTable& table, const Node& lhs, const Node& rhs,
                             const Approach& a, std::optional<int> order, const std::optional<Node>& order_term);
// integral(f, x) = G  by integrate
Derivation antiderivative_derivation(const std::string& file, const SymbolTable& table, const Node& f, const Node& G,
                                     const Node& var);
// The ODE's sides are in y, yp, ypp; `table` must declare the function y(var) and not the
// symbols y, yp, ypp (ode_function_table in claims.cpp builds it).
Derivation ode_derivation(const std::string& file, const SymbolTable& table, const Node& ode_lhs, const Node& ode_rhs,
                          const Node& var, const Node& solution, const std::vector<InitialValue>& initial);

// The names of the ODE's unknown function and its derivatives in a solves_ode claim.
inline constexpr const char* kOdeNames[] = {"y", "yp", "ypp"};
// An ODE side as the .dc file writes it: y -> y(var), yp -> diff(y(var), var),
// ypp -> diff(y(var), var, 2).
Node ode_form(const Node& side, const Node& var);

// check_step on the derivation's last step.
StepResult check_last_step(const Derivation& d, const ProveOptions& opt);

// Does the tree contain integral(...)?
bool contains_integral(const Node& n);

}  // namespace dc::claims
