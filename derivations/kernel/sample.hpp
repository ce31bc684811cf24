// Points of the declared domain and values at a point: a deterministic random generator,
// exact rational samples of each symbol's domain (ordinary, extreme and near the boundary of an
// assumption), admissible points for a set of expressions, abstract applications replaced by
// reproducible values, and evaluation of a constant expression (CLN through evalf).
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/symbolic/inspect.hpp"
#include "derivations/symbolic/symbols.hpp"
#include "derivations/symbolic/verdict.hpp"

namespace dc::detail {

// splitmix64: tiny, fast, and identical on every platform (std:: distributions are not).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : s_(seed) {}
  std::uint64_t next();
  double uniform();                              // [0, 1)
  std::uint64_t below(std::uint64_t n);          // [0, n)

 private:
  std::uint64_t s_;
};

std::uint64_t hash_text(const std::string& s, std::uint64_t seed);

// An exact rational close to x (x != 0) to about `resolution`: random denominator so that
// sample points do not sit on a regular grid; never an integer.
GiNaC::numeric rational_near(double x, double resolution, Rng& rng);

// An exact rational drawn from the domain: real -> both signs, magnitude 10^[-2, 2] (tier 0),
// 10^[-6, 6] (tier 1) or 10^[-30, 30] (tiers 2, 3), never 0, +-1 or an integer; intervals ->
// interior points (tier 1 anywhere, tier 2 within 1e-9 of the lower end, tier 3 of the upper).
GiNaC::numeric sample_value(const Domain& d, Rng& rng, int tier);

// A constraint read as a bound on one of its symbols s, the other symbols at their values in p:
// a*s + b OP 0 with a != 0 (a, b turned into exact rationals by `value`) is s OP' at, at = -b/a
// (OP' is OP flipped when a < 0). nullopt when c is not linear in s or a, b are not numbers
// there.
struct LinearBound {
  GiNaC::numeric at;
  Constraint::Op op;
};
std::optional<LinearBound> linear_bound(const Constraint& c, const GiNaC::ex& s, const GiNaC::exmap& p,
                                        const std::function<std::optional<GiNaC::numeric>(const GiNaC::ex&)>& value);

// Sampling of admissible points for a set of expressions: the symbols they use plus every
// symbol linked to them through a constraint, and the constraints that apply.
class PointSampler {
 public:
  PointSampler(const std::vector<GiNaC::ex>& exprs, const SymbolTable& ctx);
  const std::vector<GiNaC::ex>& symbols() const { return syms_; }
  const std::vector<const Constraint*>& constraints() const { return cons_; }
  // A random point of magnitude tier 0-3 (sample_value); tier 4: a tier-0 point with one
  // symbol moved just inside the boundary of one assumption; tier 5: a point drawn inside the
  // region the assumptions leave, symbol by symbol, each within the bounds the assumptions
  // linear in it give once the others have values (near those bounds, between a bound and 0,
  // or an ordinary distance inside; without assumptions, a tier-0 point). `admissible` says
  // whether every applicable constraint holds there.
  GiNaC::exmap draw(Rng& rng, int tier, bool* admissible) const;
  // "m1 = 7/3, m2 = 5/2" in declaration order, and the same as pairs.
  std::vector<std::pair<std::string, std::string>> describe(const GiNaC::exmap& p) const;

 private:
  std::vector<GiNaC::ex> syms_;
  std::vector<Domain> doms_;
  std::vector<const Constraint*> cons_;
};

std::string join_point(const std::vector<std::pair<std::string, std::string>>& pt);
// Replace each abstract application (innermost first) by a pseudo-random rational that
// depends only on (seed, function name, derivative orders, numeric argument values): equal
// applications get equal values, distinct ones independent values.
GiNaC::ex replace_abstract(const GiNaC::ex& e, std::uint64_t seed);

// Evaluation of a constant expression at `digits`. ok=false with a reason when undefined
// (pole, exception) or not real (imaginary part above rounding level).
struct RealValue {
  bool ok = false;
  bool exact = false;        // an exact rational (no rounding)
  GiNaC::numeric value;
  std::string why;
};
RealValue eval_real(const GiNaC::ex& e, long digits);

// e.subs(p) for a point p of exact numbers (no_pattern), refusing what GiNaC would evaluate
// exactly at an absurd cost: a rational base (not 0, +-1) to a rational exponent so large that
// the exact power would have more than a million digits. (1 + 1/x)^x at x = 10^8 asks CLN for
// (1 + 10^-8)^(10^8) exactly, x^(x^12) at x = 10^30 for an exponent of 10^360: both hang.
// There it throws std::range_error, which callers
// treat like a pole: the expression cannot be evaluated at this point. 0^0 and 0^(negative)
// throw before GiNaC::pow is called (GiNaC leaks the power it allocates when evaluation throws).
// Where only a value or a sign is needed, kernel::enclose_at evaluates without substituting.
GiNaC::ex subs_point(const GiNaC::ex& e, const GiNaC::exmap& p);

}  // namespace dc::detail

namespace dc::kernel {

// Does the constraint hold at the point? The sign of lhs - rhs there, certified by ball
// arithmetic; a point where it cannot be certified (undefined, or too close to call) is not
// admissible.
bool holds_at(const Constraint& c, const GiNaC::exmap& point);

}  // namespace dc::kernel
