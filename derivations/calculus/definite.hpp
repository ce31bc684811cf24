// Definite and improper integrals by an antiderivative:
//
//   integral(f, x, a, b) = lim_{x -> b-} F(x) - lim_{x -> a+} F(x)
//
// where F is an antiderivative of f proved by differentiation (antiderivative.hpp), and f and F
// are defined and continuous on the open interval (a, b). a may be -oo and b may be oo. The
// theorem is the fundamental theorem of calculus on every [c, d] inside (a, b), with the limit
// c -> a+, d -> b- that defines the improper integral. The limits come from the limit engine
// (Gruntz; derivations/calculus/limit_entry.hpp), so an integrable singularity at an end (1/sqrt(x) on
// (0, 1)) or an infinite range (exp(-x) on (0, oo)) is handled like an ordinary end.
//
// Continuity on (a, b) is a list of conditions, each of which must be guaranteed:
//   - a divisor is not 0 and the argument of log, of sqrt or of a fractional power is > 0;
//   - the argument of asin or acos lies in (-1, 1);
//   - cos of the argument of tan is not 0.
// A condition that is a polynomial in x with rational coefficients, on an interval with rational
// or infinite ends, is decided exactly: Sturm's theorem counts its real roots in (a, b). Any
// other condition must follow from the declared domains, with x restricted to (a, b)
// (side_conditions). A log(u) whose u is negative on the whole interval becomes log(-u), which
// has the same derivative.
//
// Outcome: a value (the caller compares it with the claimed one); "diverges" when an end's
// limit of F is infinite; "does not exist" when the engine certifies that a limit does not
// exist (oscillation); otherwise unknown, with the reason. Divergence and non-existence hold
// for every admissible value of the parameters, because each condition was guaranteed for all
// of them.
#pragma once
#include <string>

#include <ginac/ginac.h>

#include "derivations/symbolic/calculus_hooks.hpp"
#include "derivations/symbolic/symbols.hpp"

namespace dc::integrals {


// a_inf = -1 for a = -oo (a ignored), b_inf = +1 for b = oo (b ignored).
Definite definite_integral(const GiNaC::ex& f, const GiNaC::symbol& x, const GiNaC::ex& a, int a_inf,
                           const GiNaC::ex& b, int b_inf, const SymbolTable& ctx);

}  // namespace dc::integrals
