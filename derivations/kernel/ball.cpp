// Rigorous evaluation with Arb (see ball.hpp). One recursive walk over the GiNaC tree; each
// node returns a status and, for Value, an arb ball that contains the true real value.
#include "derivations/kernel/ball.hpp"
#include "derivations/kernel/ball_impl.hpp"
#include "derivations/kernel/ball_box.hpp"

#include <algorithm>
#include <sstream>

#include <arb.h>
#include <arb_hypgeom.h>
#include <cln/integer.h>
#include <cln/integer_io.h>
#include <cln/rational.h>
#include <cln/real.h>

namespace dc::kernel {

using GiNaC::ex;
using GiNaC::numeric;


Ball::Ball() : impl(std::make_unique<Impl>()) {}
Ball::~Ball() = default;
Ball::Ball(Ball&&) noexcept = default;
Ball& Ball::operator=(Ball&&) noexcept = default;

bool Ball::positive() const { return status == BallStatus::Value && arb_is_positive(impl->v); }
bool Ball::negative() const { return status == BallStatus::Value && arb_is_negative(impl->v); }
bool Ball::exact_zero() const { return status == BallStatus::Value && arb_is_zero(impl->v); }
bool Ball::contains_zero() const { return status != BallStatus::Value || arb_contains_zero(impl->v); }

namespace {

std::string arb_text(const arb_t x, int sig) {
  char* s = arb_get_str(x, sig, ARB_STR_NO_RADIUS);
  std::string out(s);
  flint_free(s);
  return out;
}

}  // namespace

std::string Ball::text(int sig) const {
  switch (status) {
    case BallStatus::Value: {
      // Values with astronomically large or small exponents are shown as 10^(x): their
      // decimal exponent alone can have thousands of digits.
      const arf_struct* m = arb_midref(impl->v);
      if (!arf_is_zero(m) && (arf_cmpabs_2exp_si(m, 1L << 16) > 0 || arf_cmpabs_2exp_si(m, -(1L << 16)) < 0)) {
        arb_t t, ten;
        arb_init(t);
        arb_init(ten);
        arb_abs(t, impl->v);
        arb_log_base_ui(t, t, 10, 128);
        std::string out = std::string(arf_sgn(m) < 0 ? "-" : "") + "10^(" + arb_text(t, 12) + ")";
        arb_clear(t);
        arb_clear(ten);
        return out;
      }
      return arb_text(impl->v, sig);
    }
    case BallStatus::NotReal: return "not real (" + why + ")";
    case BallStatus::Pole: return "undefined (" + why + ")";
    case BallStatus::Unknown: return "unknown (" + why + ")";
  }
  return "";
}

namespace {

// man * 2^exp of a finite arf, exactly; false when |exp| is too large to write out.
bool arf_to_numeric(const arf_t x, GiNaC::numeric& out, long max_exp_bits) {
  if (arf_is_zero(x)) {
    out = 0;
    return true;
  }
  if (!arf_is_finite(x)) return false;
  fmpz_t man, exp;
  fmpz_init(man);
  fmpz_init(exp);
  arf_get_fmpz_2exp(man, exp, x);
  bool ok = fmpz_fits_si(exp) && std::labs(fmpz_get_si(exp)) <= max_exp_bits;
  if (ok) {
    char* digits = fmpz_get_str(nullptr, 10, man);
    long e = fmpz_get_si(exp);
    GiNaC::numeric m(digits);
    flint_free(digits);
    out = e >= 0 ? m * GiNaC::numeric(2).power(e) : m / GiNaC::numeric(2).power(-e);
  }
  fmpz_clear(man);
  fmpz_clear(exp);
  return ok;
}

}  // namespace

bool Ball::exact_bounds(GiNaC::numeric& lo, GiNaC::numeric& hi, long max_exp_bits) const {
  if (status != BallStatus::Value) return false;
  arf_t a;
  arf_init(a);
  arb_get_lbound_arf(a, impl->v, ARF_PREC_EXACT);
  bool ok = arf_to_numeric(a, lo, max_exp_bits);
  arb_get_ubound_arf(a, impl->v, ARF_PREC_EXACT);
  ok = ok && arf_to_numeric(a, hi, max_exp_bits);
  arf_clear(a);
  return ok;
}

long Ball::rel_accuracy_bits() const {
  if (status != BallStatus::Value) return 0;
  return arb_rel_accuracy_bits(impl->v);
}

double Ball::to_double() const {
  if (status != BallStatus::Value) return 0;
  return arf_get_d(arb_midref(impl->v), ARF_RND_NEAR);
}

namespace {

// Arguments whose magnitude exceeds 2^kMaxExpBits are refused (Unknown): exp of them would
// need an exponent that does not fit in memory.
constexpr long kMaxExpBits = 1L << 26;

class BallEvaluator {
 public:
  explicit BallEvaluator(long prec, const GiNaC::exmap* point = nullptr, const Box* box = nullptr)
      : prec_(prec), point_(point), box_(box) {}
  std::string why;

  BallStatus eval(const ex& e, arb_t out) {
    if (GiNaC::is_a<numeric>(e)) return number(GiNaC::ex_to<numeric>(e), out);
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
      bool is_add = GiNaC::is_a<GiNaC::add>(e);
      arb_set_si(out, is_add ? 0 : 1);
      Tmp t;
      BallStatus worst = BallStatus::Value;
      for (std::size_t i = 0; i < e.nops(); ++i) {
        BallStatus s = eval(e.op(i), t.v);
        if (s == BallStatus::NotReal || s == BallStatus::Pole) return s;   // certified: done
        if (s == BallStatus::Unknown) {
          worst = s;
          continue;   // a later operand may still be certified NotReal
        }
        if (is_add) arb_add(out, out, t.v, prec_);
        else arb_mul(out, out, t.v, prec_);
      }
      return worst == BallStatus::Value ? finite(out) : worst;
    }
    if (GiNaC::is_a<GiNaC::power>(e)) return power(e.op(0), e.op(1), out);
    if (GiNaC::is_a<GiNaC::constant>(e)) {
      if (e.is_equal(GiNaC::Pi)) arb_const_pi(out, prec_);
      else if (e.is_equal(GiNaC::Euler)) arb_const_euler(out, prec_);
      else if (e.is_equal(GiNaC::Catalan)) arb_const_catalan(out, prec_);
      else return unknown("an unknown constant");
      return BallStatus::Value;
    }
    if (GiNaC::is_a<GiNaC::function>(e)) return function(e, out);
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
      // the sample point's value, read here rather than substituted: GiNaC would evaluate
      // (1 + 1/x)^x exactly at x = 10^29/7 and never finish
      if (point_) {
        auto it = point_->find(e);
        if (it != point_->end()) return eval(it->second, out);
      }
      if (box_) {
        auto it = box_->find(e);
        if (it != box_->end()) {
          // the whole interval [lo, hi] as one ball
          Tmp lo, hi;
          if (number(it->second.first, lo.v) != BallStatus::Value || number(it->second.second, hi.v) != BallStatus::Value)
            return unknown("a box with a non-real end");
          arb_union(out, lo.v, hi.v, prec_);
          return BallStatus::Value;
        }
      }
      return unknown("a symbol without a value");
    }
    return unknown("an expression that is not a number");
  }

 private:
  long prec_;
  const GiNaC::exmap* point_;
  const Box* box_;

  struct Tmp {
    arb_t v;
    Tmp() { arb_init(v); }
    ~Tmp() { arb_clear(v); }
    Tmp(const Tmp&) = delete;
    Tmp& operator=(const Tmp&) = delete;
  };

  BallStatus unknown(const std::string& w) {
    if (why.empty()) why = w;
    return BallStatus::Unknown;
  }
  BallStatus not_real(const std::string& w) {
    why = w;
    return BallStatus::NotReal;
  }
  BallStatus pole(const std::string& w) {
    why = w;
    return BallStatus::Pole;
  }
  BallStatus finite(arb_t x) {
    if (!arb_is_finite(x)) return unknown("the enclosure is not finite at this precision");
    return BallStatus::Value;
  }

  static void set_fmpz_from_cln(fmpz_t z, const cln::cl_I& i) {
    if (cln::integer_length(i) < 62) {
      fmpz_set_si(z, cln::cl_I_to_long(i));
      return;
    }
    std::ostringstream os;
    os << i;
    fmpz_set_str(z, os.str().c_str(), 10);
  }

  BallStatus number(const numeric& n, arb_t out) {
    // An imaginary part here comes from a real-only operation outside its domain that GiNaC
    // has already evaluated (log(-3/2) = log(3/2) + I*pi, sqrt(-4) = 2*I): no real value.
    if (!n.is_real()) return not_real("a complex intermediate value (log or root of a negative number)");
    cln::cl_R r = cln::the<cln::cl_R>(n.to_cl_N());
    cln::cl_RA q = cln::rational(r);   // exact value of a rational or of a binary float
    fmpz_t a, b;
    fmpz_init(a);
    fmpz_init(b);
    set_fmpz_from_cln(a, cln::numerator(q));
    set_fmpz_from_cln(b, cln::denominator(q));
    arb_set_fmpz(out, a);
    if (!fmpz_is_one(b)) arb_div_fmpz(out, out, b, prec_);
    fmpz_clear(a);
    fmpz_clear(b);
    return BallStatus::Value;
  }

  // exp(x) also for arguments so large that Arb's exp gives up: 2^floor(lo/ln 2) <= exp(x) <=
  // 2^ceil(hi/ln 2), exact powers of two with exponents as big as the argument requires.
  BallStatus exp_of(const arb_t x, arb_t out) {
    arb_exp(out, x, prec_);
    if (arb_is_finite(out) && !(arb_contains_zero(out) && arb_is_positive(x))) return BallStatus::Value;
    if (!arb_is_finite(x)) return unknown("exp of an argument that is not finite");
    if (arf_cmpabs_2exp_si(arb_midref(x), kMaxExpBits) > 0) return unknown("exp of an argument beyond 2^(2^26)");
    Tmp ln2, t;
    arb_const_log2(ln2.v, prec_);
    arb_div(t.v, x, ln2.v, prec_);
    arf_t lo, hi;
    arf_init(lo);
    arf_init(hi);
    arb_get_lbound_arf(lo, t.v, prec_);
    arb_get_ubound_arf(hi, t.v, prec_);
    // a wide ball (exp(exp(exp(x))) at a huge x) has ends beyond what an fmpz exponent takes:
    // arf_get_fmpz aborts on them
    if (!arf_is_finite(lo) || !arf_is_finite(hi) || arf_cmpabs_2exp_si(lo, kMaxExpBits) > 0 ||
        arf_cmpabs_2exp_si(hi, kMaxExpBits) > 0) {
      arf_clear(lo);
      arf_clear(hi);
      return unknown("exp of an argument beyond 2^(2^26)");
    }
    fmpz_t klo, khi;
    fmpz_init(klo);
    fmpz_init(khi);
    arf_get_fmpz(klo, lo, ARF_RND_FLOOR);
    arf_get_fmpz(khi, hi, ARF_RND_CEIL);
    arf_one(lo);
    arf_one(hi);
    arf_mul_2exp_fmpz(lo, lo, klo);
    arf_mul_2exp_fmpz(hi, hi, khi);
    arb_set_interval_arf(out, lo, hi, prec_);
    arf_clear(lo);
    arf_clear(hi);
    fmpz_clear(klo);
    fmpz_clear(khi);
    return finite(out);
  }

  BallStatus power(const ex& base, const ex& expo, arb_t out) {
    Tmp b;
    BallStatus sb = eval(base, b.v);
    if (GiNaC::is_a<numeric>(expo) && GiNaC::ex_to<numeric>(expo).is_rational()) {
      const numeric& q = GiNaC::ex_to<numeric>(expo);
      if (sb != BallStatus::Value) return sb;
      if (q.is_integer()) {
        if (q.is_negative() && arb_contains_zero(b.v))
          return arb_is_zero(b.v) ? pole("division by zero") : unknown("a divisor not separated from 0");
        fmpz_t k;
        fmpz_init(k);
        set_fmpz_from_cln(k, cln::the<cln::cl_I>(q.to_cl_N()));
        arb_pow_fmpz(out, b.v, k, prec_);
        fmpz_clear(k);
        return finite(out);
      }
      // x^(p/q), q > 1: principal branch; real only for x >= 0.
      if (arb_is_zero(b.v)) {
        if (q.is_positive()) {
          arb_zero(out);
          return BallStatus::Value;
        }
        return pole("a negative power of zero");
      }
      if (arb_is_negative(b.v)) return not_real(q.denom() == 2 ? "square root of a negative number"
                                                                : "fractional power of a negative number");
      if (!arb_is_nonnegative(b.v) || (q.is_negative() && arb_contains_zero(b.v)))
        return unknown("a fractional power of a number not separated from 0");
      fmpq_t f;
      fmpq_init(f);
      set_fmpz_from_cln(fmpq_numref(f), cln::the<cln::cl_I>(q.numer().to_cl_N()));
      set_fmpz_from_cln(fmpq_denref(f), cln::the<cln::cl_I>(q.denom().to_cl_N()));
      arb_pow_fmpq(out, b.v, f, prec_);
      fmpq_clear(f);
      return finite(out);
    }
    Tmp x;
    BallStatus sx = eval(expo, x.v);
    if (sb == BallStatus::NotReal || sb == BallStatus::Pole) return sb;
    if (sx == BallStatus::NotReal || sx == BallStatus::Pole) return sx;
    if (sb != BallStatus::Value || sx != BallStatus::Value) return BallStatus::Unknown;
    if (!arb_is_positive(b.v) && arb_is_exact(x.v) && arb_is_int(x.v)) {
      // an exponent that is exactly an integer here ((-1)^n at an integer n): b^k is real.
      // (A positive base keeps the exp-log path below, which also bounds huge exponents.)
      if (arf_sgn(arb_midref(x.v)) < 0 && arb_contains_zero(b.v))
        return arb_is_zero(b.v) ? pole("division by zero") : unknown("a divisor not separated from 0");
      if (arb_is_zero(b.v)) {
        if (!arb_is_positive(x.v)) return unknown("0^0");
        arb_zero(out);
        return BallStatus::Value;
      }
      fmpz_t k;
      fmpz_init(k);
      arf_get_fmpz(k, arb_midref(x.v), ARF_RND_DOWN);
      if (fmpz_bits(k) <= 64) {
        arb_pow_fmpz(out, b.v, k, prec_);
        fmpz_clear(k);
        return finite(out);
      }
      const bool odd = fmpz_is_odd(k);
      fmpz_clear(k);
      if (!arb_is_negative(b.v)) return unknown("a huge integer power of a number not separated from 0");
      // |b|^k = exp(k log|b|), the sign from the parity of k
      Tmp l;
      arb_neg(l.v, b.v);
      arb_log(l.v, l.v, prec_);
      arb_mul(l.v, l.v, x.v, prec_);
      BallStatus st = exp_of(l.v, out);
      if (odd) arb_neg(out, out);
      return st;
    }
    if (arb_is_positive(b.v)) {
      // b^x = exp(x log b), through exp_of so that huge exponents stay finite
      Tmp l;
      arb_log(l.v, b.v, prec_);
      arb_mul(l.v, l.v, x.v, prec_);
      return exp_of(l.v, out);
    }
    if (arb_is_zero(b.v) && arb_is_positive(x.v)) {
      arb_zero(out);
      return BallStatus::Value;
    }
    return unknown("a power with a base not certainly positive and a non-rational exponent");
  }

  BallStatus function(const ex& e, arb_t out) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    std::size_t n = e.nops();
    if (n == 2 && name == "atan2") {
      Tmp y, x;
      BallStatus sy = eval(e.op(0), y.v), sx = eval(e.op(1), x.v);
      if (sy == BallStatus::NotReal || sy == BallStatus::Pole) return sy;
      if (sx == BallStatus::NotReal || sx == BallStatus::Pole) return sx;
      if (sy != BallStatus::Value || sx != BallStatus::Value) return BallStatus::Unknown;
      if (arb_is_zero(x.v) && arb_is_zero(y.v)) return pole("atan2(0, 0)");
      // over a box atan2 may jump across its cut: only a positive x is continuous there
      if (box_ && !arb_is_positive(x.v)) return unknown("atan2 over a box that reaches x <= 0");
      // on the branch cut (x < 0, y = 0) only an exact y = 0 is decided
      if (!arb_is_positive(x.v) && arb_contains_zero(y.v) && !arb_is_zero(y.v))
        return unknown("atan2 near its branch cut");
      arb_atan2(out, y.v, x.v, prec_);
      return finite(out);
    }
    if (n == 2 && name == "binomial") {
      Tmp a, k;
      BallStatus sa = eval(e.op(0), a.v), sk = eval(e.op(1), k.v);
      if (sa != BallStatus::Value) return sa;
      if (sk != BallStatus::Value) return sk;
      if (!arb_is_exact(k.v) || !arb_is_int(k.v) || arb_is_negative(k.v)) return unknown("binomial with a non-integer k");
      ulong kk = static_cast<ulong>(arf_get_si(arb_midref(k.v), ARF_RND_DOWN));
      // binomial(a, k) = a (a-1) ... (a-k+1) / k!
      if (kk == 0) {
        arb_one(out);
        return BallStatus::Value;
      }
      Tmp t, f;
      arb_sub_ui(t.v, a.v, kk - 1, prec_);
      arb_hypgeom_rising_ui(out, t.v, kk, prec_);
      arb_fac_ui(f.v, kk, prec_);
      arb_div(out, out, f.v, prec_);
      return finite(out);
    }
    if (n != 1) return unknown("the function " + name + " cannot be evaluated rigorously");
    Tmp a;
    BallStatus sa = eval(e.op(0), a.v);
    if (sa != BallStatus::Value) return sa;
    arb_t& x = a.v;
    auto certified_le1 = [&](const arb_t v) {   // |v| <= 1 certainly
      Tmp t;
      arb_abs(t.v, v);
      return arb_le(t.v, one());
    };
    auto certified_gt1 = [&](const arb_t v) {   // |v| > 1 certainly
      Tmp t;
      arb_abs(t.v, v);
      return arb_gt(t.v, one());
    };
    if (name == "exp") return exp_of(x, out);
    if (name == "log") {
      if (arb_is_positive(x)) {
        arb_log(out, x, prec_);
        return finite(out);
      }
      if (arb_is_zero(x)) return pole("log(0)");
      if (arb_is_negative(x)) return not_real("log of a negative number");
      return unknown("log of a number not separated from 0");
    }
    if (name == "sin" || name == "cos" || name == "tan") {
      if (arf_cmpabs_2exp_si(arb_midref(x), kMaxExpBits) > 0) return unknown(name + " of an argument beyond 2^(2^26)");
      if (name == "sin") arb_sin(out, x, prec_);
      else if (name == "cos") arb_cos(out, x, prec_);
      else {
        Tmp c;
        arb_cos(c.v, x, prec_);
        if (arb_contains_zero(c.v)) return unknown("tan near a pole");
        arb_tan(out, x, prec_);
      }
      return finite(out);
    }
    if (name == "asin" || name == "acos") {
      if (certified_gt1(x)) return not_real(name + " of a number outside [-1, 1]");
      if (!certified_le1(x)) return unknown(name + " of a number not separated from +-1");
      if (name == "asin") arb_asin(out, x, prec_);
      else arb_acos(out, x, prec_);
      return finite(out);
    }
    if (name == "atan") {
      arb_atan(out, x, prec_);
      return finite(out);
    }
    if (name == "sinh" || name == "cosh" || name == "tanh") {
      if (arf_cmpabs_2exp_si(arb_midref(x), kMaxExpBits) > 0) return unknown(name + " of an argument beyond 2^(2^26)");
      if (name == "tanh") arb_tanh(out, x, prec_);
      else {
        // (exp(x) +- exp(-x)) / 2 through exp_of: no overflow for huge arguments
        Tmp p, m, nx;
        arb_neg(nx.v, x);
        if (exp_of(x, p.v) != BallStatus::Value || exp_of(nx.v, m.v) != BallStatus::Value)
          return unknown(name + " overflowed");
        if (name == "sinh") arb_sub(out, p.v, m.v, prec_);
        else arb_add(out, p.v, m.v, prec_);
        arb_mul_2exp_si(out, out, -1);
      }
      return finite(out);
    }
    if (name == "asinh") {
      arb_asinh(out, x, prec_);
      return finite(out);
    }
    if (name == "acosh") {
      if (arb_lt(x, one())) return not_real("acosh of a number below 1");
      if (!arb_ge(x, one())) return unknown("acosh of a number not separated from 1");
      arb_acosh(out, x, prec_);
      return finite(out);
    }
    if (name == "atanh") {
      if (certified_gt1(x)) return not_real("atanh of a number outside [-1, 1]");
      Tmp t;
      arb_abs(t.v, x);
      if (arb_is_exact(t.v) && arb_equal(t.v, one())) return pole("atanh(+-1)");
      if (!arb_lt(t.v, one())) return unknown("atanh of a number not separated from +-1");
      arb_atanh(out, x, prec_);
      return finite(out);
    }
    if (name == "abs") {
      arb_abs(out, x);
      return BallStatus::Value;
    }
    if (name == "csgn" || name == "step") {
      if (arb_is_positive(x)) arb_one(out);
      else if (arb_is_negative(x)) arb_set_si(out, name == "csgn" ? -1 : 0);
      else return unknown(name + " of a number not separated from 0");
      return BallStatus::Value;
    }
    if (name == "tgamma") {
      if (arb_is_exact(x) && arb_is_int(x) && !arb_is_positive(x)) return pole("tgamma at a non-positive integer");
      arb_gamma(out, x, prec_);
      return finite(out);
    }
    if (name == "lgamma") {
      if (!arb_is_positive(x)) return unknown("lgamma of a number not certainly positive");
      arb_lgamma(out, x, prec_);
      return finite(out);
    }
    if (name == "factorial") {
      if (!arb_is_exact(x) || !arb_is_int(x) || arb_is_negative(x)) return unknown("factorial of a non-integer");
      Tmp t;
      arb_add_ui(t.v, x, 1, prec_);
      arb_gamma(out, t.v, prec_);
      return finite(out);
    }
    if (name == "zeta") {
      if (arb_is_exact(x) && arb_equal(x, one())) return pole("zeta(1)");
      arb_zeta(out, x, prec_);
      return finite(out);
    }
    return unknown("the function " + name + " cannot be evaluated rigorously");
  }

  const arb_t& one() {
    if (!one_init_) {
      arb_one(one_.v);
      one_init_ = true;
    }
    return one_.v;
  }
  Tmp one_;
  bool one_init_ = false;
};

long digits_to_bits(long digits) { return static_cast<long>(digits * 3.3219280948873623) + 16; }
long bits_to_digits(long bits) { return static_cast<long>(bits / 3.3219280948873623); }

}  // namespace

Ball enclose(const ex& constant, long prec_bits) { return enclose_at(constant, nullptr, prec_bits); }

namespace {

// e at a point, over a box of intervals, or (both null) as a constant.
Ball enclose_with(const ex& e, const GiNaC::exmap* point, const Box* box, long prec_bits) {
  Ball b;
  b.prec_bits = prec_bits;
  BallEvaluator ev(prec_bits, point, box);
  try {
    b.status = ev.eval(e, b.impl->v);
  } catch (const std::exception&) {
    b.status = BallStatus::Unknown;
    ev.why = "evaluation failed";
  }
  b.why = ev.why;
  return b;
}

}  // namespace

Ball enclose_at(const ex& e, const GiNaC::exmap* point, long prec_bits) { return enclose_with(e, point, nullptr, prec_bits); }

Ball enclose_box(const ex& e, const Box& box, long prec_bits) { return enclose_with(e, nullptr, &box, prec_bits); }

bool certainly_nonnegative(const Ball& b) { return b.status == BallStatus::Value && arb_is_nonnegative(b.impl->v); }

Ball enclose_sign(const ex& constant, long start_bits, long max_bits) {
  return enclose_sign_at(constant, nullptr, start_bits, max_bits);
}

bool sign_decided(const Ball& b) {
  return b.status == BallStatus::NotReal || b.status == BallStatus::Pole ||
         (b.status == BallStatus::Value &&
          (arb_is_positive(b.impl->v) || arb_is_negative(b.impl->v) || arb_is_zero(b.impl->v)));
}

Ball enclose_sign_at(const ex& constant, const GiNaC::exmap* point, long start_bits, long max_bits) {
  for (long p = std::max(32L, start_bits);; p *= 4) {
    Ball b = enclose_at(constant, point, std::min(p, max_bits));
    if (sign_decided(b) || p >= max_bits) return b;
  }
}

const std::string& PointComparison::lhs_text() const {
  if (!lhs_text_) lhs_text_ = lhs_ball ? lhs_ball->text(sig) : std::string();
  return *lhs_text_;
}

const std::string& PointComparison::rhs_text() const {
  if (!rhs_text_) rhs_text_ = rhs_ball ? rhs_ball->text(sig) : std::string();
  return *rhs_text_;
}

PointComparison compare_balls(Ball&& lhs, Ball&& rhs, long tol_exponent, int sig) {
  using K = PointComparison::Kind;
  PointComparison out;
  out.sig = sig;
  out.lhs_ball = std::make_shared<const Ball>(std::move(lhs));
  out.rhs_ball = std::make_shared<const Ball>(std::move(rhs));
  const Ball& l = *out.lhs_ball;
  const Ball& r = *out.rhs_ball;
  const long prec = std::max(l.prec_bits, r.prec_bits) + 16;
  auto certified_undefined = [](const Ball& b) {
    return b.status == BallStatus::NotReal || b.status == BallStatus::Pole;
  };
  if (certified_undefined(l) && certified_undefined(r)) {
    bool pole = l.status == BallStatus::Pole || r.status == BallStatus::Pole;
    out.kind = pole && !(l.status == BallStatus::NotReal || r.status == BallStatus::NotReal) ? K::IsolatedPole
                                                                                            : K::NeitherReal;
    out.why = "lhs " + l.text() + ", rhs " + r.text();
    return out;
  }
  if (l.status == BallStatus::Pole || r.status == BallStatus::Pole) {
    out.kind = K::IsolatedPole;
    out.why = (l.status == BallStatus::Pole ? "lhs " + l.text() : "rhs " + r.text());
    return out;
  }
  if (l.status == BallStatus::Value && r.status == BallStatus::NotReal) {
    out.kind = K::LhsOnly;
    return out;
  }
  if (r.status == BallStatus::Value && l.status == BallStatus::NotReal) {
    out.kind = K::RhsOnly;
    return out;
  }
  if (l.status == BallStatus::Value && r.status == BallStatus::Value) {
    arb_t d;
    arb_init(d);
    arb_sub(d, l.impl->v, r.impl->v, prec);
    bool differ = !arb_contains_zero(d);
    // Agree: upper bound of |d| <= 10^tol * max(lower bounds of |l|, |r|, 1e-300)
    arf_t dub, slb, t;
    arf_init(dub);
    arf_init(slb);
    arf_init(t);
    arb_get_abs_ubound_arf(dub, d, prec);
    arb_get_abs_lbound_arf(slb, l.impl->v, prec);
    arb_get_abs_lbound_arf(t, r.impl->v, prec);
    if (arf_cmp(t, slb) > 0) arf_set(slb, t);
    arb_t floor_, tol, bound;
    arb_init(floor_);
    arb_init(tol);
    arb_init(bound);
    arb_set_ui(floor_, 10);
    arb_pow_ui(floor_, floor_, 300, 64);
    arb_inv(floor_, floor_, 64);
    arb_get_lbound_arf(t, floor_, 64);
    bool floored = arf_cmp(t, slb) > 0;   // both sides below 1e-300: the absolute floor applies
    if (floored) arf_set(slb, t);
    arb_set_ui(tol, 10);
    arb_pow_ui(tol, tol, static_cast<ulong>(-tol_exponent), 64);
    arb_set_arf(bound, slb);
    arb_div(bound, bound, tol, 64);
    arb_get_lbound_arf(t, bound, 64);
    bool agree = !differ && arf_cmp(dub, t) <= 0;
    // Agreement through the absolute floor counts only when the difference is of the size
    // rounding leaves at this precision: exp(-10^300*x) against 0 gives a ball as small as the
    // value itself, far below rounding, which must be resolved at a higher precision.
    if (agree && floored && !arf_is_zero(dub) && arf_cmpabs_2exp_si(dub, -8 * prec) < 0) agree = false;
    // relative difference (estimate for Differ, bound for Agree)
    if (arf_is_zero(slb)) out.rel_diff = 0;
    else {
      arf_div(t, agree ? dub : arb_midref(d), slb, 64, ARF_RND_UP);
      out.rel_diff = std::abs(arf_get_d(t, ARF_RND_UP));
    }
    arb_clear(floor_);
    arb_clear(tol);
    arb_clear(bound);
    arf_clear(dub);
    arf_clear(slb);
    arf_clear(t);
    arb_clear(d);
    if (differ) {
      out.kind = K::Differ;
      // enough digits to show the difference
      out.lhs_text_ = l.text(sig);
      out.rhs_text_ = r.text(sig);
      for (int s = sig + 10; s <= 200 && *out.lhs_text_ == *out.rhs_text_; s += 10) {
        out.lhs_text_ = l.text(s);
        out.rhs_text_ = r.text(s);
      }
      return out;
    }
    if (agree) {
      out.kind = K::Agree;
      return out;
    }
  }
  out.kind = K::Unknown;
  out.why = l.status != BallStatus::Value ? "lhs: " + l.why
            : r.status != BallStatus::Value ? "rhs: " + r.why
                                            : "the difference is not resolved";
  return out;
}

PointComparison compare_constants(const ex& lhs, const ex& rhs, const CompareOptions& opt) {
  return compare_at(lhs, rhs, nullptr, opt);
}

PointComparison compare_at(const ex& lhs, const ex& rhs, const GiNaC::exmap* point, const CompareOptions& opt) {
  using K = PointComparison::Kind;
  PointComparison out;
  for (long digits = std::max(opt.start_digits, -opt.tol_exponent + 15);; digits *= 4) {
    long prec = std::min(digits_to_bits(digits), opt.max_bits);
    out = compare_balls(enclose_at(lhs, point, prec), enclose_at(rhs, point, prec), opt.tol_exponent, opt.sig);
    const Ball& l = *out.lhs_ball;
    const Ball& r = *out.rhs_ball;
    out.digits = prec < opt.max_bits ? digits : bits_to_digits(prec);
    if (out.kind != K::Unknown) return out;
    if (prec >= opt.max_bits) {
      out.kind = K::Unknown;
      std::string w = l.status != BallStatus::Value ? "lhs: " + l.why
                      : r.status != BallStatus::Value ? "rhs: " + r.why
                                                      : "the difference is not resolved";
      out.why = w + " at the precision cap (" + std::to_string(bits_to_digits(opt.max_bits)) + " digits)";
      return out;
    }
  }
}

}  // namespace dc::kernel
