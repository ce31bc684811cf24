// Double-double tape evaluation (see compensated.hpp).
#include "numeric/compensated.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "numeric/dd_functions.hpp"
#include "numeric/dd_tables.hpp"

namespace dc::num {
namespace dd {
namespace {

using LD = long double;

LD to_ld(const DD& a) { return static_cast<LD>(a.hi) + static_cast<LD>(a.lo); }

// a long double value split exactly into a double-double (64 bits fit in 53 + 53)
DD from_ld(LD v) {
  const double hi = static_cast<double>(v);
  if (!std::isfinite(hi)) return {hi, 0.0};
  return {hi, static_cast<double>(v - static_cast<LD>(hi))};
}

// expm1 in double-double, relative accuracy ~2^-100 for |x| <= 0.5: x scaled by 2^-9, Taylor
// series, then nine doublings expm1(2r) = 2 expm1(r) + expm1(r)^2 (no cancellation: relative).
DD expm1_small(const DD& x) {
  const DD r = {std::ldexp(x.hi, -9), std::ldexp(x.lo, -9)};
  // sum r^n/n!, n = 1..12 (|r| < 1e-3: the 12th term is below 1e-44 relative)
  DD term = r, sum = r;
  for (int n = 2; n <= 12; ++n) {
    term = div(mul(term, r), DD{static_cast<double>(n), 0.0});
    sum = add(sum, term);
    if (std::fabs(term.hi) < 1e-36 * std::fabs(sum.hi)) break;
  }
  for (int i = 0; i < 9; ++i) sum = add(mul_d(sum, 2.0), mul(sum, sum));
  return sum;
}

const DD kLn2{6.93147180559945286e-01, 2.319046813846299558e-17};

// exp(x) - 1 and exp(x) in double-double: x = k ln2 + r, |r| <= ln2/2
DD expm1_dd(const DD& x) {
  if (!std::isfinite(x.hi)) return {std::expm1(x.hi), 0.0};
  if (std::fabs(x.hi) <= 0.5) return expm1_small(x);
  if (x.hi > 709.8) return {INFINITY, 0.0};
  if (x.hi < -745.2) return {-1.0, 0.0};
  const double k = std::nearbyint(x.hi / kLn2.hi);
  const DD r = sub(x, mul_d(kLn2, k));
  const DD e = add(expm1_small(r), DD{1.0, 0.0});  // exp(r) in [0.7, 1.42]
  const int ki = static_cast<int>(k);
  const DD ek = {std::ldexp(e.hi, ki), std::ldexp(e.lo, ki)};  // exact unless it underflows
  return add(ek, DD{-1.0, 0.0});
}
DD exp_dd(const DD& x) {
  if (!std::isfinite(x.hi)) return {std::exp(x.hi), 0.0};
  if (x.hi > 709.8) return {INFINITY, 0.0};
  if (x.hi < -745.2) return {0.0, 0.0};
  if (std::fabs(x.hi) <= 0.5) return add(expm1_small(x), DD{1.0, 0.0});
  const double k = std::nearbyint(x.hi / kLn2.hi);
  const DD r = sub(x, mul_d(kLn2, k));
  const DD e = add(expm1_small(r), DD{1.0, 0.0});
  // 2^k in two steps: ldexp of a value near 1 by k near -1074 or 1024 in one step could
  // round a subnormal twice; these halves are exact
  const int ki = static_cast<int>(k), k1 = ki / 2, k2 = ki - k1;
  const double s1 = std::ldexp(1.0, k1), s2 = std::ldexp(1.0, k2);
  const DD p = mul_d(mul_d(e, s1), s2);
  return std::isfinite(p.hi) ? p : DD{p.hi, 0.0};
}

// log1p(a) in double-double: y0 = log1p in long double, then one Newton step on
// exp(y) = 1 + a written without cancellation: y1 = y0 + a exp(-y0) + expm1(-y0)
DD log_dd(const DD& x);

DD log1p_dd(const DD& a) {
  if (std::isnan(a.hi) || !std::isfinite(a.hi)) return {std::log1p(a.hi), 0.0};
  // far from 0, 1 + a is formed in double-double without loss (exactly for a in [-1, -1/2]),
  // which keeps log1p(-1 + 1e-162) finite and correct: its lo part carries the 1e-162
  if (a.hi < -0.5 || a.hi > 1.0) return log_dd(add(a, DD{1.0, 0.0}));
  if (a.hi == 0.0) return a;
  const DD y0 = from_ld(std::log1p(to_ld(a)));
  const DD ny = neg(y0);
  const DD corr = add(mul(a, exp_dd(ny)), expm1_dd(ny));
  return add(y0, corr);
}

// log(x): near 1 as log1p(x - 1) (x - 1 exact in double-double there); elsewhere Newton from the
// long double value: y1 = y0 + x exp(-y0) - 1
DD log_dd(const DD& x) {
  if (!(x.hi > 0.0) || !std::isfinite(x.hi)) return {std::log(x.hi), 0.0};
  if (x.hi > 0.5 && x.hi < 2.0) return log1p_dd(sub(x, DD{1.0, 0.0}));
  const DD y0 = from_ld(std::log(to_ld(x)));
  const DD e = exp_dd(neg(y0));
  if (e.hi == 0.0 || !std::isfinite(e.hi)) return y0;  // x beyond exp's range: y0 as is
  return add(y0, add(mul(x, e), DD{-1.0, 0.0}));
}

// sin, cos, tan, asin, acos, atan, pow: the certified batch's double-double kernels (their
// bound is not needed here, only their ~2^-70 relative accuracy or better); false where a
// kernel gives up (sin beyond 2^20, acos next to +-1, pow of a negative base, ...)
bool kernel_value(Op op, const DD& a, const DD& b, DD& out) {
  using dde::DDE;
  const DDE r = dde::apply(op, DDE{a.hi, a.lo, 0.0}, DDE{b.hi, b.lo, 0.0});
  if (!(std::isfinite(r.e) && std::isfinite(r.h) && std::isfinite(r.l))) return false;
  out = {r.h, r.l};
  return true;
}

}  // namespace

DD transcendental(Op op, const DD& a, const DD& b) {
  DD k;
  switch (op) {
    case Op::Sin: case Op::Cos: case Op::Tan: case Op::Asin: case Op::Acos: case Op::Atan: case Op::Pow:
      if (kernel_value(op, a, b, k)) return k;
      break;
    default: break;
  }
  switch (op) {
    case Op::Exp: return exp_dd(a);
    case Op::Expm1: return expm1_dd(a);
    case Op::Log: return log_dd(a);
    case Op::Log1p: return log1p_dd(a);
    case Op::Sin: return from_ld(std::sin(to_ld(a)));
    case Op::Cos: return from_ld(std::cos(to_ld(a)));
    case Op::Tan: return from_ld(std::tan(to_ld(a)));
    case Op::Asin: return from_ld(std::asin(to_ld(a)));
    case Op::Acos:
      // acos(x) = 2 asin(sqrt((1 - x)/2)): 1 - x in double-double keeps acos(1 - tiny)
      if (a.hi > 0.5 && a.hi <= 1.0) {
        const DD h = mul_d(sub(DD{1.0, 0.0}, a), 0.5);
        return mul_d(from_ld(std::asin(to_ld(sqrt(h)))), 2.0);
      }
      return from_ld(std::acos(to_ld(a)));
    case Op::Atan: return from_ld(std::atan(to_ld(a)));
    case Op::Pow: return from_ld(std::pow(to_ld(a), to_ld(b)));
    case Op::Hypot: {
      const double m = std::max(std::fabs(a.hi), std::fabs(b.hi));
      if (m == 0.0 || !std::isfinite(m)) return {std::hypot(a.hi, b.hi), 0.0};
      int ex = 0;
      std::frexp(m, &ex);
      const double s = std::ldexp(1.0, -ex), inv = std::ldexp(1.0, ex);  // exact scalings
      const DD as = mul_d(a, s), bs = mul_d(b, s);
      const DD r = sqrt(add(mul(as, as), mul(bs, bs)));
      return mul_d(r, inv);
    }
    default: return apply(op, a, b);
  }
}

}  // namespace dd

CompensatedEvaluator::CompensatedEvaluator(Program p) : prog_(std::move(p)) {
  // the kernels' tables, built here rather than on first use inside an evaluation (building
  // them uses GiNaC, which is not thread-safe)
  if (std::any_of(prog_.code.begin(), prog_.code.end(), [](const Instr& in) { return dde::has_kernel(in.op); }))
    dde::tables();
  regs_.assign(prog_.n_registers, DD{});
  for (std::size_t c = 0; c < prog_.const_double.size(); ++c)
    regs_[prog_.n_inputs() + c] =
        DD{prog_.const_double[c], c < prog_.const_double_lo.size() ? prog_.const_double_lo[c] : 0.0};
}

double CompensatedEvaluator::operator()(const std::vector<double>& args) const {
  if (args.size() != prog_.n_inputs())
    throw std::invalid_argument("evaluator: expected " + std::to_string(prog_.n_inputs()) +
                                " input values, got " + std::to_string(args.size()));
  return (*this)(args.data());
}

namespace {

// One instruction over n points, registers as separate hi and lo arrays. The switch is outside
// the loops, so each loop is straight-line error-free arithmetic.
// Cloned for CPUs with FMA (chosen at load time by GCC's ifunc dispatch): the baseline x86-64
// build (no -march) would otherwise call libm's fma() for every TwoProd and vectorise nothing.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__FMA__)
__attribute__((target_clones("fma", "default")))
#endif
void apply_block(Op op, double* __restrict dh, double* __restrict dl, const double* ah,
                 const double* al, const double* bh, const double* bl, std::size_t n) {
  switch (op) {
    case Op::Add:
      for (std::size_t i = 0; i < n; ++i) {
        const DD r = dd::add({ah[i], al[i]}, {bh[i], bl[i]});
        dh[i] = r.hi, dl[i] = r.lo;
      }
      return;
    case Op::Sub:
      for (std::size_t i = 0; i < n; ++i) {
        const DD r = dd::add({ah[i], al[i]}, {-bh[i], -bl[i]});
        dh[i] = r.hi, dl[i] = r.lo;
      }
      return;
    case Op::Mul:
      for (std::size_t i = 0; i < n; ++i) {
        const DD r = dd::mul({ah[i], al[i]}, {bh[i], bl[i]});
        dh[i] = r.hi, dl[i] = r.lo;
      }
      return;
    case Op::Div:
      for (std::size_t i = 0; i < n; ++i) {
        const DD r = dd::div({ah[i], al[i]}, {bh[i], bl[i]});
        dh[i] = r.hi, dl[i] = r.lo;
      }
      return;
    case Op::Neg:
      for (std::size_t i = 0; i < n; ++i) dh[i] = -ah[i], dl[i] = -al[i];
      return;
    default:
      for (std::size_t i = 0; i < n; ++i) {
        const DD r = dd::apply(op, {ah[i], al[i]}, {bh[i], bl[i]});
        dh[i] = r.hi, dl[i] = r.lo;
      }
      return;
  }
}

}  // namespace

void CompensatedEvaluator::eval_batch(const double* const* columns, double* out, std::size_t n) const {
  const std::size_t nreg = prog_.n_registers, nin = prog_.n_inputs(), first_temp = prog_.first_temp();
  if (hi_.size() != nreg * kBlock) {
    hi_.assign(nreg * kBlock, 0.0);
    lo_.assign(nreg * kBlock, 0.0);
    for (std::size_t c = nin; c < first_temp; ++c)
      for (std::size_t i = 0; i < kBlock; ++i) {
        hi_[c * kBlock + i] = regs_[c].hi;
        lo_[c * kBlock + i] = regs_[c].lo;
      }
  }
  // inputs are exact doubles: their lo parts are the zero rows of the input registers
  std::vector<const double*> sh(nreg), sl(nreg);
  for (std::size_t c = 0; c < nreg; ++c) {
    sh[c] = hi_.data() + c * kBlock;
    sl[c] = lo_.data() + c * kBlock;
  }
  for (std::size_t start = 0; start < n; start += kBlock) {
    const std::size_t m = std::min(kBlock, n - start);
    for (std::size_t i = 0; i < nin; ++i) sh[i] = columns[i] + start;
    for (const Instr& in : prog_.code)
      apply_block(in.op, hi_.data() + in.dst * kBlock, lo_.data() + in.dst * kBlock, sh[in.a],
                  sl[in.a], sh[in.b], sl[in.b], m);
    const double* rh = sh[prog_.result];
    const double* rl = sl[prog_.result];
    for (std::size_t i = 0; i < m; ++i) out[start + i] = rh[i] + rl[i];
  }
}

void CompensatedEvaluator::eval_batch(const Eigen::ArrayXXd& in, Eigen::ArrayXd& out) const {
  if (static_cast<std::size_t>(in.cols()) != prog_.n_inputs())
    throw std::invalid_argument("evaluator: expected " + std::to_string(prog_.n_inputs()) +
                                " input columns, got " + std::to_string(in.cols()));
  std::vector<const double*> cols(static_cast<std::size_t>(in.cols()));
  for (Eigen::Index j = 0; j < in.cols(); ++j) cols[static_cast<std::size_t>(j)] = in.col(j).data();
  out.resize(in.rows());
  eval_batch(cols.data(), out.data(), static_cast<std::size_t>(in.rows()));
}

}  // namespace dc::num
