// Double-double numbers with a running error bound, one point at a time, for the certified
// batch (certified_batch.hpp) and its functions (dd_functions.hpp). Everything here is inline
// and branch-free so that loops over a block of points vectorise; a value that gives up carries
// the bound NaN, which every later operation keeps.
//
// A DDE is a value V = h + l (|l| <= ulp(h) / 2) and a bound e >= |V - true value|:
//   add  the "accurate" double-double sum (Joldes, Muller, Popescu, ACM TOMS 44(2), 2017,
//        Algorithm 6: relative error <= 3u^2/(1 - 4u), u = 2^-53); we charge 8u^2 |h|;
//        add_keep_exact: the sum of two exact doubles is exact (TwoSum) and keeps e = 0;
//   mul  DWTimesDW1 (ibid., Algorithm 10: <= 7u^2); we charge 16u^2 |h|; mul_keep_exact: the
//        product of two exact doubles away from underflow and overflow is exact (TwoProd);
//   div, sqrt: no a priori bound; the error is measured from the residual A - Q B (S^2 - A),
//        itself computed with the two operations above;
//   operand errors propagate as in interval arithmetic (|A| eb + |B| ea + ea eb, ...);
//   every operation adds kEta (roundings of subnormal low parts, each at most 2^-1075; kEta is
//        the smallest normal double, far more than needed, because a subnormal operand in the
//        bound's own additions costs a microcode assist per vector on Intel cores: with 2^-1060
//        the certified batch of velocity_symbols ran 20 % slower there), and the bound's own
//        arithmetic (round to nearest) is covered by the factor kSafe per operation.
// A DE is a plain double with a bound on its error: a polynomial tail small enough for double's
// precision, bounded a priori by its caller (dd_functions.cpp, poly_tail), then added into a DDE.
// Needs every operation rounded as written: compile users with -ffp-contract=off.
#pragma once
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#if defined(__GNUC__)
#define DC_DD_INLINE [[gnu::always_inline]] inline
#else
#define DC_DD_INLINE inline
#endif

namespace dc::num::dde {

inline constexpr double kU = 0x1p-53;        // unit roundoff of double
inline constexpr double kAdd = 0x1p-103;     // 8u^2: a double-double sum, relative to |h| (cited 3u^2)
inline constexpr double kMul = 0x1p-102;     // 16u^2: a double-double product (cited 7u^2)
inline constexpr double kEta = 0x1p-1022;    // per operation: roundings of subnormal low parts (normal: no assists)
inline constexpr double kSafe = 1 + 0x1p-40; // the bound's own roundings (a few dozen, each <= 2^-53)
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kTiny = 0x1p-960;    // above it a product's rounding error is a double
inline constexpr double kBig = 0x1p1020;     // below it nothing in an error-free transformation overflows

// ---- error-free transformations (exact when nothing overflows) ------------------------------
DC_DD_INLINE void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}
DC_DD_INLINE void fast_two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  e = b - (s - a);
}
// Algorithm 6 of Joldes-Muller-Popescu: (ah + al) + (bh + bl)
DC_DD_INLINE void dd_add(double ah, double al, double bh, double bl, double& sh, double& sl) {
  double s, e, t, f;
  two_sum(ah, bh, s, e);
  two_sum(al, bl, t, f);
  e += t;
  fast_two_sum(s, e, s, e);
  e += f;
  fast_two_sum(s, e, sh, sl);
}
// Algorithm 10 (DWTimesDW1): (ah + al) (bh + bl)
DC_DD_INLINE void dd_mul(double ah, double al, double bh, double bl, double& ph, double& pl) {
  const double p = ah * bh;
  double e = std::fma(ah, bh, -p);
  const double cross = ah * bl + al * bh;
  e += cross;
  fast_two_sum(p, e, ph, pl);
}

// x rounded to an integer (ties to even), for |x| < 2^51, and x's residue mod 2^m as an integer.
DC_DD_INLINE double round_int(double x) {
  constexpr double M = 0x1.8p52;
  return (x + M) - M;
}
DC_DD_INLINE std::uint64_t int_bits(double k) {   // k an integer, |k| < 2^51: k + 2^51 (mod 2^52)
  return std::bit_cast<std::uint64_t>(k + 0x1.8p52);
}
// 2^k for an integer k in [-1022, 1023]
DC_DD_INLINE double pow2(double k) {
  return std::bit_cast<double>(std::bit_cast<std::uint64_t>(k + (0x1p52 + 1023)) << 52);
}

// ---- DDE: double-double with a bound ---------------------------------------------------------
struct DDE {
  double h, l, e;
};
DC_DD_INLINE DDE exact(double x) { return {x, 0.0, 0.0}; }
DC_DD_INLINE DDE neg(DDE a) { return {-a.h, -a.l, a.e}; }
DC_DD_INLINE DDE give_up_unless(bool ok, DDE a) { return {a.h, a.l, ok ? a.e : kNaN}; }
// |true value| <= mag(a)
DC_DD_INLINE double mag(DDE a) { return std::fabs(a.h) + std::fabs(a.l) + a.e; }

// The operations always charge their rounding error (a chain of them vectorises; GCC 12 does
// not vectorise a select whose condition tests the result of another select).
DC_DD_INLINE DDE add(DDE a, DDE b) {
  double h, l;
  dd_add(a.h, a.l, b.h, b.l, h, l);
  return {h, l, (a.e + b.e + kAdd * std::fabs(h) + kEta) * kSafe};
}
DC_DD_INLINE DDE sub(DDE a, DDE b) { return add(a, neg(b)); }
DC_DD_INLINE DDE mul(DDE a, DDE b) {
  double h, l;
  dd_mul(a.h, a.l, b.h, b.l, h, l);
  return {h, l, (std::fabs(a.h) * b.e + std::fabs(b.h) * a.e + a.e * b.e + kMul * std::fabs(h) + kEta) * kSafe};
}
// The same, exact (e = 0) for two exact doubles: TwoSum, and TwoProd away from underflow and
// overflow; so that a result exactly halfway between two doubles is still decided. For single
// operations over a block (certified_batch.cpp).
DC_DD_INLINE DDE add_keep_exact(DDE a, DDE b) {
  const DDE s = add(a, b);
  const bool ex = a.e == 0 && b.e == 0 && a.l == 0 && b.l == 0 && std::fabs(s.h) <= kBig;
  return {s.h, s.l, ex ? 0.0 : s.e};
}
DC_DD_INLINE DDE mul_keep_exact(DDE a, DDE b) {
  const DDE p = mul(a, b);
  const bool ex = a.e == 0 && b.e == 0 && a.l == 0 && b.l == 0 && std::fabs(p.h) >= kTiny && std::fabs(p.h) <= kBig;
  return {p.h, p.l, ex ? 0.0 : p.e};
}
// the exact product of two doubles (TwoProd), as a DDE with e = 0 away from underflow/overflow
DC_DD_INLINE DDE prod(double a, double b) {
  const double p = a * b;
  const double e = std::fma(a, b, -p);
  // below kTiny the residual may be rounded (by at most 2^-1075); beyond kBig it may overflow
  const double ap = std::fabs(p);
  return {p, e, ap <= kBig ? (ap >= kTiny ? 0.0 : kEta) : kNaN};
}
// a * p, p = +-2^k: exact unless the low part or the bound becomes subnormal
DC_DD_INLINE DDE scale(DDE a, double p) { return {a.h * p, a.l * p, a.e * std::fabs(p) + kEta}; }

DC_DD_INLINE DDE div(DDE a, DDE b) {
  // two quotient digits: q1 = a/b, q2 = (a - b q1)/b
  const double q1 = a.h / b.h;
  double ph, pl, rh, rl;
  dd_mul(b.h, b.l, q1, 0.0, ph, pl);
  dd_add(a.h, a.l, -ph, -pl, rh, rl);
  const double q2 = rh / b.h;
  double qh, ql;
  fast_two_sum(q1, q2, qh, ql);
  // a posteriori: |q - a/b| = |a - q b| / |b|, the residual computed in double-double
  dd_mul(qh, ql, b.h, b.l, ph, pl);
  dd_add(a.h, a.l, -ph, -pl, rh, rl);
  const double bb = std::fabs(b.h);
  const double comp = (std::fabs(rh) + kMul * std::fabs(ph) + kEta) / bb;
  // |a/b - a'/b'| <= 2 (|a| eb / |b| + ea) / |b| when eb <= |b| / 4 (|b'| >= |b| / 2)
  const double prop = 2 * (std::fabs(a.h) * (b.e / bb) + a.e) / bb;
  const double e = (comp + prop + kEta) * kSafe;
  return {qh, ql, b.e <= bb / 4 ? e : kNaN};
}

DC_DD_INLINE DDE sqrt(DDE a) {
  const bool zero = a.h == 0 && a.l == 0 && a.e == 0;
  const double x0 = a.h > 0 ? a.h : 1.0;   // other lanes give up below
  // one Newton step on 1/sqrt in double-double (as compensated.hpp)
  const double r = 1.0 / std::sqrt(x0);
  const double ax = x0 * r;
  double sh, sl, th, tl;
  dd_mul(ax, 0.0, ax, 0.0, sh, sl);
  dd_add(x0, a.l, -sh, -sl, th, tl);
  two_sum(ax, th * (r * 0.5), sh, sl);
  // a posteriori: |s - sqrt(a)| = |s^2 - a| / (s + sqrt(a)) <= |s^2 - a| / s
  double ph, pl;
  dd_mul(sh, sl, sh, sl, ph, pl);
  dd_add(ph, pl, -x0, -a.l, th, tl);
  const double comp = (std::fabs(th) + kMul * std::fabs(ph) + kEta) / sh;
  // |sqrt(a) - sqrt(a')| <= ea / sqrt(a) <= 2 ea / s when comp <= s / 4
  const double e = (comp + 2 * a.e / sh + kEta) * kSafe;
  const bool ok = a.h > 0 && a.e <= a.h / 2 && comp <= sh / 4;
  if (zero) return {0.0, 0.0, 0.0};
  return {sh, sl, ok ? e : kNaN};
}

// ---- DE: a double with a bound ---------------------------------------------------------------
struct DE {
  double v, e;
};
// a DE added into a DDE, with `extra` (e.g. a truncation bound) added to the bound
DC_DD_INLINE DDE add(DDE a, DE b, double extra) {
  DDE s = add(a, DDE{b.v, 0.0, 0.0});
  s.e = (s.e + b.e + extra) * kSafe;
  return s;
}

}  // namespace dc::num::dde
