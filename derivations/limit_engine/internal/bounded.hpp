// Bounds for oscillating expressions as x -> +oo (bounded.cpp), used by oscillation.cpp.
//
//   enclose:         an interval [lo, hi] (x-free ends) that contains e for every large x, by
//                    interval arithmetic with sin, cos in [-1, 1] and atan in [-pi/2, pi/2]
//                    (AccumBounds, as SymPy calls them), abs, exp, log and powers, and a part
//                    with a finite limit L within |L|/16 of L (1/16 of 0), which holds for
//                    large x; nullopt when e is not shown bounded.
//   factor_dominant: e with every sum R + O, R the terms that have a limit (+-oo) and O the
//                    oscillating ones with O/R -> 0, written R*(1 + O/R): an identity for
//                    large x (R != 0 there), after which the factors have limits of their own
//                    (x/(x + sin(x)) = 1/(1 + sin(x)/x) -> 1).
#pragma once
#include <optional>

#include <ginac/ginac.h>

#include "derivations/limit_engine/gruntz.hpp"

namespace dc::limits {

struct Enclosure {
  GiNaC::ex lo, hi;
};

// Throws BudgetExceeded when the budget runs out; every other failure is nullopt.
std::optional<Enclosure> enclose(Gruntz& G, const GiNaC::ex& e);

// `changed` is set when some sum was rewritten.
GiNaC::ex factor_dominant(Gruntz& G, const GiNaC::ex& e, bool& changed);

}  // namespace dc::limits
