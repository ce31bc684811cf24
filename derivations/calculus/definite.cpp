// Definite and improper integrals by an antiderivative (see definite.hpp).
#include "derivations/calculus/definite.hpp"

#include <optional>
#include <vector>

#include "derivations/calculus/limit_entry.hpp"
#include "derivations/symbolic/printer.hpp"
#include "derivations/decide/prove.hpp"
#include "derivations/kernel/range.hpp"
#include "derivations/kernel/sign.hpp"
#include "derivations/calculus/antiderivative.hpp"

namespace dc::integrals {
namespace {

using namespace GiNaC;

// An end of the interval: a finite value or an infinity.
struct End {
  ex at;
  int inf = 0;   // -1: -oo, +1: +oo
  bool closed = false;   // the end itself belongs to the interval examined
};

// ---- Sturm's theorem for polynomials in x with rational coefficients -------------------------

bool rational_univariate(const ex& p, const symbol& x) {
  if (!p.is_polynomial(x)) return false;
  const ex e = p.expand();
  for (int i = e.ldegree(x); i <= e.degree(x); ++i) {
    const ex c = e.coeff(x, i);
    if (!is_a<numeric>(c) || !ex_to<numeric>(c).is_rational()) return false;
  }
  return true;
}

bool rational_end(const End& e) { return e.inf != 0 || (is_a<numeric>(e.at) && ex_to<numeric>(e.at).is_rational()); }

int sign_at(const ex& s, const symbol& x, const End& t) {
  if (t.inf == 0) {
    const numeric v = ex_to<numeric>(s.subs(x == t.at));
    return v.is_zero() ? 0 : v > 0 ? 1 : -1;
  }
  const ex e = s.expand();
  const int d = e.degree(x);
  const numeric lc = ex_to<numeric>(e.coeff(x, d));
  int sg = lc > 0 ? 1 : -1;
  if (t.inf < 0 && d % 2 == 1) sg = -sg;
  return sg;
}

// Does p have a real root in the open interval (lo, hi)? p with rational coefficients, ends
// rational or infinite (Sturm's theorem, kernel/sign.hpp).
bool root_inside(const ex& p, const symbol& x, const End& lo, const End& hi) {
  return kernel::sturm_root_inside(p, x, lo.inf ? numeric(0) : ex_to<numeric>(lo.at), lo.inf < 0,
                                   hi.inf ? numeric(0) : ex_to<numeric>(hi.at), hi.inf > 0);
}

End interior_point(const End& lo, const End& hi) {
  if (lo.inf == 0 && hi.inf == 0) return {(lo.at + hi.at) / 2};
  if (lo.inf == 0) return {lo.at + 1};
  if (hi.inf == 0) return {hi.at - 1};
  return {0};
}

// ---- conditions for continuity on (a, b) -------------------------------------------------------

struct Condition {
  ex e;
  bool positive;   // e > 0 (else e != 0)
};

// The conditions under which e is defined and continuous; false when e has a part whose
// continuity is not known (an abstract function of x, an unknown function).
bool collect(const ex& e, const symbol& x, std::vector<Condition>& out) {
  for (const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    const ex& s = *it;
    if (is_a<power>(s)) {
      const ex& n = s.op(1);
      if (is_a<numeric>(n) && ex_to<numeric>(n).is_integer()) {
        if (ex_to<numeric>(n) < 0) out.push_back({s.op(0), false});
      } else if (s.op(0).has(x) || n.has(x) || (is_a<numeric>(n) && ex_to<numeric>(n) < 0)) {
        // (free of x too when it divides: a/sqrt(a^2) needs a != 0 -- the antiderivative
        // atan(x/sqrt(a^2)) of a/(a^2 + x^2) is no antiderivative at a = 0)
        if (!s.op(0).is_equal(exp(1))) out.push_back({s.op(0), true});
      }
    } else if (is_a<function>(s)) {
      const std::string name = ex_to<function>(s).get_name();
      if (name == "log") out.push_back({s.op(0), true});
      else if (name == "tan") out.push_back({cos(s.op(0)), false});
      else if (name == "asin" || name == "acos") out.push_back({1 - pow(s.op(0), 2), true});
      else if (name != "exp" && name != "sin" && name != "cos" && name != "atan" && name != "sinh" &&
               name != "cosh" && name != "tanh" && name != "abs" && s.has(x))
        return false;
    }
  }
  return true;
}

// x's entry in t, declared real there when t does not know it (a bound variable).
const SymbolInfo* declared_in(SymbolTable& t, const symbol& x) {
  if (const SymbolInfo* info = t.find(x)) return info;
  SymbolInfo si;
  si.name = x.get_name();
  si.sym = x;
  si.domain = Domain::real();
  return &t.declare(si);
}

// A table in which x ranges over the open interval (lo, hi) (everything else as in ctx).
SymbolTable restricted(const SymbolTable& ctx, const symbol& x, const End& lo, const End& hi) {
  SymbolTable t = ctx;
  const SymbolInfo* info = declared_in(t, x);
  const std::string name = info->name;
  const bool numeric_ends = (lo.inf || is_a<numeric>(lo.at.evalf())) && (hi.inf || is_a<numeric>(hi.at.evalf()));
  if (lo.inf == 0 && hi.inf == 0 && numeric_ends) {
    t.narrow_domain(name, Domain::interval(lo.at, true, hi.at, true));
    return t;
  }
  // a half-line (lo, oo) with lo >= 0 lies in the positive numbers, (-oo, hi) with hi <= 0 in the
  // negative ones: the domain says so (sums of positive terms are then seen to be positive)
  // (a symbolic end counts by the sign its declarations fix: (R, oo) with R positive)
  auto numeric_sign = [&](const End& e) -> std::optional<int> {
    if (e.inf) return std::nullopt;
    const ex v = e.at.evalf();
    if (!is_a<numeric>(v) || !ex_to<numeric>(v).is_real()) {
      if (detail::range_of(e.at, ctx).nonnegative()) return 1;
      if (detail::range_of(-e.at, ctx).nonnegative()) return -1;
      return std::nullopt;
    }
    const numeric n = ex_to<numeric>(v);
    return n.is_zero() ? 0 : n > 0 ? 1 : -1;
  };
  const auto lo_sign = numeric_sign(lo), hi_sign = numeric_sign(hi);
  // x > lo >= 0 (whatever hi is) or x < hi <= 0
  if (lo_sign && *lo_sign >= 0) t.narrow_domain(name, Domain::positive());
  else if (hi_sign && *hi_sign <= 0) t.narrow_domain(name, Domain::negative());
  else t.narrow_domain(name, Domain::real());
  if (lo.inf == 0) t.add_constraint({x, lo.at, Constraint::Op::Gt, name + " > lower limit", {}});
  if (hi.inf == 0) t.add_constraint({x, hi.at, Constraint::Op::Lt, name + " < upper limit", {}});
  return t;
}

// Guaranteed by the domains (x restricted), with the evidence; nullopt when not.
std::optional<std::string> guaranteed(const Condition& c, const symbol& x, const End& lo, const End& hi,
                                      const SymbolTable& inside) {
  // exp(u) > 0 always; log(u) != 0 (> 0) is u != 1 (u > 1), its u > 0 being a condition of its
  // own; a product is nonzero when each factor is
  if (is_a<function>(c.e) && ex_to<function>(c.e).get_name() == "exp") return std::string("exp is positive");
  if (is_a<function>(c.e) && ex_to<function>(c.e).get_name() == "log")
    return guaranteed({c.e.op(0) - 1, c.positive}, x, lo, hi, inside);
  if (!c.positive && is_a<mul>(c.e)) {
    std::string ev;
    for (std::size_t i = 0; i < c.e.nops(); ++i) {
      const auto one = guaranteed({c.e.op(i), false}, x, lo, hi, inside);
      if (!one) return std::nullopt;
      ev = *one;
    }
    return ev;
  }
  if (!c.positive && is_a<power>(c.e) && is_a<numeric>(c.e.op(1)) && ex_to<numeric>(c.e.op(1)).is_integer())
    return guaranteed({c.e.op(0), false}, x, lo, hi, inside);
  // a constant (log(2), sqrt(3) - 1): its value decides, with a wide margin
  if (!c.e.has(x)) {
    bool constant = true;
    for (const_preorder_iterator it = c.e.preorder_begin(); it != c.e.preorder_end(); ++it)
      constant = constant && !is_a<symbol>(*it);
    if (constant) {
      DigitsGuard g(60);
      const ex v = c.e.evalf();
      if (!is_a<numeric>(v) || !ex_to<numeric>(v).is_real()) return std::nullopt;
      const numeric n = ex_to<numeric>(v);
      const bool ok = c.positive ? n > numeric("1e-40") : abs(n) > numeric("1e-40");
      if (ok) return std::string("a constant, ") + (c.positive ? "positive" : "nonzero");
      return std::nullopt;
    }
  }
  if (c.e.has(x) && rational_univariate(c.e, x) && rational_end(lo) && rational_end(hi)) {
    if (root_inside(c.e, x, lo, hi)) return std::nullopt;
    for (const End* e : {&lo, &hi})
      if (e->closed && e->inf == 0 && sign_at(c.e, x, *e) == 0) return std::nullopt;
    if (!c.positive) return std::string("no root inside (Sturm)");
    if (sign_at(c.e, x, interior_point(lo, hi)) > 0) return std::string("no root inside and positive (Sturm)");
    return std::nullopt;
  }
  const ex witness = c.positive ? log(c.e) : 1 / c.e;
  const auto conds = side_conditions(witness, inside);
  if (conds.empty()) return std::nullopt;
  for (const auto& sc : conds)
    if (sc.status != SideCondition::Status::Guaranteed) return std::nullopt;
  return conds.front().evidence;
}

// Limits a and b in an order the declarations leave open: every point between them lies in the
// hull of their ranges, an interval with rational or infinite ends; x ranges over it in the
// table returned (a superset where the hull has an end other than 0 and oo). nullopt when the
// hull is the whole line.
struct Hull {
  End lo, hi;
  SymbolTable table;
  std::string text;
};
std::optional<Hull> hull_of_limits(const ex& a, const ex& b, const symbol& x, const SymbolTable& ctx) {
  const detail::Range ra = detail::range_of(a, ctx), rb = detail::range_of(b, ctx);
  End lo{0, 0}, hi{0, 0};
  if (ra.lo_inf || rb.lo_inf) lo.inf = -1;
  else {
    const bool a_lower = ra.lo < rb.lo || (ra.lo == rb.lo && !ra.lo_open);
    lo.at = a_lower ? ra.lo : rb.lo;
    lo.closed = a_lower ? !ra.lo_open : !rb.lo_open;
  }
  if (ra.hi_inf || rb.hi_inf) hi.inf = +1;
  else {
    const bool a_upper = ra.hi > rb.hi || (ra.hi == rb.hi && !ra.hi_open);
    hi.at = a_upper ? ra.hi : rb.hi;
    hi.closed = a_upper ? !ra.hi_open : !rb.hi_open;
  }
  if (lo.inf && hi.inf) return std::nullopt;
  Hull h{lo, hi, ctx, ""};
  const SymbolInfo* info = declared_in(h.table, x);
  Domain d = Domain::real();
  const numeric l = ex_to<numeric>(lo.at), u = ex_to<numeric>(hi.at);
  if (!lo.inf && !hi.inf) d = Domain::interval(lo.at, !lo.closed, hi.at, !hi.closed);
  else if (!lo.inf && (l > 0 || (l.is_zero() && !lo.closed))) d = Domain::positive();
  else if (!lo.inf && l.is_zero()) d = Domain::nonnegative();
  else if (!hi.inf && (u < 0 || (u.is_zero() && !hi.closed))) d = Domain::negative();
  h.table.narrow_domain(info->name, d);
  auto end = [](const End& e, bool lower) {
    if (e.inf) return std::string(lower ? "(-oo" : "oo)");
    const std::string v = detail::exact_text(ex_to<numeric>(e.at));
    return lower ? (e.closed ? "[" : "(") + v : v + (e.closed ? "]" : ")");
  };
  h.text = end(lo, true) + ", " + end(hi, false);
  return h;
}

std::string end_text(const End& e, const SymbolTable& t) {
  return e.inf ? (e.inf > 0 ? "oo" : "-oo") : print_text(e.at, t);
}

// Is e > 0 for every admissible value of the parameters? (numeric: decided at once)
std::optional<bool> sign_known(const ex& e, const SymbolTable& ctx) {
  const ex v = e.evalf();
  if (is_a<numeric>(v) && ex_to<numeric>(v).is_real()) {
    if (ex_to<numeric>(v).is_zero()) return std::nullopt;
    return ex_to<numeric>(v) > 0;
  }
  auto always_positive = [&](const ex& u) {
    const auto conds = side_conditions(log(u), ctx);
    if (conds.empty()) return false;
    for (const auto& sc : conds)
      if (sc.status != SideCondition::Status::Guaranteed) return false;
    return true;
  };
  if (always_positive(e)) return true;
  if (always_positive(-e)) return false;
  return std::nullopt;
}

}  // namespace

Definite definite_integral(const ex& f, const symbol& x, const ex& a, int a_inf, const ex& b, int b_inf,
                           const SymbolTable& ctx) {
  Definite out;
  if (a_inf == 0 && b_inf == 0) {
    // the interval (a, b) must be the same for every admissible parameter value: a < b
    if ((b - a).normal().is_zero()) {
      out.kind = Definite::Kind::Value;
      out.value = 0;
      out.evidence = "equal limits of integration";
      return out;
    }
    const auto order = sign_known(b - a, ctx);
    if (!order) {
      // either order: fine when f and F are continuous on the whole line (F(b) - F(a) then)
      std::string why;
      const std::optional<ex> F = antiderivative(f, x, ctx, &why);
      std::vector<Condition> conds;
      const bool collected = F && collect(f, x, conds) && collect(*F, x, conds);
      // first the interval that holds both limits (a, b positive: (0, oo)), then the whole line
      if (const auto h = collected ? hull_of_limits(a, b, x, ctx) : std::nullopt) {
        bool continuous = true;
        for (std::size_t i = 0; continuous && i < conds.size(); ++i)
          continuous = guaranteed(conds[i], x, h->lo, h->hi, h->table).has_value();
        if (continuous) {
          out.kind = Definite::Kind::Value;
          out.value = F->subs(x == b) - F->subs(x == a);
          out.evidence = "antiderivative " + print_text(*F, ctx) + " (d/d" + x.get_name() +
                         " proved), continuous on " + h->text + ", which holds both limits by the declarations";
          return out;
        }
      }
      const SymbolTable line = restricted(ctx, x, End{0, -1}, End{0, +1});
      bool continuous = collected;
      for (std::size_t i = 0; continuous && i < conds.size(); ++i)
        continuous = guaranteed(conds[i], x, End{0, -1}, End{0, +1}, line).has_value();
      if (!continuous) {
        out.why = "the order of the limits of integration is not determined by the declarations, and the integrand or "
                  "its antiderivative is not shown continuous on the whole line";
        return out;
      }
      out.kind = Definite::Kind::Value;
      out.value = F->subs(x == b) - F->subs(x == a);
      out.evidence = "antiderivative " + print_text(*F, ctx) + " (d/d" + x.get_name() +
                     " proved), continuous on the whole line";
      return out;
    }
    if (!*order) {   // integral from a to b = - integral from b to a
      Definite r = definite_integral(f, x, b, 0, a, 0, ctx);
      if (r.kind == Definite::Kind::Value) r.value = -r.value;
      r.infinite = -r.infinite;
      r.evidence = "limits reversed: " + r.evidence;
      return r;
    }
  }
  const End lo{a_inf ? ex(0) : a, a_inf}, hi{b_inf ? ex(0) : b, b_inf};
  std::string why;
  std::optional<ex> F = antiderivative(f, x, ctx, &why);
  if (!F) {
    out.why = why;
    return out;
  }
  const SymbolTable inside = restricted(ctx, x, lo, hi);
  // log(u) with u < 0 on the interval: log(-u) has the same derivative
  std::vector<Condition> conds;
  for (const_preorder_iterator it = F->preorder_begin(); it != F->preorder_end(); ++it)
    if (is_a<function>(*it) && ex_to<function>(*it).get_name() == "log" && it->op(0).has(x)) {
      const ex u = it->op(0);
      if (!guaranteed({u, true}, x, lo, hi, inside) && guaranteed({-u, true}, x, lo, hi, inside)) {
        const ex G = F->subs(log(u) == log(-u));
        if ((G.diff(x) - f).normal().is_zero()) F = G;
      }
    }
  if (!collect(f, x, conds) || !collect(*F, x, conds)) {
    out.why = "the integrand or its antiderivative has a part whose continuity is not known";
    return out;
  }
  std::string checked;
  for (const Condition& c : conds) {
    const auto ev = guaranteed(c, x, lo, hi, inside);
    if (!ev) {
      out.why = "continuity on (" + end_text(lo, ctx) + ", " + end_text(hi, ctx) + ") not shown: " +
                (c.positive ? print_text(c.e, ctx) + " > 0" : print_text_up_to_sign(c.e, ctx) + " != 0") +
                " is not guaranteed";
      return out;
    }
  }
  const LimitResult lb = hi.inf ? compute_limit(*F, x, 0, +1, 0, inside) : compute_limit(*F, x, hi.at, 0, -1, inside);
  const LimitResult la = lo.inf ? compute_limit(*F, x, 0, -1, 0, inside) : compute_limit(*F, x, lo.at, 0, +1, inside);
  const std::string F_text = "antiderivative " + print_text(*F, ctx) + " (d/d" + x.get_name() +
                             " proved), continuous on (" + end_text(lo, ctx) + ", " + end_text(hi, ctx) + ")";
  auto end_limit = [&](const LimitResult& r, const End& e, const char* side) {
    std::string s = "F(" + end_text(e, ctx) + (e.inf ? "" : side) + ") = ";
    if (r.ok) s += r.infinite ? (r.infinite > 0 ? "oo" : "-oo") : print_text(r.value, ctx);
    else s += r.does_not_exist ? "does not exist (" + r.reason + ")" : "undecided (" + r.reason + ")";
    return s;
  };
  out.evidence = F_text + "; " + end_limit(lb, hi, "-") + ", " + end_limit(la, lo, "+");
  if (lb.does_not_exist || la.does_not_exist) {
    out.kind = Definite::Kind::DoesNotExist;
    return out;
  }
  if (!lb.ok || !la.ok) {
    out.why = "a limit of the antiderivative at an end was not decided: " + out.evidence;
    return out;
  }
  if (lb.infinite || la.infinite) {
    out.kind = Definite::Kind::Diverges;
    const int up = lb.infinite, down = -la.infinite;   // the integral's share from each end
    out.infinite = up && down ? (up == down ? up : 0) : (up ? up : down);
    return out;
  }
  out.kind = Definite::Kind::Value;
  out.value = lb.value - la.value;
  return out;
}

}  // namespace dc::integrals
