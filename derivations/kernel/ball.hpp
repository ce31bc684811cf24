// Rigorous evaluation of constant expressions with ball arithmetic (Arb).
//
// This is the numeric half of the verdict kernel (docs/soundness.md). Every number the
// checker uses to refute a claim, to accept one numerically, or to decide a side condition at
// a point comes from here: a GiNaC expression without free symbols (exact rationals already
// substituted) is evaluated in Arb's ball arithmetic, which returns an interval guaranteed to
// contain the true value. Nothing here is a floating-point guess:
//   - Value:    a finite real enclosure;
//   - NotReal:  certified: some real-only operation got an argument certainly outside its
//               real domain (log of a negative number, sqrt of a negative number, acos(1.5));
//               the expression has no real value at this point (principal branches);
//   - Pole:     certified: an exact division by zero (1/0, log(0));
//   - Unknown:  the enclosure at this precision cannot decide (a divisor not yet separated
//               from 0, an argument straddling a branch point, overflow of the exponent range
//               we allow); callers raise the precision or give up honestly.
// Exponents are unbounded (exp(exp(exp(10))) is a finite ball with a 40-million-digit
// exponent), so overflow never turns into agreement.
#pragma once
#include <memory>
#include <optional>
#include <string>

#include <ginac/ginac.h>

namespace dc::kernel {

enum class BallStatus { Value, NotReal, Pole, Unknown };

// An enclosure of one expression at one precision. Opaque (holds an Arb ball).
class Ball {
 public:
  Ball();
  ~Ball();
  Ball(Ball&&) noexcept;
  Ball& operator=(Ball&&) noexcept;
  Ball(const Ball&) = delete;
  Ball& operator=(const Ball&) = delete;

  BallStatus status = BallStatus::Unknown;
  long prec_bits = 0;
  std::string why;            // NotReal / Pole / Unknown: the operation responsible

  // Value only:
  bool positive() const;      // every point of the enclosure > 0
  bool negative() const;      // every point < 0
  bool exact_zero() const;    // the enclosure is exactly {0}
  bool contains_zero() const;
  // Decimal text with `sig` significant digits, without the radius ("-0.2166818973", "1.2e+40769447553").
  std::string text(int sig = 20) const;
  // Nearest double (may be +-inf or 0 for values outside double's range).
  double to_double() const;
  // The enclosure's end points as exact rationals (lo <= value <= hi), when both fit in
  // 2^±max_exp_bits; false otherwise (or when not a Value).
  bool exact_bounds(GiNaC::numeric& lo, GiNaC::numeric& hi, long max_exp_bits = 1L << 20) const;
  // Bits of relative accuracy of the enclosure (Arb's arb_rel_accuracy_bits); negative or
  // small when the radius is as large as the value.
  long rel_accuracy_bits() const;

  struct Impl;
  std::unique_ptr<Impl> impl;
};

// Enclose the value of a constant expression at `prec_bits` of working precision.
Ball enclose(const GiNaC::ex& constant, long prec_bits);
// The same at a point: symbols take their values from `point` (exact rationals) during the
// evaluation, without GiNaC's substitution (which evaluates exact powers eagerly).
Ball enclose_at(const GiNaC::ex& e, const GiNaC::exmap* point, long prec_bits);

// Enclose with precision raised (doubling from `start_bits`) until the ball decides `want`
// or `max_bits` is reached. `want`: the sign is known (Value that is positive, negative or
// exactly zero), or any certified status (NotReal / Pole).
Ball enclose_sign(const GiNaC::ex& constant, long start_bits = 128, long max_bits = 1 << 16);
Ball enclose_sign_at(const GiNaC::ex& e, const GiNaC::exmap* point, long start_bits = 128, long max_bits = 1 << 16);
// What enclose_sign stops at: a certified status (NotReal / Pole) or a Value whose sign is known.
bool sign_decided(const Ball& b);

// The outcome of comparing two sides at one point.
struct PointComparison {
  enum class Kind {
    Agree,           // both real; |lhs - rhs| <= tol * max(|lhs|, |rhs|, 1e-300), rigorously
    Differ,          // both real; lhs != rhs, certified (the difference ball excludes 0)
    LhsOnly,         // lhs real, rhs certified not real: a certified counterexample
    RhsOnly,         // rhs real, lhs certified not real
    NeitherReal,     // neither side has a real value here: the point is outside both sides' domain
    IsolatedPole,    // a side divides by an exact zero here (x/x at 0): not a counterexample
    Unknown          // the precision cap was reached without a decision
  } kind = Kind::Unknown;
  double rel_diff = 0;              // Agree: rigorous upper bound; Differ: estimate
  long digits = 0;                  // decimal digits of the precision that decided
  std::string why;                  // Unknown / NeitherReal / IsolatedPole: the reason

  // The two values as decimal text (or "not real: log of a negative number"), `sig` significant
  // digits; for Differ, as many more as it takes to show the difference. Computed when first
  // asked for: converting a ball to decimal costs more than comparing it, and most comparisons
  // (every agreeing sample point) never print their values.
  const std::string& lhs_text() const;
  const std::string& rhs_text() const;

  // The enclosures the texts come from.
  std::shared_ptr<const Ball> lhs_ball, rhs_ball;
  int sig = 20;
  mutable std::optional<std::string> lhs_text_, rhs_text_;
};

struct CompareOptions {
  long start_digits = 50;           // first working precision
  long max_bits = 1 << 16;          // precision cap (about 19700 digits)
  long tol_exponent = -30;          // Agree needs the difference below 10^tol_exponent relative
  int sig = 20;                     // significant digits of the reported values
};

// Compare two enclosures at the precision they were computed with (Unknown when they do not
// decide; the caller may recompute at a higher precision). The comparison keeps the two balls
// (for its texts).
PointComparison compare_balls(Ball&& lhs, Ball&& rhs, long tol_exponent = -30, int sig = 20);

// Compare two constant expressions (a sample point already substituted), raising the
// precision until the comparison is decided or the cap is reached.
PointComparison compare_constants(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const CompareOptions& opt = {});
// The same with the symbols' values read from `point`.
PointComparison compare_at(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const GiNaC::exmap* point,
                           const CompareOptions& opt = {});

}  // namespace dc::kernel
