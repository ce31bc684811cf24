// Long double evaluation with a running error bound (see certified_fast.hpp).
#include "numeric/certified/certified_fast.hpp"

#include <cmath>
#include <limits>

#include "numeric/certified/certified_steps.hpp"

namespace dc::num {
namespace certified {
namespace {

using LD = long double;

constexpr LD kU = 0x1p-64L;                 // unit roundoff of the 64-bit significand
constexpr LD kEta = 0x1p-16445L;            // smallest subnormal long double
constexpr LD kLib = 8 * 0x1p-63L;           // 8 ulps of a libm result, relative

LD rounding(LD v) { return kU * std::fabs(v) + kEta; }
LD library(LD v) { return kLib * std::fabs(v) + 8 * kEta; }

Step fail(const char* why) { return {0, 0, why}; }

// (inlined into the tape's loop; unary() and binary() below are the same for other callers)
Step unary_step(Op op, LD a, LD ea) {
  using std::fabs, std::sqrt;
  switch (op) {
    case Op::Neg: return {-a, ea};
    case Op::Abs: return {fabs(a), ea};
    case Op::Sqrt: {
      if (a == 0 && ea == 0) return {0, 0};
      if (!(a > 0) || ea > a / 2) return fail("sqrt of an interval reaching 0");
      const LD v = sqrtl(a);
      return {v, ea / v + rounding(v)};   // |sqrt(x') - sqrt(a)| <= ea / (sqrt(x') + sqrt(a))
    }
    case Op::Exp: {
      const LD v = expl(a);
      return {v, library(v) + (fabs(v) + library(v)) * expm1l(ea)};
    }
    case Op::Expm1: {
      const LD v = expm1l(a);   // d/dx = e^x = 1 + expm1(x)
      return {v, library(v) + (fabs(1 + v) + library(v) + kU) * expm1l(ea)};
    }
    case Op::Log: {
      if (!(a > 0) || ea > a / 2) return fail("log of an interval reaching 0");
      const LD v = logl(a);
      return {v, library(v) + 2 * ea / a};
    }
    case Op::Log1p: {
      const LD d = 1 + a;   // its rounding is covered below by the factor 2 margin
      if (!(d > 0) || ea > d / 4) return fail("log1p of an interval reaching -1");
      const LD v = log1pl(a);
      return {v, library(v) + 2 * ea / d};
    }
    case Op::Sin: {
      const LD v = sinl(a);
      return {v, library(v) + ea};
    }
    case Op::Cos: {
      const LD v = cosl(a);
      return {v, library(v) + ea};
    }
    case Op::Tan: {
      const LD v = tanl(a);
      // sup |tan| over [a - ea, a + ea] <= (|t| + tan ea) / (1 - |t| tan ea) <= 2 (|t| + 2 ea)
      // when |t| tan ea <= 1/2 (tan ea <= 2 ea for ea <= 1)
      const LD t = fabs(v) + library(v);
      if (!(ea <= 0x1p-10L) || t * 2 * ea > 0.5L) return fail("tan of an interval near a pole");
      const LD sup = 2 * (t + 2 * ea);
      return {v, library(v) + ea * (1 + sup * sup)};
    }
    case Op::Atan: {
      const LD v = atanl(a);
      return {v, library(v) + ea};
    }
    case Op::Asin:
    case Op::Acos: {
      // |d/dx| = 1 / sqrt(1 - x^2) <= 1 / sqrt(1 - m) with m = |a| + ea < 1 (1 + m >= 1)
      const LD gap = 1 - fabs(a);
      if (!(gap > 0) || ea > gap / 4) return fail("asin/acos of an interval reaching +-1");
      const LD v = op == Op::Asin ? asinl(a) : acosl(a);
      return {v, library(v) + 2 * ea / sqrtl(gap / 2)};
    }
    default: break;
  }
  return fail("unsupported operation");
}

Step binary_step(Op op, LD a, LD ea, LD b, LD eb) {
  using std::fabs;
  switch (op) {
    case Op::Add: { const LD v = a + b; return {v, ea + eb + rounding(v)}; }
    case Op::Sub: { const LD v = a - b; return {v, ea + eb + rounding(v)}; }
    case Op::Mul: {
      const LD v = a * b;
      return {v, fabs(a) * eb + fabs(b) * ea + ea * eb + rounding(v)};
    }
    case Op::Div: {
      if (!(fabs(b) > 0) || eb > fabs(b) / 2) return fail("division by an interval reaching 0");
      const LD v = a / b;
      // |a/b - a'/b'| <= (|a| eb + |b| ea) / (|b| |b'|), |b'| >= |b| / 2
      return {v, 2 * (fabs(a) * eb + fabs(b) * ea) / (b * b) + rounding(v)};
    }
    case Op::Hypot: {
      const LD v = hypotl(a, b);   // 1-Lipschitz in each argument
      return {v, library(v) + ea + eb};
    }
    case Op::Pow: {
      // a^b = exp(b log a) for a > 0 (integer powers never reach here: they are multiplications)
      if (!(a > 0) || ea > a / 2) return fail("pow of a base interval reaching 0");
      const LD v = powl(a, b);
      const LD la = fabs(logl(a)) * (1 + kLib) + 8 * kEta;
      const LD dl = 2 * ea / a;                           // |log a' - log a|
      const LD dz = fabs(b) * dl + eb * (la + dl);          // |b' log a' - b log a|
      if (!(dz <= 1)) return fail("pow with a wide exponent interval");
      return {v, library(v) + (fabs(v) + library(v)) * expm1l(dz) * (1 + kLib)};
    }
    default: break;
  }
  return fail("unsupported operation");
}

}  // namespace

Step unary(Op op, LD a, LD ea) { return unary_step(op, a, ea); }
Step binary(Op op, LD a, LD ea, LD b, LD eb) { return binary_step(op, a, ea, b, eb); }

}  // namespace certified

using certified::kSafe;
using LD = long double;
constexpr LD kInf = std::numeric_limits<LD>::infinity();

CertifiedTape::CertifiedTape(Program p) : prog_(std::move(p)) {
  v_.assign(prog_.n_registers, 0);
  e_.assign(prog_.n_registers, 0);
  for (const Instr& in : prog_.code) binary_.push_back(op_arity(in.op) == 2);
  for (std::size_t c = 0; c < prog_.const_long_double.size(); ++c) {
    const std::size_t r = prog_.n_inputs() + c;
    v_[r] = prog_.const_long_double[c];
    // the constant went through 40 significant digits and strtold: 1e-39 + 2^-64 relative
    e_[r] = 0x1p-63L * std::fabs(v_[r]) * kSafe;
  }
}

FastCertified CertifiedTape::operator()(const double* x, const double* x_err) const {
  FastCertified out;
  LD* v = v_.data();
  LD* e = e_.data();
  for (std::size_t i = 0; i < prog_.n_inputs(); ++i) {
    v[i] = x[i];
    e[i] = x_err ? static_cast<LD>(x_err[i]) * kSafe : 0;
  }
  for (std::size_t i = 0; i < prog_.code.size(); ++i) {
    const Instr& in = prog_.code[i];
    const certified::Step st = binary_[i] ? certified::binary_step(in.op, v[in.a], e[in.a], v[in.b], e[in.b])
                                           : certified::unary_step(in.op, v[in.a], e[in.a]);
    if (st.why || !std::isfinite(st.v) || !std::isfinite(st.e)) {
      out.why_not = st.why ? st.why : "a value or bound beyond long double's range";
      return out;
    }
    v[in.dst] = st.v;
    e[in.dst] = st.e * kSafe;
  }
  out.approx = v[prog_.result];
  out.bound = e[prog_.result];
  // [lo, hi] contains the true value: the roundings of v -+ e are covered by one step outward
  const LD lo = std::nextafter(out.approx - out.bound, -kInf);
  const LD hi = std::nextafter(out.approx + out.bound, kInf);
  const double dlo = static_cast<double>(lo), dhi = static_cast<double>(hi);   // round to nearest
  if (out.bound == 0) {
    out.decided = true;
    out.value = static_cast<double>(out.approx);
  } else if (dlo == dhi) {   // also -0 == +0: the true value rounds to zero
    out.decided = true;
    out.value = dhi;
  } else {
    out.why_not = "the enclosure straddles a rounding boundary of double";
  }
  return out;
}

}  // namespace dc::num
