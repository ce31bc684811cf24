// The certified automatic mode over many points (`eval --points`, the C++ API): correctly rounded
// doubles with a certificate, a block of points at a time, escalating point by point only where
// a stage cannot decide.
//
// Stage 1, double-double with a running error bound (numeric/double_double.hpp). Every
// register holds, per point, a value V = hi + lo (a double-double) and a bound E >= |V - true
// value|, computed in double:
//   exact the sum or product of two exact doubles (TwoSum, TwoProd away from underflow) has
//         E = 0, so that a result exactly halfway between two doubles is still decided;
//   + -   the "accurate" double-double sum (Joldes, Muller, Popescu, ACM TOMS 44(2), 2017,
//         Algorithm 6: relative error <= 3u^2/(1 - 4u), u = 2^-53); we charge 8u^2 |hi|;
//   *     DWTimesDW1 (ibid., Algorithm 10: <= 7u^2); we charge 16u^2 |hi|;
//   / and sqrt carry no a priori bound: their error is measured a posteriori from the residual
//         A - Q B (or S^2 - A), itself computed with the two operations above;
//   operand errors propagate as in interval arithmetic (|A| Eb + |B| Ea + Ea Eb for a product,
//         and so on); a division by, or a square root of, an interval that may reach 0 gives up;
//   exp, expm1, log, log1p, sin, cos, tan, asin, acos, atan, pow, hypot: double-double kernels
//         built from the same operations, with tables computed from Arb enclosures and the
//         truncation of their series bounded (numeric/dd_functions.hpp; 2^-70 relative or better);
//         where a kernel gives up (exp beyond 708, sin beyond 2^20, acos next to +-1, ...) the
//         long double step takes the point (certified_steps.hpp: glibc's documented long double
//         errors, 8 ulps charged; the rounding of V to long double is measured exactly);
//   underflow: every operation adds 2^-1022 (far above the few roundings at 2^-1075 that a
//         subnormal lo part can suffer, and a normal number: a subnormal one costs a
//         microcode assist on Intel cores); the bound's own arithmetic (round to nearest) is
//         covered by a factor 1 + 2^-40 per operation.
// The loops over a block are branch-free (a point that gives up carries E = NaN) so that the
// compiler vectorises them; the function is compiled for x86-64-v4 (AVX-512), v3 (AVX2 + FMA)
// and the baseline, chosen at load time. The true value lies in [V - E, V + E]; when both ends
// round to the same double, that double is the correctly rounded result.
//
// Stage 2, for the points stage 1 leaves: the long double tape (certified_fast.hpp), whose wider
// exponent range survives intermediate overflow and underflow. What both leave undecided
// (rounding boundaries, singular intervals) is for the caller's Arb escalation (certified.cpp).
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "numeric/certified/certified_fast.hpp"
#include "numeric/evaluator.hpp"

namespace dc::num {

// Which stage decided a point (None: neither did; the caller escalates).
enum class CertifiedStage : unsigned char { None = 0, DoubleDouble = 1, LongDouble = 2 };

struct CertifiedBatchStats {
  std::size_t double_double = 0, long_double = 0, undecided = 0;
};

// The double that every real number in [hi + lo - e, hi + lo + e] rounds to, if there is one
// (e == 0: hi + lo rounded); nullopt when the interval straddles a rounding boundary or is not
// finite.
std::optional<double> round_certified(double hi, double lo, double e);

// The inputs of a batch, by input: columns[i][k] is input i at point k. lows (may be null, or
// lows[i] null): a second double per value, so that the input is the double-double
// columns + lows (|low| <= half an ulp of the column's value), e.g. a decimal that is not a
// double; errors (likewise optional): bounds on |value - exact input|. Missing: 0.
struct BatchInputs {
  const double* const* columns = nullptr;
  const double* const* lows = nullptr;
  const double* const* errors = nullptr;
};

class CertifiedBatch {
 public:
  static constexpr std::size_t kBlock = 64;

  explicit CertifiedBatch(Program p);
  const Program& program() const { return prog_; }
  const CertifiedTape& long_double_stage() const { return tape_; }

  // Where stage[k] != None, out[k] is the double nearest the true value at point k (+-inf when
  // the true value is beyond the largest double, 0 below half the smallest subnormal).
  // Elsewhere out[k] is the double-double value rounded, with no claim. One object per thread
  // (scratch space).
  CertifiedBatchStats eval(const BatchInputs& in, std::size_t n, double* out, CertifiedStage* stage) const;

  // Stage 1 alone on the points [offset, offset + n), n <= kBlock, for tests, benchmarks and
  // single points: the result's value V = hi + lo and bound E per point (E NaN or infinite:
  // gave up).
  void eval_dd_block(const BatchInputs& in, std::size_t offset, std::size_t n, double* hi, double* lo,
                     double* bound) const;

 private:
  Program prog_;
  CertifiedTape tape_;
  mutable std::vector<double> hi_, lo_, er_;   // kBlock values per register
};

}  // namespace dc::num
