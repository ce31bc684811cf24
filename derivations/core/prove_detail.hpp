// Internals shared by prove.cpp and limit.cpp: deterministic random sampling from symbol
// domains, evaluation at a point (CLN via evalf), sign/range analysis, number formatting and a
// small deterministic printer. Not part of the public interface.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/core/symbols.hpp"

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

// The domain of a symbol (SymbolTable entry; a symbol the table does not know is real, or
// positive when it is a GiNaC possymbol).
// (Symbols travel as GiNaC::ex: copying a realsymbol/possymbol into a GiNaC::symbol slices it
// and the copy no longer compares equal.)
Domain domain_of(const GiNaC::ex& s, const SymbolTable& ctx);

// The symbols of e (each once).
void collect_symbols(const GiNaC::ex& e, GiNaC::exset& out);
// Symbols of e in declaration order (then unknown symbols by name): deterministic, unlike
// GiNaC's traversal order.
std::vector<GiNaC::ex> ordered_symbols(const GiNaC::ex& e, const SymbolTable& ctx);

// 10^k, exact.
GiNaC::numeric pow10(int k);

// --- sampling (sampling.cpp) ---------------------------------------------------------------

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

// Abstract function applications: GiNaC functions that are not one of the evaluable
// built-ins (exp, log, sin, ...) and every fderivative.
bool is_abstract_application(const GiNaC::ex& e);
bool has_abstract_application(const GiNaC::ex& e);
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
// (1 + 10^-8)^(10^8) exactly, x^(x^12) at x = 10^30 for an exponent of 10^360: both hang
// (found by fuzz_expr, docs/hardening.md). There it throws std::range_error, which callers
// treat like a pole: the expression cannot be evaluated at this point. 0^0 and 0^(negative)
// throw before GiNaC::pow is called (GiNaC leaks the power it allocates when evaluation throws).
// Where only a value or a sign is needed, kernel::enclose_at evaluates without substituting.
GiNaC::ex subs_point(const GiNaC::ex& e, const GiNaC::exmap& p);

// Numbers for reports: exact rationals as "7/3"; any real number to `sig` significant
// digits ("2.6253741264076874400e17", "-0.5", "1.2345678901234567890"). Deterministic.
std::string exact_text(const GiNaC::numeric& q);
std::string format_number(const GiNaC::numeric& x, int sig = 20);

// Range analysis over the declared domains (interval arithmetic with exact rational bounds).
struct Range {
  bool lo_inf = true, hi_inf = true;
  GiNaC::numeric lo, hi;
  bool lo_open = true, hi_open = true;
  static Range all() { return {}; }
  bool positive() const;      // every value > 0
  bool negative() const;      // every value < 0
  bool nonnegative() const;   // every value >= 0
  bool nonzero() const { return positive() || negative(); }
  bool within(const GiNaC::numeric& a, const GiNaC::numeric& b) const;   // subset of [a, b]
  std::string to_string() const;
};
Range range_of(const GiNaC::ex& e, const SymbolTable& ctx);

// Sign facts that the domains (and GiNaC's info flags) make evident.
bool provably_positive(const GiNaC::ex& e, const SymbolTable& ctx);
bool provably_nonzero(const GiNaC::ex& e, const SymbolTable& ctx);
bool provably_real(const GiNaC::ex& e, const SymbolTable& ctx);

// Deterministic plain text of a GiNaC expression: operands of sums and products sorted by
// their own text, numbers first in products and last in sums. (A private printer: used for
// residuals and side conditions, never GiNaC's process-dependent print order.)
std::string canon_text(const GiNaC::ex& e);
// Residual text: numerator/denominator expanded and the denominator's sign fixed, so the
// same residual prints identically whatever sign GiNaC's normal() chose for the sub-sums.
// Printed with dc::print_text (the project's deterministic printer). Falls back to a
// term-count note when expansion would be too large.
std::string residual_text(const GiNaC::ex& e, const SymbolTable& ctx, double max_terms = 2000);

}  // namespace dc::detail
