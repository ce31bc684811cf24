// Inline sin/cos for the JIT (jit_sincos.hpp).
//
// Reduction: k = x 2/pi rounded to an integer (one FMA onto 1.5 2^52, whose low bits then hold
// k mod 4), r = x - k pi/2 as a sum of two doubles r_hi + r_lo. pi/2 = C1 + C2 + C3 (53 bits
// each); x - k C1 is exact in one FMA (both are multiples of 2^-52, or of 2^-53 below 1, and the
// difference is below 1), k C2 is split exactly with an FMA, and two TwoSums gather the rest, so
// r is known to 2^-100 relative or better for |x| <= 2^19 (beyond, the caller uses SLEEF).
// |r| <= pi/4 (a little more where k rounded the other way; the fits cover |r| <= 0.79).
//
// Both polynomials are computed and the quadrant picks one (sin x = sin r, cos r, -sin r, -cos r
// for k mod 4 = 0..3; cos x is sin of the next quadrant). Fits: tools/fit_jit_polynomials.py.
//   sin(r) = r + r z S(z), z = r^2:  |z (S_true - S)| <= 2^-57.28 (the rounding of -1/6 to a
//            double dominates). Computed as r_hi + w with w = fma(r_hi z, S, corr): r_hi z
//            and z = r_hi^2 are split exactly with FMAs, and corr carries their low parts times
//            S and r_lo (1 - z/2), so the error in w comes from evaluating S (1.03 u |S|) and
//            rounding w (u |w|) only, with |w| <= 0.1 |r| and sin r >= 0.9 r: at most
//            (0.106 + 0.1 + 0.06) u r / 0.9 = 0.3 ulp before the final rounding.
//   cos(r) = 1 - z/2 + z^2 C(z):  |z^2 (C_true - C)| <= 2^-59.42 cos(0.79). Computed as
//            w + (((1 - w) - z/2) + t) with w = 1 - z/2 (fdlibm's exact split: 1 - w and
//            (1 - w) - z/2 are exact), t = z^2 C - zl/2 - r_hi r_lo with z = r_hi^2 + zl:
//            the rounding of t and of the sum inside (|t| <= 0.016 + 2^-52) and C's own error
//            (0.016 1.03 u) are under 0.08 ulp of cos r >= 0.7.
// With the final rounding (0.5 ulp) and the dropped terms (r_lo^2, r_lo z^2/24: under 0.01 ulp),
// sin and cos are below 0.9 ulp where |x| <= 2^19. tests/numeric/test_jit.cpp measures them
// against CLN near multiples of pi/4 and pi/2, at tiny, random and large arguments.
#include "numeric/jit_module/jit_sincos.hpp"

#include <array>

#include <llvm/IR/Intrinsics.h>

namespace dc::num::jitir {

namespace {

// tools/fit_jit_polynomials.py sin / cos
constexpr std::array<double, 8> kS = {
    -0.16666666666666666,    0.008333333333333333,  -0.00019841269841269828, 2.7557319223974017e-06,
    -2.50521083795834e-08,   1.6059042185382187e-10, -7.646896962735251e-13, 2.788460316589222e-15,
};
constexpr std::array<double, 8> kC = {
    0.041666666666666664,  -0.001388888888888889,  2.4801587301587295e-05, -2.755731922397995e-07,
    2.0876756984937288e-09, -1.1470744771571323e-11, 4.779343884641522e-14, -1.5504181317361554e-16,
};
constexpr double kTwoOverPi = 0.6366197723675814;
constexpr double kC1 = 1.5707963267948966;      // pi/2 = kC1 + kC2 + kC3 + O(2^-160)
constexpr double kC2 = 6.123233995736766e-17;
constexpr double kC3 = -1.4973849048591698e-33;
constexpr double kRound = 0x1.8p52;              // x + kRound rounds x to an integer
constexpr double kLimit = 0x1p19;

}  // namespace

InlineResult emit_sincos(llvm::IRBuilder<>& b, llvm::Value* x, bool cos) {
  using namespace llvm;
  auto* vec = cast<FixedVectorType>(x->getType());
  const ElementCount n = vec->getElementCount();
  auto splat = [&](double v) { return ConstantVector::getSplat(n, ConstantFP::get(b.getDoubleTy(), v)); };
  auto fma = [&](Value* p, Value* q, Value* r) { return b.CreateIntrinsic(Intrinsic::fma, {vec}, {p, q, r}); };
  auto horner = [&](Value* z, const std::array<double, 8>& c) {
    Value* p = splat(c[7]);
    for (int k = 6; k >= 0; --k) p = fma(z, p, splat(c[static_cast<std::size_t>(k)]));
    return p;
  };
  // s + e = p + q exactly (Knuth's TwoSum: no assumption on the magnitudes)
  auto two_sum = [&](Value* p, Value* q, Value*& s, Value*& e) {
    s = b.CreateFAdd(p, q);
    Value* bb = b.CreateFSub(s, p);
    e = b.CreateFAdd(b.CreateFSub(p, b.CreateFSub(s, bb)), b.CreateFSub(q, bb));
  };

  Value* inside = b.CreateFCmpOLE(b.CreateUnaryIntrinsic(Intrinsic::fabs, x), splat(kLimit));  // false for NaN
  Value* xs = b.CreateSelect(inside, x, splat(0.0));  // keeps k finite in the other lanes
  Value* kr = fma(xs, splat(kTwoOverPi), splat(kRound));
  Value* k = b.CreateFSub(kr, splat(kRound));
  Value* q = b.CreateBitCast(kr, FixedVectorType::get(b.getInt64Ty(), vec->getNumElements()));
  if (cos) q = b.CreateAdd(q, ConstantInt::get(q->getType(), 1));

  // r_hi + r_lo = x - k (C1 + C2 + C3)
  Value* a0 = fma(b.CreateFNeg(k), splat(kC1), xs);  // exact
  Value* bh = b.CreateFMul(k, splat(kC2));
  Value* bl = fma(k, splat(kC2), b.CreateFNeg(bh));
  Value *s1, *e1, *rhi, *rlo;
  two_sum(a0, b.CreateFNeg(bh), s1, e1);
  Value* lo = b.CreateFSub(b.CreateFSub(e1, bl), b.CreateFMul(k, splat(kC3)));
  two_sum(s1, lo, rhi, rlo);

  Value* z = b.CreateFMul(rhi, rhi);
  Value* zl = fma(rhi, rhi, b.CreateFNeg(z));
  // sin r = r_hi + (r_hi z S + corr)
  Value* s = horner(z, kS);
  Value* rz = b.CreateFMul(rhi, z);
  Value* rzl = fma(rhi, z, b.CreateFNeg(rz));
  Value* corr = fma(fma(rhi, zl, rzl), s, b.CreateFMul(rlo, fma(z, splat(-0.5), splat(1.0))));
  Value* sinr = b.CreateFAdd(rhi, fma(rz, s, corr));
  // cos r = w + (((1 - w) - z/2) + (z^2 C - zl/2 - r_hi r_lo))
  Value* hz = b.CreateFMul(z, splat(0.5));
  Value* w = b.CreateFSub(splat(1.0), hz);
  Value* t = fma(b.CreateFMul(z, z), horner(z, kC), b.CreateFNeg(fma(zl, splat(0.5), b.CreateFMul(rhi, rlo))));
  Value* cosr = b.CreateFAdd(w, b.CreateFAdd(b.CreateFSub(b.CreateFSub(splat(1.0), w), hz), t));

  auto bit = [&](std::uint64_t m) {
    return b.CreateICmpNE(b.CreateAnd(q, ConstantInt::get(q->getType(), m)), ConstantInt::get(q->getType(), 0));
  };
  Value* v = b.CreateSelect(bit(1), cosr, sinr);
  v = b.CreateSelect(bit(2), b.CreateFNeg(v), v);
  if (!cos) v = b.CreateSelect(b.CreateFCmpOEQ(x, splat(0.0)), x, v);  // sin(-0) = -0
  return {v, b.CreateNot(inside)};
}

}  // namespace dc::num::jitir
