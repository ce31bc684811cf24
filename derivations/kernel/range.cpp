// Range analysis (range.hpp).
#include "derivations/kernel/range.hpp"

#include <algorithm>
#include <climits>
#include <set>

#include <cln/rational.h>
#include <cln/real.h>

#include "derivations/kernel/sign.hpp"
#include "derivations/symbolic/inspect.hpp"
#include "derivations/symbolic/printer.hpp"
#include "derivations/symbolic/verdict.hpp"

namespace dc::detail {

using GiNaC::ex;
using GiNaC::numeric;


bool Range::positive() const { return !lo_inf && (lo.is_positive() || (lo.is_zero() && lo_open)); }
bool Range::negative() const { return !hi_inf && (hi.is_negative() || (hi.is_zero() && hi_open)); }
bool Range::nonnegative() const { return !lo_inf && !lo.is_negative(); }
bool Range::within(const numeric& a, const numeric& b) const {
  return !lo_inf && !hi_inf && lo >= a && hi <= b;
}
std::string Range::to_string() const {
  std::string s = lo_inf ? "(-oo" : std::string(lo_open ? "(" : "[") + exact_text(lo);
  s += ", ";
  s += hi_inf ? "oo)" : exact_text(hi) + (hi_open ? ")" : "]");
  return s;
}

namespace {

Range point_range(const numeric& q) {
  Range r;
  r.lo_inf = r.hi_inf = false;
  r.lo = r.hi = q;
  r.lo_open = r.hi_open = false;
  return r;
}

Range make_range(bool lo_inf, numeric lo, bool lo_open, bool hi_inf, numeric hi, bool hi_open) {
  Range r;
  r.lo_inf = lo_inf;
  r.hi_inf = hi_inf;
  r.lo = lo;
  r.hi = hi;
  r.lo_open = lo_open;
  r.hi_open = hi_open;
  return r;
}

// Outward rational enclosure of a real constant (pi, pi/2, exp(1), ...).
Range constant_range(const ex& c) {
  DigitsGuard g(40);
  ex v = c.evalf();
  if (!GiNaC::is_a<numeric>(v) || !GiNaC::ex_to<numeric>(v).is_real()) return Range::all();
  numeric f = GiNaC::ex_to<numeric>(v);
  cln::cl_R cr = cln::the<cln::cl_R>(f.to_cl_N());
  numeric q = numeric(cln::cl_N(cln::rational(cr)));
  numeric pad = GiNaC::abs(q) * pow10(-30) + pow10(-60);
  return make_range(false, q - pad, false, false, q + pad, false);
}

Range bound_range_of_domain(const Domain& d) {
  using K = Domain::Kind;
  switch (d.kind) {
    case K::Real: return Range::all();
    case K::Positive: return make_range(false, 0, true, true, 0, true);
    case K::Nonnegative: return make_range(false, 0, false, true, 0, true);
    case K::Negative: return make_range(true, 0, true, false, 0, true);
    case K::Interval: {
      Range lo = GiNaC::is_a<numeric>(d.lo) ? point_range(GiNaC::ex_to<numeric>(d.lo)) : constant_range(d.lo);
      Range hi = GiNaC::is_a<numeric>(d.hi) ? point_range(GiNaC::ex_to<numeric>(d.hi)) : constant_range(d.hi);
      if (lo.lo_inf || hi.hi_inf) return Range::all();
      return make_range(false, lo.lo, d.lo_open, false, hi.hi, d.hi_open);
    }
  }
  return Range::all();
}

Range neg_range(const Range& a) {
  return make_range(a.hi_inf, -a.hi, a.hi_open, a.lo_inf, -a.lo, a.lo_open);
}

Range add_range(const Range& a, const Range& b) {
  Range r;
  r.lo_inf = a.lo_inf || b.lo_inf;
  r.hi_inf = a.hi_inf || b.hi_inf;
  if (!r.lo_inf) {
    r.lo = a.lo + b.lo;
    r.lo_open = a.lo_open || b.lo_open;
  }
  if (!r.hi_inf) {
    r.hi = a.hi + b.hi;
    r.hi_open = a.hi_open || b.hi_open;
  }
  return r;
}

bool is_point(const Range& a) { return !a.lo_inf && !a.hi_inf && a.lo == a.hi && !a.lo_open && !a.hi_open; }

// product of two ranges that are both >= 0
Range mul_nonneg(const Range& a, const Range& b) {
  Range r;
  r.lo_inf = false;
  r.lo = a.lo * b.lo;
  r.lo_open = (a.lo_open && b.lo_open) || (a.lo_open && !b.lo.is_zero()) || (b.lo_open && !a.lo.is_zero());
  r.hi_inf = a.hi_inf || b.hi_inf;
  if (!r.hi_inf) {
    r.hi = a.hi * b.hi;
    r.hi_open = (a.hi_open && b.hi_open) || (a.hi_open && !b.hi.is_zero()) || (b.hi_open && !a.hi.is_zero());
  }
  return r;
}

Range mul_range(const Range& a, const Range& b) {
  if (is_point(a) && a.lo.is_zero()) return a;
  if (is_point(b) && b.lo.is_zero()) return b;
  bool a_nn = !a.lo_inf && !a.lo.is_negative(), b_nn = !b.lo_inf && !b.lo.is_negative();
  bool a_np = !a.hi_inf && !a.hi.is_positive(), b_np = !b.hi_inf && !b.hi.is_positive();
  if (a_nn && b_nn) return mul_nonneg(a, b);
  if (a_np && b_nn) return neg_range(mul_nonneg(neg_range(a), b));
  if (a_nn && b_np) return neg_range(mul_nonneg(a, neg_range(b)));
  if (a_np && b_np) return mul_nonneg(neg_range(a), neg_range(b));
  if (a.lo_inf || a.hi_inf || b.lo_inf || b.hi_inf) return Range::all();
  numeric c[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  numeric mn = c[0], mx = c[0];
  for (auto& v : c) {
    if (v < mn) mn = v;
    if (v > mx) mx = v;
  }
  return make_range(false, mn, false, false, mx, false);
}

Range int_power_range(const Range& b, long n) {
  if (n == 0) return point_range(1);
  if (n < 0) {
    Range p = int_power_range(b, -n);
    bool neg = false;
    Range q = p;
    if (p.negative()) {
      q = neg_range(p);
      neg = true;
    } else if (!p.positive()) {
      return Range::all();
    }
    // q > 0: 1/q in [1/hi, 1/lo]
    Range r;
    r.lo_inf = false;
    if (q.hi_inf) {
      r.lo = 0;
      r.lo_open = true;
    } else {
      r.lo = 1 / q.hi;
      r.lo_open = q.hi_open;
    }
    if (q.lo.is_zero()) {
      r.hi_inf = true;
    } else {
      r.hi_inf = false;
      r.hi = 1 / q.lo;
      r.hi_open = q.lo_open;
    }
    return neg ? neg_range(r) : r;
  }
  if (n > 64) {
    // sign only: avoid huge bounds
    if (n % 2 == 0) return make_range(false, 0, b.nonzero(), true, 0, true);
    if (b.positive()) return make_range(false, 0, true, true, 0, true);
    if (b.negative()) return make_range(true, 0, true, false, 0, true);
    return Range::all();
  }
  numeric nn(n);
  auto p = [&](const numeric& x) { return GiNaC::pow(x, nn); };
  bool odd = n % 2 == 1;
  if (odd || b.nonnegative()) {
    return make_range(b.lo_inf, b.lo_inf ? 0 : p(b.lo), b.lo_open, b.hi_inf, b.hi_inf ? 0 : p(b.hi),
                      b.hi_open);
  }
  if (!b.hi_inf && !b.hi.is_positive()) {  // b <= 0, even power
    return make_range(false, p(b.hi), b.hi_open, b.lo_inf, b.lo_inf ? 0 : p(b.lo), b.lo_open);
  }
  // mixed sign, even power
  if (b.lo_inf || b.hi_inf) return make_range(false, 0, false, true, 0, true);
  numeric a = p(b.lo), c = p(b.hi);
  return make_range(false, 0, false, false, a > c ? a : c, false);
}

Range range_rec(const ex& e, const SymbolTable& ctx);

// range_where_defined is running: ranges hold where the expression is real (a fractional
// power's base need not be nonnegative everywhere).
thread_local bool g_where_defined = false;

Range function_range(const GiNaC::function& f, const SymbolTable& ctx) {
  const std::string name = f.get_name();
  auto rat = [](long p, long q) { return numeric(p, q); };
  if (name == "exp") return make_range(false, 0, true, true, 0, true);
  if (name == "sin" || name == "cos") {
    // sin > 0 on (0, pi) and cos > 0 on (-pi/2, pi/2): the bounds below are rationals just
    // inside pi and pi/2, so the test is exact and errs on the side of "not evident".
    Range a = range_rec(f.op(0), ctx);
    // Bounds like pi/2 arrive as padded 40-digit enclosures: a bound within 1e-28 of pi/2 counts
    // as pi/2 itself, and then it must be open.
    numeric half_pi;
    {
      DigitsGuard g(40);
      half_pi = GiNaC::ex_to<numeric>((GiNaC::Pi / 2).evalf());
    }
    const numeric eps = pow10(-28);  // wider than constant_range's outward padding (~1e-30 relative)
    auto below = [&](const numeric& x, bool open, const numeric& bound) {
      return x < bound - eps || (GiNaC::abs(x - bound) <= eps && open);
    };
    auto above = [&](const numeric& x, bool open, const numeric& bound) {
      return x > bound + eps || (GiNaC::abs(x - bound) <= eps && open);
    };
    bool pos = false;
    if (!a.lo_inf && !a.hi_inf) {
      if (name == "sin") pos = above(a.lo, a.lo_open, 0) && below(a.hi, a.hi_open, 2 * half_pi);
      else pos = above(a.lo, a.lo_open, -half_pi) && below(a.hi, a.hi_open, half_pi);
    }
    if (pos) return make_range(false, 0, true, false, 1, false);
    return make_range(false, -1, false, false, 1, false);
  }
  if (name == "tan") {
    // increasing on (-pi/2, pi/2): an argument range inside it gives (tan(lo), tan(hi)), the
    // ends enclosed outward (an exact 0 stays exact); an end at +-pi/2 (open) gives +-oo
    Range a = range_rec(f.op(0), ctx);
    if (a.lo_inf || a.hi_inf) return Range::all();
    numeric half_pi;
    {
      DigitsGuard g(40);
      half_pi = GiNaC::ex_to<numeric>((GiNaC::Pi / 2).evalf());
    }
    const numeric eps = pow10(-28);
    const bool lo_at_pole = GiNaC::abs(a.lo + half_pi) <= eps, hi_at_pole = GiNaC::abs(a.hi - half_pi) <= eps;
    if ((lo_at_pole && !a.lo_open) || (hi_at_pole && !a.hi_open)) return Range::all();
    if (!lo_at_pole && a.lo < -half_pi) return Range::all();
    if (!hi_at_pole && a.hi > half_pi) return Range::all();
    Range r;
    r.lo_inf = lo_at_pole;
    r.hi_inf = hi_at_pole;
    if (!r.lo_inf) {
      const Range c = a.lo.is_zero() ? point_range(0) : constant_range(GiNaC::tan(ex(a.lo)));
      if (c.lo_inf) return Range::all();
      r.lo = c.lo, r.lo_open = a.lo.is_zero() && a.lo_open;
    }
    if (!r.hi_inf) {
      const Range c = a.hi.is_zero() ? point_range(0) : constant_range(GiNaC::tan(ex(a.hi)));
      if (c.hi_inf) return Range::all();
      r.hi = c.hi, r.hi_open = a.hi.is_zero() && a.hi_open;
    }
    return r;
  }
  if (name == "tanh") return make_range(false, -1, false, false, 1, false);
  if (name == "atan") return make_range(false, rat(-15708, 10000), true, false, rat(15708, 10000), true);
  if (name == "asin") return make_range(false, rat(-15708, 10000), false, false, rat(15708, 10000), false);
  if (name == "acos") return make_range(false, 0, false, false, rat(31416, 10000), false);
  if (name == "cosh") return make_range(false, 1, false, true, 0, true);
  if (name == "abs") {
    Range a = range_rec(f.op(0), ctx);
    return make_range(false, 0, a.nonzero(), true, 0, true);
  }
  if (name == "log") {
    Range a = range_rec(f.op(0), ctx);
    if (!a.lo_inf && a.lo >= 1) return make_range(false, 0, a.lo == 1 && a.lo_open ? true : a.lo > 1, true, 0, true);
    if (a.positive() && !a.hi_inf && a.hi <= 1)
      return make_range(true, 0, true, false, 0, a.hi < 1 || a.hi_open);
    return Range::all();
  }
  return Range::all();
}

Range range_rec(const ex& e, const SymbolTable& ctx) {
  if (GiNaC::is_a<numeric>(e)) {
    const numeric& n = GiNaC::ex_to<numeric>(e);
    if (n.is_rational()) return point_range(n);
    if (n.is_real()) return constant_range(e);
    return Range::all();
  }
  if (GiNaC::is_a<GiNaC::symbol>(e)) return bound_range_of_domain(domain_of(e, ctx));
  if (GiNaC::is_a<GiNaC::constant>(e)) return constant_range(e);
  if (GiNaC::is_a<GiNaC::add>(e)) {
    Range r = point_range(0);
    for (std::size_t i = 0; i < e.nops(); ++i) {
      r = add_range(r, range_rec(e.op(i), ctx));
      if (r.lo_inf && r.hi_inf) return r;
    }
    return r;
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    Range r = point_range(1);
    for (std::size_t i = 0; i < e.nops(); ++i) r = mul_range(r, range_rec(e.op(i), ctx));
    return r;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    Range b = range_rec(e.op(0), ctx);
    const ex& x = e.op(1);
    if (GiNaC::is_a<numeric>(x)) {
      const numeric& n = GiNaC::ex_to<numeric>(x);
      if (n.is_integer()) {
        if (GiNaC::abs(n) > 100000) return Range::all();
        return int_power_range(b, n.to_long());
      }
      if (n.is_rational()) {
        bool pos = n.is_positive();
        // where it is defined, a real fractional power is >= 0 (> 0 with a negative exponent)
        if (g_where_defined && !b.nonnegative())
          return make_range(false, 0, !pos, true, 0, true);
        if (pos && !b.lo_inf && !b.lo.is_negative() && !b.hi_inf && b.hi <= 1)
          return make_range(false, 0, b.positive(), false, 1, b.hi_open);
        if (b.positive()) return make_range(false, 0, true, true, 0, true);
        if (pos && b.nonnegative()) return make_range(false, 0, false, true, 0, true);
        return Range::all();
      }
    }
    if (b.positive() && provably_real(x, ctx)) return make_range(false, 0, true, true, 0, true);
    return Range::all();
  }
  if (GiNaC::is_a<GiNaC::function>(e) && !is_abstract_application(e))
    return function_range(GiNaC::ex_to<GiNaC::function>(e), ctx);
  return Range::all();
}

}  // namespace

Range range_of(const ex& e, const SymbolTable& ctx) {
  try {
    return range_rec(e, ctx);
  } catch (const std::exception&) {
    return Range::all();
  }
}

Range range_where_defined(const ex& e, const SymbolTable& ctx) {
  struct Flag {
    bool saved = g_where_defined;
    Flag() { g_where_defined = true; }
    ~Flag() { g_where_defined = saved; }
  } flag;
  return range_of(e, ctx);
}

bool provably_positive(const ex& e, const SymbolTable& ctx) {
  if (range_of(e, ctx).positive()) return true;
  if (e.info(GiNaC::info_flags::positive)) return true;
  return kernel::decide_sign_by_sturm(e, kernel::SignWant::Positive, ctx).has_value();
}

bool provably_nonzero(const ex& e, const SymbolTable& ctx) {
  if (GiNaC::is_a<numeric>(e)) return !GiNaC::ex_to<numeric>(e).is_zero();
  if (range_of(e, ctx).nonzero()) return true;
  if (e.info(GiNaC::info_flags::positive) || e.info(GiNaC::info_flags::negative)) return true;
  return kernel::decide_sign_by_sturm(e, kernel::SignWant::Nonzero, ctx).has_value();
}

bool provably_real(const ex& e, const SymbolTable& ctx) {
  if (GiNaC::is_a<numeric>(e)) return GiNaC::ex_to<numeric>(e).is_real();
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    if (ctx.find(GiNaC::ex_to<GiNaC::symbol>(e))) return true;  // table symbols are real
    return e.info(GiNaC::info_flags::real);
  }
  if (GiNaC::is_a<GiNaC::constant>(e)) return e.info(GiNaC::info_flags::real);
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!provably_real(e.op(i), ctx)) return false;
    return true;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    if (!provably_real(e.op(0), ctx) || !provably_real(e.op(1), ctx)) return false;
    if (e.op(1).info(GiNaC::info_flags::integer)) return true;
    return range_of(e.op(0), ctx).nonnegative();
  }
  if (GiNaC::is_a<GiNaC::function>(e) && !is_abstract_application(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!provably_real(e.op(i), ctx)) return false;
    static const std::set<std::string> total = {"sin", "cos", "exp", "atan", "sinh", "cosh",
                                                "tanh", "abs", "asinh", "atan2"};
    if (total.count(name)) return true;
    if (name == "log") return provably_positive(e.op(0), ctx);
    if (name == "acos" || name == "asin") return range_of(e.op(0), ctx).within(-1, 1);
    return false;
  }
  return false;
}

}  // namespace dc::detail
