// One-sided limits with Gruntz's algorithm, and their numeric witness.
//
//   one_sided_limit:  lim f as x -> point from one side (x = point +- 1/t) or x -> +-oo
//                     (x = +-t), t -> +oo, by Gruntz's algorithm (gruntz.hpp), with the
//                     bounded-factor reductions of oscillation.cpp;
//   check_sequence:   the value confirmed (or contradicted) along x_k -> point with Arb balls.
//
// derivations/calculus/limit_entry.cpp combines the two sides and the witness into a LimitResult.
#pragma once
#include <string>

#include <ginac/ginac.h>

#include "derivations/symbolic/symbols.hpp"
#include "derivations/limit_engine/budget.hpp"

namespace dc::limits {

class Gruntz;

struct LimitOutcome {
  enum class Kind {
    Value,          // a finite limit `value` (may contain parameters)
    PlusInfinity,
    MinusInfinity,
    DoesNotExist,   // certified: oscillation (sin(u) with u -> oo and a nonzero amplitude)
    NotReal,        // certified: f has no real value close to the point on this side
    Undecided       // `reason` says why
  } kind = Kind::Undecided;
  GiNaC::ex value;
  std::string method;  // the evidence: "Gruntz (mrv)", "bounded factor times a factor that tends to 0", ...
  std::string reason;  // DoesNotExist / NotReal / Undecided
  bool infinite() const { return kind == Kind::PlusInfinity || kind == Kind::MinusInfinity; }
  bool decided_limit() const { return kind == Kind::Value || infinite(); }
};

// lim f as x -> point from above (dir = +1) or below (dir = -1), or as x -> +oo / -oo
// (at_infinity = +1 / -1; dir ignored). Never throws: every failure is an Undecided outcome.
LimitOutcome one_sided_limit(const GiNaC::ex& f, const GiNaC::ex& x, const GiNaC::ex& point, int at_infinity, int dir,
                        const SymbolTable& ctx, const Budget& budget = {});

// Called when Gruntz's algorithm met sin/cos of an argument that tends to infinity in g
// (g a function of G's variable, which tends to +oo): a sum of terms that have limits and of
// bounded oscillating factors times factors with limits. Throws Undecided / Oscillates.
LimitOutcome reduce_oscillation(Gruntz& G, const GiNaC::ex& g);

// The outcome of evaluating f along x_k -> point (x_k = point +- 10^-k or +-10^k, k = 2, 4,
// ..., 64) with Arb balls at a sampled admissible point of the parameters.
struct SequenceCheck {
  enum class Kind {
    Confirmed,     // the distance to the limit shrinks and is below 1e-6 (relative) at the last point
    Inconclusive,  // too few usable points, or slow convergence
    Contradicted   // certified: at the last two points f is farther than 1e-3 (relative) from the
                   // limit but moves by less than 1e-5 between them (it settles elsewhere); for
                   // an infinite limit: |f| < 1e6 and moving by less than 1e-3
  } kind = Kind::Inconclusive;
  std::string note;
};
// target: Value (value may contain parameters), PlusInfinity or MinusInfinity.
SequenceCheck check_sequence(const GiNaC::ex& f, const GiNaC::ex& x, const GiNaC::ex& point, int at_infinity, int dir,
                             const LimitOutcome& target, const SymbolTable& ctx);

}  // namespace dc::limits
