// Double-double evaluation with a running error bound, a block of points at a time (see
// certified_batch.hpp for the error model). Compiled with -ffp-contract=off (CMakeLists.txt): the
// error-free transformations and the cited bounds need every operation rounded as written.
#include "numeric/certified/certified_batch.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "numeric/certified/certified_steps.hpp"
#include "numeric/dd_functions.hpp"
#include "numeric/dd_tables.hpp"
#include "numeric/double_double.hpp"

namespace dc::num {
namespace {

using namespace dde;
constexpr double kConst = 0x1p-100;   // a constant: 40 digits (1e-39) rounded to double-double

// One instruction of + - * / sqrt neg abs over n points. The destination never aliases an
// operand (eval_dd_block goes through a scratch register), so that the loops vectorise.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#endif
void rational_block(Op op, double* __restrict dh, double* __restrict dl, double* __restrict de,
                    const double* __restrict ah, const double* __restrict al, const double* __restrict ae,
                    const double* __restrict bh, const double* __restrict bl, const double* __restrict be,
                    std::size_t n) {
  const auto A = [&](std::size_t k) { return DDE{ah[k], al[k], ae[k]}; };
  const auto B = [&](std::size_t k) { return DDE{bh[k], bl[k], be[k]}; };
  const auto put = [&](std::size_t k, DDE v) {
    dh[k] = v.h;
    dl[k] = v.l;
    de[k] = v.e;
  };
  switch (op) {
    case Op::Add: for (std::size_t k = 0; k < n; ++k) put(k, add_keep_exact(A(k), B(k))); break;
    case Op::Sub: for (std::size_t k = 0; k < n; ++k) put(k, add_keep_exact(A(k), neg(B(k)))); break;
    case Op::Mul: for (std::size_t k = 0; k < n; ++k) put(k, mul_keep_exact(A(k), B(k))); break;
    case Op::Div: for (std::size_t k = 0; k < n; ++k) put(k, div(A(k), B(k))); break;
    case Op::Sqrt: for (std::size_t k = 0; k < n; ++k) put(k, dde::sqrt(A(k))); break;
    case Op::Neg: for (std::size_t k = 0; k < n; ++k) put(k, neg(A(k))); break;
    case Op::Abs:
      for (std::size_t k = 0; k < n; ++k) {
        const double s = ah[k] < 0 ? -1.0 : 1.0;   // hi carries the sign (|lo| <= ulp(hi) / 2)
        put(k, DDE{s * ah[k], s * al[k], ae[k]});
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

// One point of a function without (or beyond the range of) a double-double kernel, through the
// long double steps: V rounded to long double (relative error 2^-64) and back, exactly, as hi + lo.
void library_lane(Op op, double* dh, double* dl, double* de, const double* ah, const double* al, const double* ae,
                  const double* bh, const double* bl, const double* be, std::size_t k) {
  using LD = long double;
  // V = hi + lo rounded to long double; its rounding error exactly (Fast2Sum in long double)
  const LD a = static_cast<LD>(ah[k]) + static_cast<LD>(al[k]);
  const LD ea = static_cast<LD>(ae[k]) + std::fabs(static_cast<LD>(al[k]) - (a - static_cast<LD>(ah[k])));
  certified::Step st;
  if (op_arity(op) == 2) {
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

// The other functions: the double-double kernels (dd_functions.hpp) where there is one, and the
// long double step at the points where the kernel gives up (or where there is none).
void library_block(Op op, double* dh, double* dl, double* de, const double* ah, const double* al, const double* ae,
                   const double* bh, const double* bl, const double* be, std::size_t n) {
  const bool kernel = has_kernel(op);
  if (kernel) function_block(op, dh, dl, de, ah, al, ae, bh, bl, be, n);
  for (std::size_t k = 0; k < n; ++k) {
    const bool good = std::fabs(dh[k]) <= std::numeric_limits<double>::max() &&
                      std::fabs(dl[k]) <= std::numeric_limits<double>::max() && de[k] >= 0 &&
                      de[k] <= std::numeric_limits<double>::max();
    if (!kernel || !good) library_lane(op, dh, dl, de, ah, al, ae, bh, bl, be, k);
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
  // the kernels' tables: built here, not inside a block loop, since building them uses GiNaC
  // (which is not thread-safe) and takes a few milliseconds
  if (std::any_of(prog_.code.begin(), prog_.code.end(), [](const Instr& in) { return has_kernel(in.op); })) tables();
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
    double* __restrict h = H + i * kBlock;
    double* __restrict l = L + i * kBlock;
    // whole-vector copies and fills: element-wise stores here would be read back as vectors by
    // the first instruction's loop, and on Intel cores such loads cannot be forwarded from
    // the pending scalar stores (they stall; measured 13 % of velocity_symbols' time)
    if (xl) {
      // a caller's double-double renormalised exactly (the cited bounds need |lo| <= ulp(hi)/2)
      for (std::size_t k = 0; k < n; ++k) two_sum(x[k], xl[k], h[k], l[k]);
    } else {
      std::copy_n(x, n, h);
      std::fill_n(l, n, 0.0);
    }
    if (xe) std::copy_n(xe, n, E + i * kBlock);
    else std::fill_n(E + i * kBlock, n, 0.0);
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
  std::copy_n(H + r, n, hi);
  std::copy_n(L + r, n, lo);
  std::copy_n(E + r, n, bound);
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
