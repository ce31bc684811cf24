// Elimination (derivations/steps/, shared by the rules): the references give equations E_k = 0;
// variables that an equation determines linearly are eliminated one equation at a time
// (Gaussian elimination over rational functions, with a preference for the unknowns the rule
// names and for symbols of the claim). Eliminating x with E = c*x + r (c != 0 generically)
// parametrises the solution set of the equations, so a claim that holds on it reduces to an
// identity.
//
// Eliminating x with an equation c*x + r = 0 replaces x by -r/c everywhere. That division is
// only allowed when c is not identically zero: u*log(a*b) = u*log(a) + u*log(b) holds for every
// u (a, b positive), and dividing by its coefficient log(a*b) - log(a) - log(b) would "derive"
// u = 0, from which false claims follow.
#pragma once
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "derivations/steps/context.hpp"

namespace dc::rules {

struct Elimination {
  ex var;            // atomized: a symbol, an abstract application's stand-in, sin(theta), omega^2
  ex value;          // var = value in the quantities not eliminated (kept fully substituted)
  ex coef;           // the coefficient divided by, with later eliminations substituted as in value
  ex coef_checked;   // the coefficient when it was shown not to be identically zero
  bool function_atom = false;   // sin(theta), omega^2: a function of symbols that remain
  int equation = -1;            // index of the equation it was eliminated with
  std::string key;              // deterministic text of var
  std::vector<int> sources;     // every equation the value rests on (for messages)
  bool factor_of_zero = false;  // read a product that is zero as one of its factors (c*x = 0 as x = 0)
  ex product;                   // then the product, as it was when read
  ex value_then;                // the value when eliminated, before later eliminations
};

struct Leftover {
  ex e;                         // atomized, reduced; nothing in it could be eliminated
  std::vector<int> sources;
  std::vector<ex> used;         // the eliminated atoms substituted into it
};

struct Reduction {
  std::vector<Elimination> eliminated;
  std::vector<Leftover> leftover;
  int vanished = 0;             // equations that reduced to 0 identically
  bool resource_limit = false;
  bool degenerate = false;      // no elimination order with nonzero coefficients was found
};

using Bans = std::set<std::pair<int, std::string>>;   // (equation, atom) choices that may not be used

// Gaussian elimination, one atom per equation. An elimination whose coefficient turns out to
// vanish identically once later equations are used (c*u = 0, then c = 0) was not allowed: the
// reduction is redone without that choice. `preferred`: atoms to eliminate first (with
// only_preferred, the only ones); `target`: the claim, whose atoms are preferred next.
Reduction reduce(StepContext& c, const std::vector<Eq>& eqs, const ex& target, const std::vector<ex>& preferred,
                 bool only_preferred, Bans banned = {});

// Is the coefficient of an elimination not identically zero on the declared domain? Exact
// tests first (a nonzero number, a sign the domains make evident, a rational function whose
// normal form is not 0); otherwise the probe must find a point where it is nonzero (prove_zero
// refutes it). Identically zero, "holds numerically" and undecided all forbid the division.
bool nonzero_coefficient(StepContext& c, const ex& coef);

// e with every elimination substituted (atoms restored).
ex reduced(StepContext& c, const ex& e, const Reduction& red);
// "v1, dh": the eliminated quantities.
std::string eliminated_text(const StepContext& c, const Reduction& red);

}  // namespace dc::rules
