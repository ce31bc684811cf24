// Double-double evaluation with a running error bound, a block of points at a time (see
// certified_batch.hpp for the error model). Compiled with -ffp-contract=off (CMakeLists.txt): the
// error-free transformations and the cited bounds need every operation rounded as written.
#include "numeric/certified_batch.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "numeric/certified_steps.hpp"

namespace dc::num {
namespace {

constexpr double kAdd = 0x1p-103;     // 8u^2: a double-double sum, relative to |hi| (cited 3u^2)
constexpr double kMul = 0x1p-102;     // 16u^2: a double-double product (cited 7u^2)
constexpr double kConst = 0x1p-100;   // a constant: 40 digits (1e-39) rounded to double-double
constexpr double kEta = 0x1p-1060;    // per operation: roundings of subnormal lo parts
constexpr double kSafe = 1 + 0x1p-40; // the bound's own roundings (a few dozen, each <= 2^-53)
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kTiny = 0x1p-960;    // above it a product's rounding error is a double (no underflow)
constexpr double kBig = 0x1p1020;     // below it nothing in an error-free transformation overflows

// The error-free transformations (exact when nothing overflows).
inline void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}
inline void fast_two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  e = b - (s - a);
}
// Algorithm 6 of Joldes-Muller-Popescu: (ah + al) + (bh + bl)
inline void dd_add(double ah, double al, double bh, double bl, double& sh, double& sl) {
  double s, e, t, f;
  two_sum(ah, bh, s, e);
  two_sum(al, bl, t, f);
  e += t;
  fast_two_sum(s, e, s, e);
  e += f;
  fast_two_sum(s, e, sh, sl);
}
// Algorithm 10 (DWTimesDW1): (ah + al) (bh + bl)
inline void dd_mul(double ah, double al, double bh, double bl, double& ph, double& pl) {
  const double p = ah * bh;
  double e = std::fma(ah, bh, -p);
  const double cross = ah * bl + al * bh;
  e += cross;
  fast_two_sum(p, e, ph, pl);
}

// One instruction of + - * / sqrt neg abs over n points. The destination never aliases an
// operand (eval_dd_block goes through a scratch register), so that the loops vectorise.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#endif
void rational_block(Op op, double* __restrict dh, double* __restrict dl, double* __restrict de,
                    const double* __restrict ah, const double* __restrict al, const double* __restrict ae,
                    const double* __restrict bh, const double* __restrict bl, const double* __restrict be,
                    std::size_t n) {
  switch (op) {
    case Op::Add:
    case Op::Sub: {
      const double sign = op == Op::Add ? 1.0 : -1.0;
      for (std::size_t k = 0; k < n; ++k) {
        double h, l;
        dd_add(ah[k], al[k], sign * bh[k], sign * bl[k], h, l);
        // two exact doubles: TwoSum is exact (E stays 0, so that ties are decided exactly)
        const bool exact = ae[k] == 0 && be[k] == 0 && al[k] == 0 && bl[k] == 0 && std::fabs(h) <= kBig;
        de[k] = exact ? 0.0 : (ae[k] + be[k] + kAdd * std::fabs(h) + kEta) * kSafe;
        dh[k] = h;
        dl[k] = l;
      }
      break;
    }
    case Op::Mul:
      for (std::size_t k = 0; k < n; ++k) {
        double h, l;
        dd_mul(ah[k], al[k], bh[k], bl[k], h, l);
        const double ea = ae[k], eb = be[k];
        // two exact doubles whose product is far from underflow: TwoProd is exact
        const bool exact = ea == 0 && eb == 0 && al[k] == 0 && bl[k] == 0 && std::fabs(h) >= kTiny &&
                           std::fabs(h) <= kBig;
        de[k] = exact ? 0.0 : (std::fabs(ah[k]) * eb + std::fabs(bh[k]) * ea + ea * eb + kMul * std::fabs(h) + kEta) * kSafe;
        dh[k] = h;
        dl[k] = l;
      }
      break;
    case Op::Div:
      for (std::size_t k = 0; k < n; ++k) {
        const double a_h = ah[k], a_l = al[k], b_h = bh[k], b_l = bl[k], ea = ae[k], eb = be[k];
        // two quotient digits: q1 = a/b, q2 = (a - b q1)/b
        const double q1 = a_h / b_h;
        double ph, pl, rh, rl;
        dd_mul(b_h, b_l, q1, 0.0, ph, pl);
        dd_add(a_h, a_l, -ph, -pl, rh, rl);
        const double q2 = rh / b_h;
        double qh, ql;
        fast_two_sum(q1, q2, qh, ql);
        // a posteriori: |q - a/b| = |a - q b| / |b|, the residual computed in double-double
        dd_mul(qh, ql, b_h, b_l, ph, pl);
        dd_add(a_h, a_l, -ph, -pl, rh, rl);
        const double bb = std::fabs(b_h);
        const double comp = (std::fabs(rh) + kMul * std::fabs(ph) + kEta) / bb;
        // |a/b - a'/b'| <= 2 (|a| eb / |b| + ea) / |b| when eb <= |b| / 4 (|b'| >= |b| / 2)
        const double prop = 2 * (std::fabs(a_h) * (eb / bb) + ea) / bb;
        const double e = (comp + prop + kEta) * kSafe;
        de[k] = eb <= bb / 4 ? e : kNaN;
        dh[k] = qh;
        dl[k] = ql;
      }
      break;
    case Op::Sqrt:
      for (std::size_t k = 0; k < n; ++k) {
        const double a_h = ah[k], a_l = al[k], ea = ae[k];
        const bool zero = a_h == 0 && a_l == 0 && ea == 0;
        const double x0 = a_h > 0 ? a_h : 1.0;   // other lanes give up below
        // one Newton step on 1/sqrt in double-double (as compensated.hpp)
        const double r = 1.0 / std::sqrt(x0);
        const double ax = x0 * r;
        double sh, sl, th, tl;
        dd_mul(ax, 0.0, ax, 0.0, sh, sl);
        dd_add(x0, a_l, -sh, -sl, th, tl);
        two_sum(ax, th * (r * 0.5), sh, sl);
        // a posteriori: |s - sqrt(a)| = |s^2 - a| / (s + sqrt(a)) <= |s^2 - a| / s
        double ph, pl;
        dd_mul(sh, sl, sh, sl, ph, pl);
        dd_add(ph, pl, -x0, -a_l, th, tl);
        const double comp = (std::fabs(th) + kMul * std::fabs(ph) + kEta) / sh;
        // |sqrt(a) - sqrt(a')| <= ea / sqrt(a) <= 2 ea / s when comp <= s / 4
        const double e = (comp + 2 * ea / sh + kEta) * kSafe;
        const bool ok = a_h > 0 && ea <= a_h / 2 && comp <= sh / 4;
        de[k] = zero ? 0.0 : ok ? e : kNaN;
        dh[k] = zero ? 0.0 : sh;
        dl[k] = zero ? 0.0 : sl;
      }
      break;
    case Op::Neg:
      for (std::size_t k = 0; k < n; ++k) {
        dh[k] = -ah[k];
        dl[k] = -al[k];
        de[k] = ae[k];
      }
      break;
    case Op::Abs:
      for (std::size_t k = 0; k < n; ++k) {
        const double s = ah[k] < 0 ? -1.0 : 1.0;   // hi carries the sign (|lo| <= ulp(hi) / 2)
        dh[k] = s * ah[k];
        dl[k] = s * al[k];
        de[k] = ae[k];
      }
      break;
    default: break;
  }
}

bool is_rational(Op op) {
  switch (op) {
    case Op::Add: case Op::Sub: case Op::Mul: case Op::Div: case Op::Sqrt: case Op::Neg: case Op::Abs: return true;
    default: return false;
  }
}

// The other functions, point by point, through the long double steps: V rounded to long double
// (relative error 2^-64) and back, exactly, as hi + lo.
void library_block(Op op, double* dh, double* dl, double* de, const double* ah, const double* al, const double* ae,
                   const double* bh, const double* bl, const double* be, std::size_t n) {
  using LD = long double;
  const bool two = op_arity(op) == 2;
  for (std::size_t k = 0; k < n; ++k) {
    // V = hi + lo rounded to long double; its rounding error exactly (Fast2Sum in long double)
    const LD a = static_cast<LD>(ah[k]) + static_cast<LD>(al[k]);
    const LD ea = static_cast<LD>(ae[k]) + std::fabs(static_cast<LD>(al[k]) - (a - static_cast<LD>(ah[k])));
    certified::Step st;
    if (two) {
      const LD b = static_cast<LD>(bh[k]) + static_cast<LD>(bl[k]);
      const LD eb = static_cast<LD>(be[k]) + std::fabs(static_cast<LD>(bl[k]) - (b - static_cast<LD>(bh[k])));
      st = certified::binary(op, a, ea, b, eb);
    } else {
      st = certified::unary(op, a, ea);
    }
    const double h = static_cast<double>(st.v);
    const double l = static_cast<double>(st.v - static_cast<LD>(h));   // exact unless subnormal
    const LD e = st.e * certified::kSafe;
    const bool ok = !st.why && std::isfinite(st.v) && std::isfinite(e) && std::isfinite(h);
    dh[k] = ok ? h : 0.0;
    dl[k] = ok ? l : 0.0;
    // rounded up to double; kEta covers the subnormal case of l
    de[k] = ok ? std::nextafter(static_cast<double>(e), std::numeric_limits<double>::infinity()) + kEta : kNaN;
  }
}

// The neighbours of a finite double (as std::nextafter towards +-inf, branch-free).
inline double next_up(double x) {
  const auto b = std::bit_cast<std::uint64_t>(x);
  const double n = std::bit_cast<double>(x > 0 ? b + 1 : b - 1);
  return x == 0 ? std::numeric_limits<double>::denorm_min() : n;
}
inline double next_down(double x) { return -next_up(-x); }

// Per point: whether every real number in [h + l - e, h + l + e] rounds to one double, and that
// double. [h + next_down(l - e), h + next_up(l + e)] contains the interval (the outward steps
// cover the rounding of l -+ e) and rounding to nearest is monotonic, so equal ends decide; -0
// == +0 (the true value rounds to zero) counts as equal. e == 0: h + l is exact.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#endif
void decide_block(const double* __restrict h, const double* __restrict l, const double* __restrict e,
                  double* __restrict out, unsigned char* __restrict decided, std::size_t n) {
  constexpr double kMax = std::numeric_limits<double>::max();
  for (std::size_t k = 0; k < n; ++k) {
    const double down = h[k] + next_down(l[k] - e[k]);
    const double up = h[k] + next_up(l[k] + e[k]);
    const bool finite = std::fabs(h[k]) <= kMax && std::fabs(l[k]) <= kMax && e[k] >= 0 && e[k] <= kMax;
    const bool exact = e[k] == 0;
    out[k] = exact ? h[k] + l[k] : up;
    decided[k] = finite && (exact || down == up) ? 1 : 0;
  }
}

}  // namespace

std::optional<double> round_certified(double hi, double lo, double e) {
  double v = 0;
  unsigned char ok = 0;
  decide_block(&hi, &lo, &e, &v, &ok, 1);
  if (!ok) return std::nullopt;
  return v;
}

CertifiedBatch::CertifiedBatch(Program p) : prog_(std::move(p)), tape_(prog_) {
  // one more register: the scratch destination of an instruction that overwrites an operand
  hi_.assign((prog_.n_registers + 1) * kBlock, 0.0);
  lo_.assign((prog_.n_registers + 1) * kBlock, 0.0);
  er_.assign((prog_.n_registers + 1) * kBlock, 0.0);
  for (std::size_t c = 0; c < prog_.const_double.size(); ++c) {
    const std::size_t r = (prog_.n_inputs() + c) * kBlock;
    // renormalised (exactly): the cited bounds assume |lo| <= ulp(hi) / 2, and a constant's
    // hi comes from a 40-digit decimal, which may miss the nearest double next to a midpoint
    double h = 0, l = 0;
    two_sum(prog_.const_double[c], c < prog_.const_double_lo.size() ? prog_.const_double_lo[c] : 0.0, h, l);
    const double e = std::isfinite(h) ? kConst * std::fabs(h) + kEta : kNaN;
    for (std::size_t k = 0; k < kBlock; ++k) {
      hi_[r + k] = h;
      lo_[r + k] = l;
      er_[r + k] = e;
    }
  }
}

void CertifiedBatch::eval_dd_block(const BatchInputs& in, std::size_t offset, std::size_t n, double* hi, double* lo,
                                   double* bound) const {
  double* H = hi_.data();
  double* L = lo_.data();
  double* E = er_.data();
  for (std::size_t i = 0; i < prog_.n_inputs(); ++i) {
    const double* x = in.columns[i] + offset;
    const double* xl = in.lows && in.lows[i] ? in.lows[i] + offset : nullptr;
    const double* xe = in.errors && in.errors[i] ? in.errors[i] + offset : nullptr;
    for (std::size_t k = 0; k < n; ++k) {
      // a caller's double-double renormalised exactly (the cited bounds need |lo| <= ulp(hi)/2)
      double h = x[k], l = 0;
      if (xl) two_sum(x[k], xl[k], h, l);
      H[i * kBlock + k] = h;
      L[i * kBlock + k] = l;
      E[i * kBlock + k] = xe ? xe[k] : 0.0;
    }
  }
  const std::size_t scratch = prog_.n_registers * kBlock;
  for (const Instr& in : prog_.code) {
    const std::size_t a = in.a * kBlock, b = (op_arity(in.op) == 2 ? in.b : in.a) * kBlock;
    const std::size_t dst = in.dst * kBlock;
    const std::size_t d = dst == a || dst == b ? scratch : dst;
    (is_rational(in.op) ? rational_block : library_block)(in.op, H + d, L + d, E + d, H + a, L + a, E + a, H + b,
                                                          L + b, E + b, n);
    if (d != dst) {
      std::copy_n(H + d, n, H + dst);
      std::copy_n(L + d, n, L + dst);
      std::copy_n(E + d, n, E + dst);
    }
  }
  const std::size_t r = prog_.result * kBlock;
  for (std::size_t k = 0; k < n; ++k) {
    hi[k] = H[r + k];
    lo[k] = L[r + k];
    bound[k] = E[r + k];
  }
}

CertifiedBatchStats CertifiedBatch::eval(const BatchInputs& in, std::size_t n, double* out, CertifiedStage* stage) const {
  CertifiedBatchStats st;
  double hi[kBlock], lo[kBlock], bound[kBlock];
  unsigned char decided[kBlock];
  std::vector<double> x(prog_.n_inputs()), xe(prog_.n_inputs());
  const double inf = std::numeric_limits<double>::infinity();
  for (std::size_t off = 0; off < n; off += kBlock) {
    const std::size_t m = std::min(kBlock, n - off);
    eval_dd_block(in, off, m, hi, lo, bound);
    decide_block(hi, lo, bound, out + off, decided, m);
    for (std::size_t k = 0; k < m; ++k) {
      stage[off + k] = decided[k] ? CertifiedStage::DoubleDouble : CertifiedStage::None;
      if (decided[k]) {
        ++st.double_double;
        continue;
      }
      out[off + k] = hi[k] + lo[k];
      // stage 2 takes double inputs: a low part becomes input error (rounded up)
      for (std::size_t i = 0; i < prog_.n_inputs(); ++i) {
        x[i] = in.columns[i][off + k];
        const double e = in.errors && in.errors[i] ? in.errors[i][off + k] : 0.0;
        const double l = in.lows && in.lows[i] ? std::fabs(in.lows[i][off + k]) : 0.0;
        xe[i] = l == 0 ? e : std::nextafter(e + l, inf);
      }
      const FastCertified r = tape_(x.data(), xe.data());
      if (r.decided) {
        out[off + k] = r.value;
        stage[off + k] = CertifiedStage::LongDouble;
        ++st.long_double;
      } else {
        ++st.undecided;
      }
    }
  }
  return st;
}

}  // namespace dc::num
