// value_in_domain (in_domain.hpp).
#include "derivations/rules/in_domain.hpp"

#include "derivations/symbolic/printer.hpp"
#include "derivations/kernel/range.hpp"
#include "derivations/kernel/sign.hpp"
#include "derivations/steps/context.hpp"
#include "derivations/decide/integer.hpp"

namespace dc::rules {

namespace {

using GiNaC::ex;

// The claimed root g of an unknown declared `in (lo, hi)` (ends open or closed) must lie in that
// interval for every admissible parameter value: a constant g is compared exactly (or at 50
// digits when its difference from an end is not exactly zero); otherwise lo <= g and g <= hi are
// decided as sqrt((g - lo)^2) = g - lo and sqrt((hi - g)^2) = hi - g by the prover, whose probe
// refutes at a point where g leaves the interval.
Verdict in_interval(const ex& g, const Domain& dom, const SymbolTable& t, const ProveOptions& opt) {
  Combiner all;
  auto end = [&](const ex& gap, bool open, const std::string& what) {   // gap >= 0 (> 0 if open)
    const ex v = gap.evalf();
    if (GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real()) {
      const bool zero = gap.normal().is_zero();
      const bool inside = zero ? !open : GiNaC::ex_to<GiNaC::numeric>(v) > 0;
      Verdict r = inside ? proved("root in the declared domain", what)
                         : Verdict{};
      if (!inside) {
        r.kind = VerdictKind::Refuted;
        r.method = "root in the declared domain";
        r.detail = "the claimed root " + print_text(g, t) + " is not " + what;
      }
      all.add(r, what);
      return;
    }
    if (open ? detail::provably_positive(gap, t) : detail::range_of(gap, t).nonnegative()) {
      all.add(proved("root in the declared domain", what + " (range of the root)"), what);
      return;
    }
    Verdict r = prove_equal(GiNaC::sqrt(GiNaC::pow(gap, 2)), gap, t, opt);
    r.method = prefix_method("root in the declared domain", r.method);
    all.add(r, what);
  };
  // asin(u), acos(u), atan(u): their exact ranges, and asin/atan have the sign of u
  if (GiNaC::is_a<GiNaC::function>(g)) {
    const std::string f = GiNaC::ex_to<GiNaC::function>(g).get_name();
    const ex half = GiNaC::Pi / 2;
    ex lo, hi;
    bool strict = f == "atan";
    if (f == "asin" || f == "atan") lo = -half, hi = half;
    else if (f == "acos") lo = 0, hi = GiNaC::Pi;
    if (!lo.is_zero() || f == "acos") {
      const ex u = g.op(0);
      auto at_least = [&](const ex& a, const ex& b) {   // a >= b for constants
        const ex v = (a - b).evalf();
        return (a - b).normal().is_zero() ||
               (GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real() &&
                GiNaC::ex_to<GiNaC::numeric>(v) > 0);
      };
      auto numeric_end = [](const ex& e) { return GiNaC::is_a<GiNaC::numeric>(e.evalf()); };
      // lower end: below the range's lower bound, or 0 with u >= 0 (u > 0 for an open end)
      // an open end equal to the range's bound: u must stay off the argument that reaches it
      const ex u_at_lo = f == "acos" ? ex(1) : ex(-1), u_at_hi = f == "acos" ? ex(-1) : ex(1);
      auto off = [&](const ex& bound) {   // u < 1 (bound 1) or u > -1 (bound -1)
        return detail::provably_positive(bound.is_equal(1) ? 1 - u : u + 1, t);
      };
      auto end_ok = [&](const ex& range_end, const ex& dom_end, bool open, const ex& u_end, bool lower) {
        if (!(lower ? at_least(range_end, dom_end) : at_least(dom_end, range_end))) return false;
        if (!(range_end - dom_end).normal().is_zero() || !open || strict) return true;
        return off(u_end);
      };
      bool lo_ok = numeric_end(dom.lo) &&
                   (end_ok(lo, dom.lo, dom.lo_open, u_at_lo, true) ||
                    (dom.lo.is_zero() && f != "acos" &&
                     (dom.lo_open ? detail::provably_positive(u, t) : detail::range_of(u, t).nonnegative())));
      bool hi_ok = numeric_end(dom.hi) &&
                   (end_ok(hi, dom.hi, dom.hi_open, u_at_hi, false) ||
                    (dom.hi.is_zero() && f != "acos" &&
                     (dom.hi_open ? detail::provably_positive(-u, t) : detail::range_of(-u, t).nonnegative())));
      if (lo_ok && hi_ok)
        return proved("root in the declared domain", "the range of " + f + " lies in " + dom.to_string());
    }
  }
  end(g - dom.lo, dom.lo_open, std::string(dom.lo_open ? "> " : ">= ") + print_text(dom.lo, t));
  end(dom.hi - g, dom.hi_open, std::string(dom.hi_open ? "< " : "<= ") + print_text(dom.hi, t));
  return all.result();
}

// g > 0 (strict) or g >= 0 for every admissible parameter value.
Verdict sign_holds(const ex& g, bool strict, const std::string& what, const SymbolTable& t, const ProveOptions& opt) {
  const ex v = g.evalf();
  if (GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real()) {
    const bool zero = g.normal().is_zero();
    if (zero ? !strict : GiNaC::ex_to<GiNaC::numeric>(v) > 0) return proved("value in the declared domain", what);
    Verdict r;
    r.kind = VerdictKind::Refuted;
    r.method = "value in the declared domain";
    r.detail = print_text(g, t) + " is not " + what;
    return r;
  }
  if (strict ? detail::provably_positive(g, t) : detail::range_of(g, t).nonnegative())
    return proved("value in the declared domain", what + " (signs of the declarations)");
  if (auto how = kernel::decide_sign(g, strict ? kernel::SignWant::Positive : kernel::SignWant::Nonnegative, t))
    return proved("value in the declared domain", what + " (" + *how + ")");
  Verdict r = prove_equal(GiNaC::sqrt(GiNaC::pow(g, 2)), g, t, opt);
  r.method = prefix_method("value in the declared domain", r.method);
  return r;
}

}  // namespace

Verdict value_in_domain(const ex& g, const Domain& dom, const SymbolTable& t, const ProveOptions& opt) {
  if (dom.integer) {
    // the sign or interval first, then integer values: proved for an integer-valued form
    // (integer symbols combined by +, -, *), refuted for a constant that is no integer
    Domain plain = dom;
    plain.integer = false;
    Verdict v = value_in_domain(g, plain, t, opt);
    if (!v.holds()) return v;
    if (integer_valued(g, t)) return v;
    Verdict r;
    r.method = "value in the declared domain";
    if (GiNaC::is_a<GiNaC::numeric>(g) && GiNaC::ex_to<GiNaC::numeric>(g).is_rational()) {
      r.kind = VerdictKind::Refuted;
      r.detail = "the value " + print_text(g, t) + " is not an integer (declared " + dom.to_string() + ")";
      return r;
    }
    r.kind = VerdictKind::Undecided;
    r.reason = "whether " + print_text(g, t) + " is an integer (declared " + dom.to_string() +
               ") is not decided: only integer symbols combined by +, - and * are known to be integers";
    r.detail = r.reason;
    return r;
  }
  switch (dom.kind) {
    case Domain::Kind::Real: return proved("value in the declared domain", "real");
    case Domain::Kind::Positive: return sign_holds(g, true, "positive", t, opt);
    case Domain::Kind::Nonnegative: return sign_holds(g, false, "nonnegative", t, opt);
    case Domain::Kind::Negative: return sign_holds(-g, true, "negative", t, opt);
    case Domain::Kind::Interval: return in_interval(g, dom, t, opt);
  }
  return proved("value in the declared domain", "");
}

}  // namespace dc::rules
