// Compensated evaluation of a tape: every register holds a double-double (hi + lo, |lo| <=
// ulp(hi)/2, about 106 significant bits) and the result is rounded to double at the end.
//
// Why: a formula whose value crosses zero inside its domain (v'1 = (m1 v1 + m2 v2 - e m2 (v1 -
// v2))/(m1 + m2), the rocket's -u_e ln(m_r/m0) - g t) cancels near the zero in any fixed double
// formula: the terms' rounding errors (relative 2^-53 of the terms) become large relative to the
// small result. In double-double the terms carry 2^-106 relative error, so the cancellation may
// amplify it by up to ~2^50 before the rounded double result is affected by more than an ulp.
//
// Arithmetic (the classic error-free transformations):
//   add/sub   TwoSum on hi and lo parts, renormalised ("accurate" double-double addition)
//   mul       TwoProd with std::fma, cross terms added
//   div       three quotient digits with exact remainders (long division in double-double)
//   sqrt      one Newton step on 1/sqrt in double-double
//   hypot     scaled by a power of two, then sqrt of the double-double sum of squares
// exp, expm1, log, log1p are double-double accurate (~2^-100 relative): exp/expm1 by argument
// reduction (k ln2, then 2^-9) and a Taylor series; log/log1p by one Newton step in
// double-double from the long double value (log near 1 as log1p(x - 1), x - 1 exact there).
// sin, cos, tan, asin, atan, pow are NOT: they are computed in long double (x86-64: 64-bit
// significand, ~2^-64 relative) from the double-double argument rounded to long double, and
// acos(x) for x > 1/2 as 2 asin(sqrt((1 - x)/2)) with 1 - x in double-double. After those the
// value has ~11 bits beyond double, not ~53: a cancellation after them that amplifies by more
// than ~2^10 still shows (no handout formula has one; see docs/numeric.md).
// Overflow: a product or sum that overflows gives +-inf (not NaN from inf - inf in the error
// term), like double evaluation.
#pragma once
#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "numeric/double_double.hpp"
#include "numeric/evaluator.hpp"

namespace dc::num {

struct DD {
  double hi = 0, lo = 0;
};

namespace dd {

// the error-free transformations of numeric/double_double.hpp, as DD values
inline DD quick_two_sum(double a, double b) {
  DD r;
  dde::fast_two_sum(a, b, r.hi, r.lo);
  return r;
}
inline DD two_sum(double a, double b) {
  DD r;
  dde::two_sum(a, b, r.hi, r.lo);
  return r;
}
inline DD two_prod(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};   // exact residual (as dde::prod, without its bound)
}
inline DD finite_or(const DD& r, double raw) {
  // an overflowed (or NaN) partial result: report it as double evaluation would
  return std::isfinite(r.hi) ? r : DD{raw, 0.0};
}

inline DD add(const DD& a, const DD& b) {
  DD s = two_sum(a.hi, b.hi);
  if (!std::isfinite(s.hi)) return {s.hi, 0.0};
  const DD t = two_sum(a.lo, b.lo);
  s.lo += t.hi;
  s = quick_two_sum(s.hi, s.lo);
  s.lo += t.lo;
  return finite_or(quick_two_sum(s.hi, s.lo), a.hi + b.hi);
}
inline DD neg(const DD& a) { return {-a.hi, -a.lo}; }
inline DD sub(const DD& a, const DD& b) { return add(a, neg(b)); }
inline DD mul(const DD& a, const DD& b) {
  DD p = two_prod(a.hi, b.hi);
  if (!std::isfinite(p.hi)) return {p.hi, 0.0};
  p.lo += a.hi * b.lo + a.lo * b.hi;
  return finite_or(quick_two_sum(p.hi, p.lo), a.hi * b.hi);
}
inline DD mul_d(const DD& a, double b) {
  DD p = two_prod(a.hi, b);
  if (!std::isfinite(p.hi)) return {p.hi, 0.0};
  p.lo += a.lo * b;
  return quick_two_sum(p.hi, p.lo);
}
inline DD div(const DD& a, const DD& b) {
  const double q1 = a.hi / b.hi;
  if (!std::isfinite(q1) || q1 == 0.0 || !std::isfinite(b.hi)) return {q1, 0.0};
  DD r = sub(a, mul_d(b, q1));
  const double q2 = r.hi / b.hi;
  r = sub(r, mul_d(b, q2));
  const double q3 = r.hi / b.hi;
  const DD q = quick_two_sum(q1, q2);
  return finite_or(add(q, DD{q3, 0.0}), q1);
}
inline DD sqrt(const DD& a) {
  if (a.hi <= 0.0 || !std::isfinite(a.hi)) return {std::sqrt(a.hi), 0.0};
  const double x = 1.0 / std::sqrt(a.hi);
  const double ax = a.hi * x;
  const DD sq = two_prod(ax, ax);
  const double corr = sub(a, sq).hi * (x * 0.5);
  return two_sum(ax, corr);
}
inline double to_double(const DD& a) { return a.hi + a.lo; }

// the non-rational operations (long double based, see the file comment); out of line
DD transcendental(Op op, const DD& a, const DD& b);

inline DD apply(Op op, const DD& a, const DD& b) {
  switch (op) {
    case Op::Add: return add(a, b);
    case Op::Sub: return sub(a, b);
    case Op::Mul: return mul(a, b);
    case Op::Div: return div(a, b);
    case Op::Neg: return neg(a);
    case Op::Sqrt: return sqrt(a);
    case Op::Abs: return a.hi < 0 ? neg(a) : a;
    default: return transcendental(op, a, b);
  }
}

}  // namespace dd

// Evaluates a Program in double-double; inputs and result are double. Holds scratch registers:
// one object per thread (copy it).
class CompensatedEvaluator {
 public:
  static constexpr std::size_t kBlock = 256;

  CompensatedEvaluator() = default;
  explicit CompensatedEvaluator(Program p);

  const Program& program() const { return prog_; }
  std::size_t n_inputs() const { return prog_.n_inputs(); }

  DD eval_dd(const double* args) const {
    DD* r = regs_.data();
    const std::size_t n = prog_.n_inputs();
    for (std::size_t i = 0; i < n; ++i) r[i] = DD{args[i], 0.0};
    for (const Instr& in : prog_.code) r[in.dst] = dd::apply(in.op, r[in.a], r[in.b]);
    return r[prog_.result];
  }
  double operator()(const double* args) const { return dd::to_double(eval_dd(args)); }
  double operator()(const std::vector<double>& args) const;

  // Many points: columns[i] points at n values of input i; writes n rounded results to out.
  void eval_batch(const double* const* columns, double* out, std::size_t n) const;
  void eval_batch(const Eigen::ArrayXXd& in, Eigen::ArrayXd& out) const;

 private:
  Program prog_;
  mutable std::vector<DD> regs_;
  mutable std::vector<double> hi_, lo_;  // block registers, kBlock values each
};

}  // namespace dc::num
