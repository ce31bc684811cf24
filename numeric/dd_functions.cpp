// The double-double functions (dd_functions.hpp). Compiled with -ffp-contract=off (CMakeLists):
// the error-free transformations need every operation rounded as written; and with
// -fno-math-errno -fno-trapping-math, without which GCC does not vectorise the loops.
#include "numeric/dd_functions.hpp"

#include <algorithm>
#include <cmath>

#include "numeric/dd_tables.hpp"

namespace dc::num::dde {
namespace {

constexpr double k64OverLn2 = 92.332482616893656877;   // only picks m: any rounding will do
constexpr double k64OverPi = 20.371832715762602978;

DC_DD_INLINE DDE select(bool c, DDE a, DDE b) { return {c ? a.h : b.h, c ? a.l : b.l, c ? a.e : b.e}; }
DC_DD_INLINE DDE entry(const double* h, const double* l, const double* e, std::size_t i) { return {h[i], l[i], e[i]}; }
DC_DD_INLINE double pow_int(double t, int n) {
  double p = 1;
  for (int i = 0; i < n; ++i) p *= t;
  return p;
}
// the coefficients 1/n! (n! is exact for n <= 18, and the division is correctly rounded),
// computed at compile time
constexpr double inv_fact_of(int n) {
  double f = 1;
  for (int i = 2; i <= n; ++i) f *= i;
  return 1.0 / f;
}
struct InvFact {
  double v[14];
  constexpr InvFact() : v{} {
    for (int n = 0; n < 14; ++n) v[n] = inv_fact_of(n);
  }
};
constexpr InvFact kInvFact;
DC_DD_INLINE constexpr double inv_fact(int n) { return kInvFact.v[n]; }

// A series tail t^k (c_0 + c_1 s + ... + c_m s^m), s = t or t^2 (step), evaluated in plain double
// at t = x.h, as a DE whose bound covers, against the same polynomial at x's true value:
//   - the roundings: Horner's (Higham, Accuracy and Stability, Thm 5.1: gamma_{2m} sum |c_i||s|^i),
//     the coefficients' (u each), that of s = t^2 (raising s^i by i u at most), the k - 1 of
//     t^k and the final product: 2m + 1 + m + k; all of it is below (2m + 2k + 4) u smax tau^k,
//     where smax >= sum |c_i| tau^(i step) on the kernel's range (this needs m <= k + 3 for step 2);
//   - the perturbation |x.l| + x.e of t, times the derivative of the tail, <= dmax tau^(k-1);
//   - underflow of the products: 2m + 2k + 4 times kEta (2^-1022, far above the 2^-1075 each).
// tau >= |t| and >= |x's true value|; the caller checks that tau is within the kernel's range.
template <int M>
DC_DD_INLINE DE poly_tail(const double (&c)[M + 1], int step, int k, DDE x, double tau, double smax, double dmax) {
  const double t = x.h;
  const double s = step == 2 ? t * t : t;
  double p = c[M];
#pragma GCC unroll 16
  for (int i = M - 1; i >= 0; --i) p = p * s + c[i];
  const double tk = pow_int(t, k);
  const double rounds = 2 * M + 2 * k + 4;
  const double e = (rounds * kU * smax * pow_int(tau, k) * 1.01 + dmax * pow_int(tau, k - 1) * (std::fabs(x.l) + x.e) +
                    rounds * kEta) * kSafe;
  return {p * tk, e};
}

// ---- exp ------------------------------------------------------------------------------------
// expm1(r) for |r| <= 0.006: r + r^2/2 in double-double, r^3/6 + ... + r^8/8! in double (it is
// below 4e-8 |r|), and the rest bounded by tau^9/9! / (1 - tau) <= 1.01 tau^9/9!.
DC_DD_INLINE DDE expm1_small(DDE r, bool& ok) {
  const double tau = mag(r);
  ok = ok & (tau <= 0.006);
  const DDE p = add(r, scale(mul(r, r), 0.5));
  // r^3 (1/6 + r/24 + ... + r^5/8!): sum |c_i| tau^i <= 0.1669, derivative <= 0.502 tau^2
  constexpr double c[6] = {inv_fact(3), inv_fact(4), inv_fact(5), inv_fact(6), inv_fact(7), inv_fact(8)};
  const DE q = poly_tail<5>(c, 1, 3, r, tau, 0.168, 0.51);
  return add(p, q, pow_int(tau, 9) * (1.01 * inv_fact(9)));
}

// exp(x) = 2^k T_j (1 + expm1(r)), r = x - m ln2/64, m = 64 k + j. Also gives m (expm1 uses it).
DC_DD_INLINE DDE exp_dd(DDE x, const Tables& T, bool& ok, double& m_out, DDE& em1_out) {
  ok = ok & (std::fabs(x.h) <= 708.0);
  x = select(ok, x, exact(0.0));
  const double m = round_int(x.h * k64OverLn2);
  const double k = std::floor(m * (1.0 / 64));
  const std::uint64_t j = int_bits(m - 64 * k) & 63;   // m - 64 k in [0, 63]
  DDE r = add(x, neg(prod(m, T.ln2_64.p[0])));
  r = add(r, neg(prod(m, T.ln2_64.p[1])));
  r.e = (r.e + std::fabs(m) * T.ln2_64.res2) * kSafe;
  const DDE em1 = expm1_small(r, ok);
  const DDE tj = entry(T.exp_h, T.exp_l, T.exp_e, j);
  m_out = m;
  em1_out = em1;
  return scale(add(tj, mul(tj, em1)), pow2(k));
}

DC_DD_INLINE DDE exp_of(DDE x, const Tables& T) {
  bool ok = true;
  double m;
  DDE em1;
  const DDE y = exp_dd(x, T, ok, m, em1);
  return give_up_unless(ok, y);
}

DC_DD_INLINE DDE expm1_of(DDE x, const Tables& T) {
  bool ok = true;
  double m;
  DDE em1;
  const DDE y = exp_dd(x, T, ok, m, em1);
  // m = 0 (|x| < ln2/128): expm1(x) = em1 keeps relative accuracy; else |result| >= 0.0054
  return give_up_unless(ok, select(m == 0, em1, add(y, exact(-1.0))));
}

// ---- log ------------------------------------------------------------------------------------
// E with x = 2^E f, 0.75 <= f < 1.5, for a positive normal x (bit operations only: vectorised)
DC_DD_INLINE double exponent_of(double x) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  const double field = std::bit_cast<double>((bits >> 52) | 0x4330000000000000ULL) - 0x1p52;   // biased
  const double f = std::bit_cast<double>((bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL);   // [1, 2)
  return field - 1023 + (f >= 1.5 ? 1.0 : 0.0);
}

// log x = E ln2 - log r_j + log1p(u), x = 2^E f (0.75 <= f < 1.5), u = f r_j - 1 (|u| <= 0.0027),
// log1p(u) = u - u^2/2 in double-double + u^3 (1/3 - u/4 + ... - u^7/10) in double, the rest
// <= tau^11/11 / (1 - tau). direct: x is already u (log1p of a small argument), E = 0, j = 0.
DC_DD_INLINE DDE log_dd(DDE x, bool direct, const Tables& T) {
  bool ok = direct || (x.h >= 0x1p-1022 && x.h < 0x1.8p1022 && x.e <= x.h / 4);
  const double E = direct || !ok ? 0.0 : exponent_of(x.h);   // |E| <= 1022
  const DDE F = select(direct, exact(1.0), scale(select(ok, x, exact(1.0)), pow2(-E)));
  // F.h in [0.75, 1.5): j in [-64, 128] (the padding entries, r = 1, are never needed)
  const double j = round_int((F.h - 1) * 256);
  const std::uint64_t i = int_bits(j + 64) & 255;
  const double r = T.log_r[i];
  // u = F r - 1 from exact pieces: F.h r = ph + pl (TwoProd), ph - 1 exact (Sterbenz), F.l r = q
  const DDE p = prod(F.h, r);
  const DDE q = prod(F.l, r);
  DDE u = add(add(exact(p.h - 1), exact(p.l)), q);
  u.e = (u.e + p.e + F.e * r) * kSafe;
  u = select(direct, x, u);
  const double tau = mag(u);
  ok = ok & (tau <= 0.003);
  const DDE l1 = add(u, scale(mul(u, u), -0.5));
  // u^3 (1/3 - u/4 + ... - u^7/10): sum |c_i| tau^i <= 0.3341, derivative <= 1.004 tau^2
  constexpr double c[8] = {1.0 / 3, -1.0 / 4, 1.0 / 5, -1.0 / 6, 1.0 / 7, -1.0 / 8, 1.0 / 9, -1.0 / 10};
  const DE s = poly_tail<7>(c, 1, 3, u, tau, 0.335, 1.01);
  const DDE l = add(l1, s, pow_int(tau, 11) * (1.01 / 11));
  DDE el = add(prod(E, T.ln2.p[0]), prod(E, T.ln2.p[1]));
  el.e = (el.e + std::fabs(E) * T.ln2.res2) * kSafe;
  const DDE nl = select(direct, exact(0.0), entry(T.log_h, T.log_l, T.log_e, i));
  return give_up_unless(ok, add(add(el, nl), l));
}

DC_DD_INLINE DDE log1p_of(DDE x, const Tables& T) {
  // small x: u = x directly; else log(1 + x)
  const bool direct = std::fabs(x.h) < 1.0 / 512 && x.e <= 1.0 / 1024;
  return log_dd(select(direct, x, add(exact(1.0), x)), direct, T);
}

// ---- sin, cos -------------------------------------------------------------------------------
// x = m pi/64 + r (|r| <= pi/128 + tiny), j = m mod 128; sin r = r - r^3/6 in double-double +
// r^5 (1/120 - r^2/5040 + r^4/9! - r^6/11!) in double, rest <= tau^13/13!; cos r = 1 - r^2/2
// + r^4 (1/24 - r^2/6! + r^4/8! - r^6/10!), rest <= tau^12/12!; then the addition theorems with
// the tabled sin, cos of j pi/64.
struct SinCos {
  DDE s, c;
};
DC_DD_INLINE SinCos sincos_dd(DDE x, const Tables& T, bool& ok) {
  ok = ok & (std::fabs(x.h) <= 0x1p20);
  x = select(ok, x, exact(0.0));
  const double m = round_int(x.h * k64OverPi);
  const std::uint64_t j = int_bits(m) & 127;
  DDE r = add(x, neg(prod(m, T.pi_64.p[0])));
  r = add(r, neg(prod(m, T.pi_64.p[1])));
  r = add(r, neg(prod(m, T.pi_64.p[2])));
  r.e = (r.e + std::fabs(m) * T.pi_64.res3) * kSafe;
  const double tau = mag(r);
  ok = ok & (tau <= 0.025);
  const DDE r2 = mul(r, r);
  const DDE minus_sixth{T.minus_sixth[0], T.minus_sixth[1], T.minus_sixth[2]};
  // sin: r^5 (1/5! - r^2/7! + r^4/9! - r^6/11!): sum <= 0.00834, derivative <= 0.0417 tau^4
  constexpr double cs[4] = {inv_fact(5), -inv_fact(7), inv_fact(9), -inv_fact(11)};
  const DE qs = poly_tail<3>(cs, 2, 5, r, tau, 0.00834, 0.042);
  const DDE s = add(add(r, mul(mul(r2, r), minus_sixth)), qs, pow_int(tau, 13) * (1.01 * inv_fact(13)));
  // cos: r^4 (1/4! - r^2/6! + r^4/8! - r^6/10!): sum <= 0.041668, derivative <= 0.1667 tau^3
  constexpr double cc[4] = {inv_fact(4), -inv_fact(6), inv_fact(8), -inv_fact(10)};
  const DE qc = poly_tail<3>(cc, 2, 4, r, tau, 0.04168, 0.167);
  const DDE c = add(add(exact(1.0), scale(r2, -0.5)), qc, pow_int(tau, 12) * (1.01 * inv_fact(12)));
  const DDE sj = entry(T.sin_h, T.sin_l, T.sin_e, j), cj = entry(T.cos_h, T.cos_l, T.cos_e, j);
  return {add(mul(sj, c), mul(cj, s)), sub(mul(cj, c), mul(sj, s))};
}

// op is a constant of each loop that calls this (Sin, Cos or Tan): the selection folds away
DC_DD_INLINE DDE sin_cos_tan_of(Op op, DDE x, const Tables& T) {
  bool ok = true;
  const SinCos sc = sincos_dd(x, T, ok);
  return give_up_unless(ok, op == Op::Sin ? sc.s : op == Op::Cos ? sc.c : div(sc.s, sc.c));
}

// ---- asin, acos, atan: one Newton step from a double guess y0 --------------------------------
// g(x) = g(c) + g'(c) (x - c) + g''(xi) (x - c)^2 / 2 with c = cos y0 (acos), sin y0 (asin):
// |g''(xi)| = |xi| / (1 - xi^2)^(3/2) <= m / w^(3/2), m >= |xi|, w <= 1 - m^2.
DC_DD_INLINE double arc_remainder(double d, double m) {
  const double w = (1 - m) * (1 + m) * (1 - 0x1p-50);
  return d * d * m / (2 * w * std::sqrt(w)) * 1.01;
}
// acos x = y0 - (x - cos y0)/sin y0 + R, asin x = y0 + (x - sin y0)/cos y0 + R (is_acos is a
// constant of each loop that calls this)
DC_DD_INLINE DDE arc_of(bool is_acos, DDE x, double y0, const Tables& T) {
  bool ok = true;
  const SinCos sc = sincos_dd(exact(y0), T, ok);
  const DDE c = is_acos ? sc.c : sc.s;       // the point whose acos (asin) is y0
  const DDE slope = is_acos ? sc.s : sc.c;   // 1/|g'(c)|, positive on the principal branch
  const DDE d = sub(x, c);
  const double m = std::max(mag(x), mag(c));
  ok = ok & (m <= 1 - 0x1p-30 && slope.h > 0);
  const DDE q = div(d, slope);
  DDE y = add(exact(y0), is_acos ? neg(q) : q);
  y.e = (y.e + arc_remainder(mag(d), m)) * kSafe;
  return give_up_unless(ok, y);
}
// atan x = y0 + (x - t)/(1 + t^2) + R, t = tan y0, |R| <= max|atan''| d^2/2 <= 0.65 d^2 / 2
DC_DD_INLINE DDE atan_of(DDE x, double y0, const Tables& T) {
  bool ok = true;
  const SinCos sc = sincos_dd(exact(y0), T, ok);
  ok = ok & (sc.c.h > 0);
  const DDE t = div(sc.s, sc.c);
  const DDE d = sub(x, t);
  DDE y = add(exact(y0), div(d, add(exact(1.0), mul(t, t))));
  const double dm = mag(d);
  y.e = (y.e + 0.33 * dm * dm) * kSafe;
  return give_up_unless(ok, y);
}

// ---- the block loops -------------------------------------------------------------------------
DC_DD_INLINE DDE operand(const double* h, const double* l, const double* e, std::size_t k) { return {h[k], l[k], e[k]}; }
DC_DD_INLINE void store(double* h, double* l, double* e, std::size_t k, DDE v) {
  h[k] = v.h;
  l[k] = v.l;
  e[k] = v.e;
}

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#endif
void kernel_block(Op op, double* __restrict dh, double* __restrict dl, double* __restrict de,
                  const double* __restrict ah, const double* __restrict al, const double* __restrict ae,
                  const double* __restrict bh, const double* __restrict bl, const double* __restrict be,
                  const double* __restrict guess, std::size_t n) {
  const Tables& T = tables();
  switch (op) {
    case Op::Exp:
      for (std::size_t k = 0; k < n; ++k) store(dh, dl, de, k, exp_of(operand(ah, al, ae, k), T));
      break;
    case Op::Expm1:
      for (std::size_t k = 0; k < n; ++k) store(dh, dl, de, k, expm1_of(operand(ah, al, ae, k), T));
      break;
    case Op::Log:
      for (std::size_t k = 0; k < n; ++k) store(dh, dl, de, k, log_dd(operand(ah, al, ae, k), false, T));
      break;
    case Op::Log1p:
      for (std::size_t k = 0; k < n; ++k) store(dh, dl, de, k, log1p_of(operand(ah, al, ae, k), T));
      break;
    case Op::Sin:
      for (std::size_t k = 0; k < n; ++k) store(dh, dl, de, k, sin_cos_tan_of(op, operand(ah, al, ae, k), T));
      break;
    case Op::Cos:
      for (std::size_t k = 0; k < n; ++k) store(dh, dl, de, k, sin_cos_tan_of(op, operand(ah, al, ae, k), T));
      break;
    case Op::Tan:
      for (std::size_t k = 0; k < n; ++k) store(dh, dl, de, k, sin_cos_tan_of(op, operand(ah, al, ae, k), T));
      break;
    case Op::Acos:
      for (std::size_t k = 0; k < n; ++k) store(dh, dl, de, k, arc_of(true, operand(ah, al, ae, k), guess[k], T));
      break;
    case Op::Asin:
      for (std::size_t k = 0; k < n; ++k) store(dh, dl, de, k, arc_of(false, operand(ah, al, ae, k), guess[k], T));
      break;
    case Op::Atan:
      for (std::size_t k = 0; k < n; ++k) store(dh, dl, de, k, atan_of(operand(ah, al, ae, k), guess[k], T));
      break;
    case Op::Pow:   // a^b = exp(b log a), a > 0
      for (std::size_t k = 0; k < n; ++k)
        store(dh, dl, de, k, exp_of(mul(operand(bh, bl, be, k), log_dd(operand(ah, al, ae, k), false, T)), T));
      break;
    case Op::Hypot:
      for (std::size_t k = 0; k < n; ++k) {
        const DDE a = operand(ah, al, ae, k), b = operand(bh, bl, be, k);
        store(dh, dl, de, k, sqrt(add(mul(a, a), mul(b, b))));
      }
      break;
    default:
      for (std::size_t k = 0; k < n; ++k) store(dh, dl, de, k, {0.0, 0.0, kNaN});
      break;
  }
}

}  // namespace

bool has_kernel(Op op) {
  switch (op) {
    case Op::Exp: case Op::Expm1: case Op::Log: case Op::Log1p: case Op::Sin: case Op::Cos: case Op::Tan:
    case Op::Asin: case Op::Acos: case Op::Atan: case Op::Pow: case Op::Hypot:
      return true;
    default:
      return false;
  }
}

void function_block(Op op, double* dh, double* dl, double* de, const double* ah, const double* al, const double* ae,
                    const double* bh, const double* bl, const double* be, std::size_t n) {
  constexpr std::size_t kMax = 64;
  double guess[kMax];
  for (std::size_t off = 0; off < n; off += kMax) {
    const std::size_t m = std::min(kMax, n - off);
    // asin, acos, atan: the double guesses of the Newton steps (glibc; their accuracy only sizes
    // the correction)
    if (op == Op::Acos || op == Op::Asin || op == Op::Atan) {
      for (std::size_t k = 0; k < m; ++k) {
        const double a = std::clamp(ah[off + k], -1.0, 1.0);
        guess[k] = op == Op::Acos ? std::acos(a) : op == Op::Asin ? std::asin(a) : std::atan(ah[off + k]);
        if (!std::isfinite(guess[k])) guess[k] = 0;
      }
    }
    kernel_block(op, dh + off, dl + off, de + off, ah + off, al + off, ae + off, bh ? bh + off : ah + off,
                 bl ? bl + off : al + off, be ? be + off : ae + off, guess, m);
  }
}

DDE apply(Op op, DDE a, DDE b) {
  DDE d{};
  function_block(op, &d.h, &d.l, &d.e, &a.h, &a.l, &a.e, &b.h, &b.l, &b.e, 1);
  return d;
}

}  // namespace dc::num::dde
