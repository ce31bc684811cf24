// Integer-valued symbols in the cascade (`symbol n : positive integer`, `--assume 'n integer'`).
//
// GiNaC has no integer symbols: an integer quantity is a realsymbol (a possymbol when
// positive), and what its integer values imply is applied here, as a rewriting that holds for
// every integer value of the declared integer symbols:
//   sin(a + k*pi) = (-1)^k sin(a), cos(a + k*pi) = (-1)^k cos(a), tan(a + k*pi) = tan(a),
//   exp(a + k*pi*I) = (-1)^k exp(a),   (-1)^k = (-1)^(k mod 2),   ((-1)^j)^k = (-1)^(j*k),
// for k, j integer-valued: polynomials in the integer symbols with integer coefficients
// (2*n, n*m - 3, n^2). (-1)^k is reduced to the parity of k: its terms with odd
// coefficients, each power of an integer symbol replaced by the symbol (n^2 and n have the
// same parity), so (-1)^(2*n) = 1 and (-1)^(n^2 + n) = 1.
// The probe samples integer symbols at integers only (kernel/sample.hpp), so the numeric
// witness of a proof, and every counterexample, is a point of the declared domain.
#pragma once
#include <ginac/ginac.h>

#include "derivations/symbolic/symbols.hpp"
#include "derivations/symbolic/verdict.hpp"

namespace dc {

// Is e an integer for every value of the symbols (every symbol in it declared integer,
// combined by +, -, * and nonnegative integer powers, with integer coefficients)?
bool integer_valued(const GiNaC::ex& e, const SymbolTable& ctx);

// e with the rewritings above applied everywhere; e itself when it has no integer symbol.
GiNaC::ex reduce_integer_periods(const GiNaC::ex& e, const SymbolTable& ctx);

// prove_equal's cascade with the reduction first: when reducing changes a side and the
// cascade's symbolic stages prove the reduced sides equal, the claim is Proved (method
// "integer periods + ..."); otherwise `cascade` decides the sides as written.
using Cascade = Verdict (*)(const GiNaC::ex&, const GiNaC::ex&, const SymbolTable&, const ProveOptions&);
Verdict with_integer_periods(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const SymbolTable& ctx,
                             const ProveOptions& opt, Cascade cascade);

}  // namespace dc
