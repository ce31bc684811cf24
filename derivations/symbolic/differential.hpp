// Differentials: `d(v)`, `d(m_r)`, `d(t)` in an equation such as
//
//   d(v) = -u_e*d(m_r)/m_r - g*d(t)
//
// A differential equation is a linear relation between the small changes of its quantities
// along any motion (a path through the states that the references allow): each term holds
// exactly one differential. `d(x)` of a symbol x is a quantity of its own, a real symbol named
// "d(x)" with the dimension of x, which nothing but the references constrain: a rule that
// proves a differential claim proves it for every path whose changes satisfy the references.
// `d(f(t))` of a declared function of one variable is, by the chain rule, diff(f(t), t)*d(t),
// so the derivative form of an equation of motion and its differential form are related by
// `rewrite` (and `with f(t) = x` in such a step maps diff(f(t), t) to d(x)/d(t)). The
// differential of an expression is not read: the author writes it out by the chain rule
// (d(x^2) = 2*x*d(x)) as a step of its own. Integrating a differential equation between stated
// values is `integrate` (rules/integrate_differential.cpp).
//
// The call `d(...)` is a differential whenever no function `d` is declared, also when `d` is a
// symbol (a distance): a product with d is written d*(...) in .dc.
#pragma once
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/symbolic/symbols.hpp"

namespace dc {

// Is `n` the differential d(arg) (one argument, `d` not a declared function)?
bool is_differential_call(const Node& n, const SymbolTable& table);
// Does `n` contain one?
bool has_differential_call(const Node& n, const SymbolTable& table);

// The name of the differential's symbol: "d(x)".
std::string differential_name(const std::string& of);

// Declares the symbol d(x) for every differential d(x) of a symbol x in `n`, and d(t) for a
// differential d(f(t)) of a function of one variable t (real, the dimension of x). Throws
// InputError at a differential of anything else. The readers call it before converting `n`.
void declare_differentials(const Node& n, SymbolTable& table);

// The value of the differential call `n` (is_differential_call): the symbol d(x), or
// diff(f(t), t)*d(t). Throws InputError when the differential was not declared (a claim read
// outside a derivation file) or is of an expression.
GiNaC::ex differential_value(const Node& n, const SymbolTable& table, const GiNaC::ex& converted_arg);

// The differential symbols in `e`, each with the quantity it is the differential of, in
// declaration order.
struct DifferentialOf {
  GiNaC::ex d;   // the symbol d(x)
  GiNaC::ex x;   // the symbol x
  const SymbolInfo* info;   // the declaration of x
};
std::vector<DifferentialOf> differentials_in(const GiNaC::ex& e, const SymbolTable& table);

// The differential symbol d(x) of the symbol x, if the table declares one; else 0.
GiNaC::ex differential_of(const GiNaC::ex& x, const SymbolTable& table);

}  // namespace dc
