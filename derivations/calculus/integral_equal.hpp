// A definite integral as a whole side of an equation, `integral(f, x, a, b) = G`, as the rule
// `by integrate` checks it (rules/integrate.cpp; `derivcheck equal` and claims of kind "equal"
// are checked as that step) and the Catch2 matchers. Methods, in order:
//   1. GiNaC integrates a polynomial integrand exactly (integral::eval_integ); the result is
//      compared with G by the prover;
//   2. when the upper limit b is a symbol that the integrand does not contain: G is an
//      antiderivative in b (dG/db = f(b)) that vanishes at b = a, each proved symbolically;
//   3. rigorous quadrature (Arb) at sampled parameter values: a certified difference refutes,
//      agreement everywhere holds numerically.
// Integrals inside larger expressions (and nested ones) are rewritten first: d/dx of an integral
// by Leibniz's rule, f(b) b' - f(a) a', when the integrand is free of x and continuous on the
// whole line; an integral with a polynomial integrand by its exact value. What is left without
// an integral is compared by the prover; an integral neither rewrite handles (a non-polynomial
// integrand inside an expression, an infinite limit) is undecided with that reason, never an
// input error.
#pragma once
#include <optional>

#include <ginac/ginac.h>

#include "derivations/syntax/expr.hpp"
#include "derivations/decide/prove.hpp"
#include "derivations/symbolic/symbols.hpp"
#include "derivations/symbolic/verdict.hpp"

namespace dc {


// nullopt when neither side contains integral(...): the caller proceeds as usual.
std::optional<Verdict> integral_equality(const Node& lhs, const Node& rhs, const SymbolTable& table,
                                         const ProveOptions& opt = {});

}  // namespace dc
