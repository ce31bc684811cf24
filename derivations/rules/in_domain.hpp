// Does a value lie in a declared domain for every admissible value of the parameters? The
// claimed root of `solve` for an unknown declared `in (0, pi/2)` (theta = 3*pi/4 solves
// cos(2*theta) = 0 but is not the root), and the value a named result gives a quantity declared
// `positive` (`M = integral(lambda(x), x, 0, L) = 3*lambda0*L/2`).
//   proved     constant values compared exactly; ranges (asin, acos, atan, the domains' interval
//              arithmetic) or signs the declarations fix;
//   refuted    a point of the parameters where the value leaves the domain (the prover's probe of
//              sqrt((g - lo)^2) = g - lo), or a constant outside it;
//   otherwise  what the prover says of those identities (holds numerically, undecided).
#pragma once
#include <ginac/ginac.h>

#include "derivations/decide/prove.hpp"
#include "derivations/symbolic/symbols.hpp"
#include "derivations/symbolic/verdict.hpp"

namespace dc::rules {

Verdict value_in_domain(const GiNaC::ex& g, const Domain& dom, const SymbolTable& t, const ProveOptions& opt);

}  // namespace dc::rules
