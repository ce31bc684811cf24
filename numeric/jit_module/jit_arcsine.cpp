// Inline asin/acos for the JIT (jit_arcsine.hpp).
//
// Method (the classical one of fdlibm and SLEEF, with the square root's error carried exactly):
// with a = |x|,
//   a < 1/2:  s = a,        z = x^2 (rounded),   asin(a) = s + s z P(z)
//   a >= 1/2: s ~ sqrt(z),  z = (1 - a)/2 exact, asin(a) = pi/2 - 2 asin(sqrt z)
// and z in [0, 1/4] either way. P is a degree-12 polynomial fitted by Remez exchange
// (tools/fit_jit_polynomials.py asin): |z (P_true - P)| <= 2^-58.19 on [0, 1/4] with the coefficients as
// doubles. The upper range uses no division and no square root instruction (the divider is
// what the rest of a formula already waits on): y ~ 1/sqrt(z) from the hardware estimate
// (2^-14 with AVX-512, 1.5 2^-12 with AVX2's float one) and one Newton step (2^-21 or better),
// s = z y and one Newton step for sqrt (2^-41 or better), and c = (z - s^2) y/2 with the
// remainder from one FMA, so that sqrt z = s + c to 2^-63 relative. The result is assembled as
// K - u - w with K = 0, pi/2 or pi (in two doubles), u the leading term (x, -a or 2 s) and w the
// small rest; K - u is split exactly (Fast2Sum: |K| >= |u| or K = 0), so only the last addition
// rounds at the scale of the result.
//
// Error bound, u = 2^-53. asin(sqrt z) = s + t + eta with t = fl(c + q),
// q = fl(fl(s + c) fl(z P(z))), and |eta| <= 0.36 u s: approximation 0.03 u s; P by Horner
// (1.15 u relative) and the three roundings in q, 0.2 u s (z P <= 0.0472); rounding t
// 0.05 u s; sqrt z - s - c under 0.001 u s; in the lower range the rounding of z = x^2
// 0.053 u s. Measured against the result V (ulp(V) >= u V):
//   acos, a < 1/2:  V >= pi/3, s <= 1/2, so eta is at most 0.09 ulp
//   acos, a >= 1/2: x > 0: V = 2 asin(sqrt z) >= 2 s, 2 eta <= 0.36 ulp;  x < 0: V >= 2 pi/3, 0.1 ulp
//   asin, a < 1/2:  V >= s, 0.36 ulp;   asin, a >= 1/2: V >= pi/6, 2 eta <= 0.36 ulp
// plus the rounding of the small part (under 0.02 ulp) and the final rounding (0.5 ulp): below
// 0.9 ulp everywhere. tests/numeric/test_jit.cpp measures both functions against CLN near
// |x| = 1/2, near 1, at tiny and random x on both instruction sets (0.58 ulp at most when
// written), and every operation at SLEEF's 1 ulp.
#include "numeric/jit_module/jit_arcsine.hpp"

#include <array>

#include <llvm/IR/Intrinsics.h>
#include <llvm/IR/IntrinsicsX86.h>

namespace dc::num::jitir {

namespace {

// tools/fit_jit_polynomials.py asin
constexpr std::array<double, 13> kP = {
    0.16666666666666702,   0.07499999999984511,  0.04464285716363594,   0.030381943144576987,
    0.022372204933033622,  0.017351756627662213, 0.01397947103515358,   0.01140715396380983,
    0.010748063085275792,  0.0037806899502983936, 0.021629907438306728, -0.02102061110459657,
    0.032716104830982834,
};
constexpr double kPio2Hi = 1.5707963267948966;      // pi/2 rounded to double
constexpr double kPio2Lo = 6.123233995736766e-17;   // pi/2 - kPio2Hi, rounded
constexpr double kPiHi = 3.141592653589793;
constexpr double kPiLo = 1.2246467991473532e-16;

// 1/sqrt(z) to about 12 bits: VRSQRT14PD on 8 lanes, RSQRTPS (on floats) on 4; NaN for z < 0,
// inf for z = 0. Only the x86 vector widths the JIT uses (jit_llvm.cpp: 8 with AVX-512, 4 with
// AVX2 + FMA).
llvm::Value* rsqrt_estimate(llvm::IRBuilder<>& b, llvm::Value* z) {
  using namespace llvm;
  auto* vec = cast<FixedVectorType>(z->getType());
  if (vec->getNumElements() == 8)
    return b.CreateIntrinsic(Intrinsic::x86_avx512_rsqrt14_pd_512, {},
                             {z, ConstantAggregateZero::get(vec), b.getInt8(0xff)});
  auto* fvec = FixedVectorType::get(b.getFloatTy(), vec->getNumElements());
  return b.CreateFPExt(b.CreateIntrinsic(Intrinsic::x86_sse_rsqrt_ps, {}, {b.CreateFPTrunc(z, fvec)}), vec);
}

}  // namespace

llvm::Value* emit_arcsine(llvm::IRBuilder<>& b, llvm::Value* x, bool acos) {
  using namespace llvm;
  auto* vec = cast<FixedVectorType>(x->getType());
  const ElementCount n = vec->getElementCount();
  auto splat = [&](double v) { return ConstantVector::getSplat(n, ConstantFP::get(b.getDoubleTy(), v)); };
  auto fma = [&](Value* p, Value* q, Value* r) { return b.CreateIntrinsic(Intrinsic::fma, {vec}, {p, q, r}); };
  auto sel = [&](Value* m, double yes, double no) { return b.CreateSelect(m, splat(yes), splat(no)); };

  Value* a = b.CreateUnaryIntrinsic(Intrinsic::fabs, x);
  Value* low = b.CreateFCmpOLT(a, splat(0.5));  // NaN: the upper range, whose sqrt keeps NaN
  Value* zu = b.CreateFMul(b.CreateFSub(splat(1.0), a), splat(0.5));  // exact for a in [1/2, 1]
  // sqrt z = su + cu without a division or a square root instruction (the divider is what the
  // rest of a formula waits on): y ~ 1/sqrt(z) from the hardware estimate and one Newton step,
  // su = z y refined by one Newton step, cu from the remainder z - su^2 (one FMA) times y/2
  Value* y = rsqrt_estimate(b, zu);
  y = b.CreateFMul(y, fma(b.CreateFMul(zu, splat(-0.5)), b.CreateFMul(y, y), splat(1.5)));
  // z = 0 (|x| = 1): the estimate is inf and y NaN; y = 0 gives su = cu = 0. z < 0 or NaN
  // keeps y NaN, and with it the result
  y = b.CreateSelect(b.CreateFCmpOEQ(zu, splat(0.0)), splat(0.0), y);
  Value* half_y = b.CreateFMul(y, splat(0.5));
  Value* s0 = b.CreateFMul(zu, y);
  Value* su = fma(fma(b.CreateFNeg(s0), s0, zu), half_y, s0);
  Value* cu = b.CreateFMul(fma(b.CreateFNeg(su), su, zu), half_y);

  Value* z = b.CreateSelect(low, b.CreateFMul(x, x), zu);
  Value* s = b.CreateSelect(low, a, su);
  Value* c = b.CreateSelect(low, splat(0.0), cu);

  // P(z) by Horner: a long chain, but the kernel interleaves four vectors, and it has the
  // fewest operations and the smallest rounding error
  Value* p = splat(kP[12]);
  for (int k = 11; k >= 0; --k) p = fma(z, p, splat(kP[k]));
  // asin(s + c) = s + t with t = c + (s + c) z P(z)
  Value* t = b.CreateFAdd(c, b.CreateFMul(b.CreateFAdd(s, c), b.CreateFMul(z, p)));

  // result = (K_hi - u) + ((err + K_lo) - w) with K_hi - u = hi + err exactly
  Value *khi, *klo, *u, *w;
  Value* two_s = b.CreateFMul(s, splat(2.0));
  Value* two_t = b.CreateFMul(t, splat(2.0));
  if (acos) {
    // a < 1/2: pi/2 - (x + sign(x) t);  x >= 1/2: 2 s + 2 t;  x <= -1/2: pi - 2 s - 2 t
    Value* neg = b.CreateFCmpOLT(x, splat(0.0));
    Value* upper_neg = b.CreateAnd(b.CreateNot(low), neg);
    khi = b.CreateSelect(low, splat(kPio2Hi), sel(upper_neg, kPiHi, 0.0));
    klo = b.CreateSelect(low, splat(kPio2Lo), sel(upper_neg, kPiLo, 0.0));
    Value* sign_t = b.CreateBinaryIntrinsic(Intrinsic::copysign, t, x);
    u = b.CreateSelect(low, x, b.CreateSelect(upper_neg, two_s, b.CreateFNeg(two_s)));
    w = b.CreateSelect(low, sign_t, b.CreateSelect(upper_neg, two_t, b.CreateFNeg(two_t)));
  } else {
    // asin(a): a < 1/2: a + t;  a >= 1/2: pi/2 - 2 s - 2 t;  then the sign of x
    khi = sel(low, 0.0, kPio2Hi);
    klo = sel(low, 0.0, kPio2Lo);
    u = b.CreateSelect(low, b.CreateFNeg(a), two_s);
    w = b.CreateSelect(low, b.CreateFNeg(t), two_t);
  }
  Value* hi = b.CreateFSub(khi, u);
  Value* err = b.CreateFSub(b.CreateFSub(khi, hi), u);
  Value* res = b.CreateFAdd(hi, b.CreateFSub(b.CreateFAdd(err, klo), w));
  return acos ? res : b.CreateBinaryIntrinsic(Intrinsic::copysign, res, x);
}

}  // namespace dc::num::jitir
