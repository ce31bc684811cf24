// Antiderivatives of the integrands textbooks meet, found by table and rules and always
// verified by differentiation before anyone uses them.
//
// The rules, tried in order on each term of a sum (constant factors pulled out):
//   - polynomials in x;
//   - a table of elementary functions of a linear argument u = a x + b: u^n, 1/u, exp, sin,
//     cos, tan, log, atan, c^u, 1/(1 + u^2), 1/sqrt(1 - u^2);
//   - a polynomial times exp / sin / cos of a linear argument (integration by parts, repeated),
//     and exp times sin or cos of linear arguments (the closed formula);
//   - a polynomial times log of a linear argument (by parts, leaving a rational function);
//   - rational functions: polynomial part, then partial fractions over the rationals (GiNaC's
//     factor) with linear factors of any multiplicity and irreducible quadratic factors to the
//     first power (log + atan);
//   - "derivative divides": f = c g'(x) h(g(x)) for h in the table (x exp(x^2), sin(x) cos(x),
//     x / (1 + x^2)).
// No rule is trusted: the result F is returned only when d/dx F - f is proved zero. An F that
// contains log(u) is valid where u > 0; the caller decides on which interval that holds (or
// flips it to log(-u)) -- see definite.hpp.
#pragma once
#include <optional>
#include <string>

#include <ginac/ginac.h>

#include "derivations/symbolic/symbols.hpp"

namespace dc::integrals {

// nullopt when no rule applies or the candidate fails the derivative check (then `why` says
// which, when given).
std::optional<GiNaC::ex> antiderivative(const GiNaC::ex& f, const GiNaC::symbol& x, const SymbolTable& ctx,
                                        std::string* why = nullptr);

}  // namespace dc::integrals
