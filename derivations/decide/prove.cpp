// prove_equal: the cascade that decides whether two expressions are equal (see prove.hpp).
#include "derivations/decide/prove.hpp"

#include <cctype>

#include <algorithm>
#include <functional>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

#include "derivations/symbolic/printer.hpp"
#include "derivations/symbolic/inspect.hpp"
#include "derivations/kernel/range.hpp"
#include "derivations/kernel/sample.hpp"
#include "derivations/kernel/ball.hpp"
#include "derivations/kernel/probe.hpp"
#include "derivations/kernel/sign.hpp"
#include "derivations/decide/common_domain.hpp"
#include "derivations/decide/integer.hpp"

namespace dc {

using GiNaC::ex;
using GiNaC::numeric;

// ------------------------------------------------------------------ stage 2: transcendental

namespace {

bool is_fn(const ex& e, const char* name) {
  return GiNaC::is_exactly_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == name;
}

// log of a positive rational as a sum over prime logs: log(6) -> log(2) + log(3), so constant
// log identities reduce to zero. Only for moderate integers (trial division up to 1e6).
ex log_of_positive_rational(const numeric& q) {
  if (q == 1) return 0;
  auto split_int = [](numeric n, ex& acc, int sign) -> bool {
    if (n > numeric("1000000000000")) return false;
    long v = n.to_long();
    ex part = 0;
    for (long p = 2; p * p <= v; ++p) {
      int k = 0;
      while (v % p == 0) {
        v /= p;
        ++k;
      }
      if (k) part += k * GiNaC::log(ex(p));
    }
    if (v > 1) part += GiNaC::log(ex(v));
    acc += sign * part;
    return true;
  };
  ex acc = 0;
  if (!split_int(q.numer(), acc, 1) || !split_int(q.denom(), acc, -1)) return GiNaC::log(ex(q));
  return acc;
}

ex log_split(const ex& a, const SymbolTable& ctx);

// log(a) for a that is not a product: powers of positive bases, exp(real), positive rationals.
ex log_atom(const ex& a, const SymbolTable& ctx) {
  if (GiNaC::is_a<numeric>(a)) {
    const numeric& q = GiNaC::ex_to<numeric>(a);
    if (q.is_rational() && q.is_positive()) return log_of_positive_rational(q);
    return GiNaC::log(a);
  }
  if (GiNaC::is_a<GiNaC::power>(a)) {
    // log(b^x) = x log(b) for b > 0 and real x
    if (detail::provably_positive(a.op(0), ctx) && detail::provably_real(a.op(1), ctx))
      return a.op(1) * log_split(a.op(0), ctx);
    return GiNaC::log(a);
  }
  if (is_fn(a, "exp") && detail::provably_real(a.op(0), ctx)) return a.op(0);
  // log(tan(u)) = log(sin(u)) - log(cos(u)) where both are positive
  if (is_fn(a, "tan") && detail::provably_positive(GiNaC::sin(a.op(0)), ctx) &&
      detail::provably_positive(GiNaC::cos(a.op(0)), ctx))
    return GiNaC::log(GiNaC::sin(a.op(0))) - GiNaC::log(GiNaC::cos(a.op(0)));
  return GiNaC::log(a);
}

// n^(k/q) for a positive integer n and 0 < k/q < 1: the q-th powers inside n taken out
// (12^(1/2) = 2*3^(1/2)), by trial division up to 10^6; nullopt when n is larger.
std::optional<ex> integer_radical(const numeric& n, const numeric& r) {
  if (!n.is_pos_integer() || n > numeric("1000000000000")) return std::nullopt;
  long v = n.to_long();
  const long k = r.numer().to_long(), q = r.denom().to_long();
  numeric out_part = 1, in_part = 1;
  auto take = [&](long p, long e) {
    const long total = e * k;   // p^(e k / q) = p^(total / q)
    out_part *= GiNaC::pow(numeric(p), numeric(total / q));
    in_part *= GiNaC::pow(numeric(p), numeric(total % q));
  };
  for (long p = 2; p * p <= v; ++p) {
    long e = 0;
    while (v % p == 0) v /= p, ++e;
    if (e) take(p, e);
  }
  if (v > 1) take(v, 1);
  return out_part * GiNaC::pow(ex(in_part), numeric(1, q));
}

// b^r for a rational r that is not an integer, with the factors whose sign the declarations
// fix taken out: (c*y)^r = c^r * y^r for c > 0 (the principal branch: arg(c*y) = arg(y)),
// (f^k)^r = f^(k r) for f > 0 and real k, and rational c reduced (sqrt(12) = 2*sqrt(3)). A
// sum is factored first, so sqrt(m^2*a^2 + m^2*b^2) = m*sqrt(a^2 + b^2) for m > 0 (only small
// polynomial sums: factorisation is costly).
ex power_split(const ex& b_in, const numeric& r, const SymbolTable& ctx) {
  ex b = b_in;
  if (GiNaC::is_a<GiNaC::add>(b_in) && b_in.nops() <= 24) try {
      GiNaC::lst syms;
      for (GiNaC::const_preorder_iterator it = b_in.preorder_begin(); it != b_in.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it)) syms.append(*it);
      if (b_in.is_polynomial(syms)) {
        // a numeric content apart: GiNaC distributes 4*(a^2 + b^2) back into the sum
        const numeric c = b_in.integer_content();
        if (c.is_positive() && c != 1)
          return power_split(c, r, ctx) * power_split(GiNaC::expand(b_in / c), r, ctx);
        const ex f = GiNaC::factor(b_in);
        if (GiNaC::is_a<GiNaC::mul>(f)) b = f;
      }
    } catch (const std::exception&) {
    }
  auto atom = [&](const ex& f) -> std::optional<ex> {   // f^r when f > 0 gives a simpler form
    if (GiNaC::is_a<numeric>(f)) {
      const numeric& c = GiNaC::ex_to<numeric>(f);
      if (!c.is_rational() || !c.is_positive()) return std::nullopt;
      // r = wi + frac with wi an integer and 0 < frac < 1
      const numeric wi = GiNaC::iquo(r.numer(), r.denom()) - (r.is_negative() ? 1 : 0);
      const numeric frac = r - wi;
      auto num = integer_radical(c.numer(), frac), den = integer_radical(c.denom(), frac);
      if (!num || !den) return std::nullopt;
      return GiNaC::pow(ex(c), wi) * *num / *den;
    }
    if (GiNaC::is_a<GiNaC::power>(f) && detail::provably_positive(f.op(0), ctx) && detail::provably_real(f.op(1), ctx))
      return GiNaC::pow(f.op(0), f.op(1) * r);
    if (detail::provably_positive(f, ctx)) return GiNaC::pow(f, r);
    return std::nullopt;
  };
  if (!GiNaC::is_a<GiNaC::mul>(b)) {
    const auto a = atom(b);
    return a ? *a : GiNaC::pow(b, r);
  }
  ex out = 1, rest = 1;
  bool split = false;
  for (std::size_t i = 0; i < b.nops(); ++i) {
    const auto a = atom(b.op(i));
    if (a) out *= *a, split = true;
    else rest *= b.op(i);
  }
  if (!split) return GiNaC::pow(b, r);
  return out * GiNaC::pow(rest, r);
}

// log(p * r) = log(p) + log(r) whenever p > 0 (the argument of p*r is that of r), so every
// provably positive factor is split off, whatever the sign of the rest.
ex log_split(const ex& a, const SymbolTable& ctx) {
  if (!GiNaC::is_a<GiNaC::mul>(a)) return log_atom(a, ctx);
  ex sum = 0, rest = 1;
  bool split = false;
  for (std::size_t i = 0; i < a.nops(); ++i) {
    const ex& f = a.op(i);
    bool pos = false;
    if (GiNaC::is_a<GiNaC::power>(f))
      pos = detail::provably_positive(f.op(0), ctx) && detail::provably_real(f.op(1), ctx);
    else
      pos = detail::provably_positive(f, ctx);
    if (pos) {
      sum += log_atom(f, ctx);
      split = true;
    } else {
      rest *= f;
    }
  }
  if (!split) return GiNaC::log(a);
  if (!rest.is_equal(1)) sum += GiNaC::log(rest);
  return sum;
}

struct TranscendentalRewrite : GiNaC::map_function {
  const SymbolTable& ctx;
  explicit TranscendentalRewrite(const SymbolTable& c) : ctx(c) {}
  ex operator()(const ex& e) override {
    if (e.nops() == 0) return e;
    ex m = e.map(*this);
    if (is_fn(m, "log")) return log_split(m.op(0), ctx);
    if (GiNaC::is_a<GiNaC::power>(m) && GiNaC::is_a<numeric>(m.op(1)) &&
        GiNaC::ex_to<numeric>(m.op(1)).is_rational() && !GiNaC::ex_to<numeric>(m.op(1)).is_integer())
      return power_split(m.op(0), GiNaC::ex_to<numeric>(m.op(1)), ctx);
    if (is_fn(m, "exp")) {
      // exp(sum) = prod exp(term); exp(c*log(y)) = y^c (GiNaC defines y^c as exp(c log y)).
      ex arg = GiNaC::expand(m.op(0));
      ex terms = GiNaC::is_a<GiNaC::add>(arg) ? arg : GiNaC::lst{arg};
      ex prod = 1;
      for (std::size_t i = 0; i < terms.nops(); ++i) {
        const ex& t = terms.op(i);
        if (is_fn(t, "log")) {
          prod *= t.op(0);
        } else if (GiNaC::is_a<GiNaC::mul>(t) && t.nops() == 2 && GiNaC::is_a<numeric>(t.op(1)) &&
                   is_fn(t.op(0), "log")) {
          prod *= GiNaC::pow(t.op(0).op(0), t.op(1));
        } else if (GiNaC::is_a<GiNaC::mul>(t) && t.nops() == 2 && GiNaC::is_a<numeric>(t.op(0)) &&
                   is_fn(t.op(1), "log")) {
          prod *= GiNaC::pow(t.op(1).op(0), t.op(0));
        } else {
          prod *= GiNaC::exp(t);
        }
      }
      return prod;
    }
    return m;
  }
};

bool has_function_or_root(const ex& e) {
  if (GiNaC::is_a<GiNaC::function>(e)) return true;
  if (GiNaC::is_a<GiNaC::power>(e) && !e.op(1).info(GiNaC::info_flags::integer)) return true;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_function_or_root(e.op(i))) return true;
  return false;
}

bool has_trig(const ex& e) {
  if (GiNaC::is_a<GiNaC::function>(e)) {
    std::string n = GiNaC::ex_to<GiNaC::function>(e).get_name();
    if (n == "sin" || n == "cos" || n == "tan" || n == "sinh" || n == "cosh" || n == "tanh") return true;
  }
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_trig(e.op(i))) return true;
  return false;
}

// sin^2 = 1 - cos^2, sinh^2 = cosh^2 - 1, tan = sin/cos, tanh = sinh/cosh.
ex apply_side_relations(const ex& e) {
  ex w = GiNaC::wild(0);
  ex s = e.subs(GiNaC::lst{GiNaC::tan(w) == GiNaC::sin(w) / GiNaC::cos(w),
                           GiNaC::tanh(w) == GiNaC::sinh(w) / GiNaC::cosh(w)});
  s = GiNaC::expand(s);
  s = s.subs(GiNaC::pow(GiNaC::sin(w), 2) == 1 - GiNaC::pow(GiNaC::cos(w), 2), GiNaC::subs_options::algebraic);
  s = s.subs(GiNaC::pow(GiNaC::sinh(w), 2) == GiNaC::pow(GiNaC::cosh(w), 2) - 1, GiNaC::subs_options::algebraic);
  return GiNaC::normal(GiNaC::expand(s));
}

// ------------------------------------------------------------------ conditions for real values

enum class CondKind { Nonzero, Positive, Nonnegative, UnitInterval };

struct RawCond {
  CondKind kind;
  ex arg;
  std::string reason;
};

// `ctx` (when given) says which symbols are integers: x^n for an integer n needs x != 0 only
// where n may be negative, not x > 0.
void collect_conditions(const ex& e, std::vector<RawCond>& out, const SymbolTable* ctx = nullptr) {
  for (std::size_t i = 0; i < e.nops(); ++i) collect_conditions(e.op(i), out, ctx);
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const ex& b = e.op(0);
    const ex& x = e.op(1);
    if (GiNaC::is_a<numeric>(b)) {
      // constants such as sqrt(2) or 1/2 need nothing
      return;
    }
    if (GiNaC::is_a<numeric>(x)) {
      const numeric& n = GiNaC::ex_to<numeric>(x);
      if (n.is_integer()) {
        if (n.is_negative()) out.push_back({CondKind::Nonzero, b, "divisor"});
        return;
      }
      std::string why = (n.denom() == 2) ? "sqrt argument" : "fractional power base";
      out.push_back({n.is_negative() ? CondKind::Positive : CondKind::Nonnegative, b,
                     n.is_negative() ? why + " (divisor)" : why});
      return;
    }
    if (ctx && integer_valued(x, *ctx)) {
      if (!detail::range_of(x, *ctx).nonnegative()) out.push_back({CondKind::Nonzero, b, "divisor"});
      return;
    }
    out.push_back({CondKind::Positive, b, "power base"});
    return;
  }
  if (is_fn(e, "log")) out.push_back({CondKind::Positive, e.op(0), "log argument"});
  // tan(u) = sin(u)/cos(u): a pole where cos(u) = 0 (constants such as tan(1) need nothing)
  if (is_fn(e, "tan") && !GiNaC::is_a<numeric>(e.op(0).evalf())) out.push_back({CondKind::Nonzero, GiNaC::cos(e.op(0)), "tan pole"});
  if (is_fn(e, "acos")) out.push_back({CondKind::UnitInterval, e.op(0), "acos argument"});
  if (is_fn(e, "asin")) out.push_back({CondKind::UnitInterval, e.op(0), "asin argument"});
}

}  // namespace

// ------------------------------------------------------------------ the cascade

std::string sci(double x) {
  std::ostringstream os;
  os.precision(2);
  os << std::scientific << x;
  return os.str();
}

namespace {

// How many distinct denominators (powers with a negative exponent) `e` has, counting stops
// above `cap`.
std::size_t distinct_denominators(const ex& e, std::size_t cap) {
  GiNaC::exset seen;
  std::vector<ex> stack{e};
  while (!stack.empty() && seen.size() <= cap) {
    ex x = stack.back();
    stack.pop_back();
    if (GiNaC::is_a<GiNaC::power>(x) && GiNaC::is_a<GiNaC::numeric>(x.op(1)) &&
        GiNaC::ex_to<GiNaC::numeric>(x.op(1)).is_negative()) {
      seen.insert(x.op(0));
      continue;
    }
    for (std::size_t i = 0; i < x.nops(); ++i) stack.push_back(x.op(i));
  }
  return seen.size();
}

Verdict cascade(const ex& lhs, const ex& rhs, const SymbolTable& ctx, const ProveOptions& opt) {
  Verdict v;
  ex diff = lhs - rhs;
  double est = estimate_expanded_terms(lhs) + estimate_expanded_terms(rhs);
  if (est > static_cast<double>(opt.max_terms)) {
    // Too big to expand: the symbolic stages are skipped, the kernel's probe (which evaluates
    // the sides as written) still decides where it can.
    std::ostringstream os;
    os << "expansion would exceed " << sci(static_cast<double>(opt.max_terms)) << " terms (estimated " << sci(est)
       << "), so the symbolic stages were skipped";
    if (opt.numeric) {
      Verdict p = kernel::probe(lhs, rhs, ctx, opt, "(not expanded)");
      if (p.kind != VerdictKind::Undecided) return p;
      p.reason = os.str() + "; " + p.reason;
      p.detail = p.reason;
      return p;
    }
    v.kind = VerdictKind::Undecided;
    v.method = "normal";
    v.reason = "resource limit: " + os.str();
    v.detail = v.reason;
    return v;
  }
  // normal() of a sum over many distinct denominators brings them to one (quadratic or worse
  // in their number: 300 terms 1/(x+i) take about a minute). A false claim of that shape is
  // refuted by the kernel's probe first, which costs one evaluation per point.
  if (opt.symbolic && opt.numeric && distinct_denominators(diff, 40) > 40) {
    Verdict p = kernel::probe(lhs, rhs, ctx, opt, "(not normalised yet)");
    if (p.kind == VerdictKind::Refuted) return p;
  }
  std::string residual;
  std::string last_method = "normal";
  if (opt.symbolic) {
    try {
      // 1. exact symbolic
      ex n = GiNaC::normal(diff);
      if (n.is_zero()) {
        v.kind = VerdictKind::Proved;
        v.method = "normal";
        v.detail = "normal(lhs - rhs) = 0";
        return v;
      }
      ex current = n;
      // 2. transcendental rules (log of products/powers of positive factors, exp of sums)
      if (has_function_or_root(n)) {
        last_method = "expand (transcendental)";
        TranscendentalRewrite rw(ctx);
        ex t = rw(diff);
        if (estimate_expanded_terms(t) <= static_cast<double>(opt.max_terms)) {
          t = GiNaC::expand(t, GiNaC::expand_options::expand_transcendental);
          t = GiNaC::normal(rw(t));
          if (t.is_zero()) {
            v.kind = VerdictKind::Proved;
            v.method = "expand (transcendental)";
            v.detail = "log/exp rules on positive factors, then normal(lhs - rhs) = 0";
            return v;
          }
          current = t;
          // 3. side relations
          if (has_trig(t)) {
            last_method = "side relations";
            ex s = apply_side_relations(t);
            if (s.is_zero()) {
              v.kind = VerdictKind::Proved;
              v.method = "side relations";
              v.detail = "sin^2 = 1 - cos^2 (and tan = sin/cos), then normal(lhs - rhs) = 0";
              return v;
            }
          }
        }
      }
      residual = detail::residual_text(current, ctx);
    } catch (const std::exception& e) {
      residual = print_text(diff, ctx);
    }
  } else {
    residual = print_text(diff, ctx);
  }
  if (opt.numeric) return kernel::probe(lhs, rhs, ctx, opt, residual);
  v.kind = VerdictKind::Undecided;
  v.method = last_method;
  v.residual = residual;
  v.reason = opt.symbolic ? "the symbolic stages leave a nonzero residual and the numeric probe is off"
                          : "both the symbolic stages and the numeric probe are off";
  v.detail = v.reason + "; residual: " + residual;
  return v;
}

// For a claim refuted at a point where some real symbols are negative: would it hold if they
// were declared positive? Returns "holds if a, b > 0: declare a, b positive", or "".
std::string declaration_hint(const ex& lhs, const ex& rhs, const SymbolTable& ctx, const ProveOptions& opt,
                             const Verdict& refuted) {
  bool negative_real = false;   // the counterexample uses a negative value of a real symbol
  for (const auto& [name, value] : refuted.point) {
    const SymbolInfo* info = ctx.find(name);
    negative_real = negative_real || (info && !info->is_function && info->domain.unrestricted() &&
                                      value.rfind('-', 0) == 0);
  }
  if (!negative_real) return "";
  // try every real symbol of the claim positive, not only the negative ones of this point
  std::vector<std::string> names;
  for (const auto& s : detail::ordered_symbols(lhs - rhs, ctx)) {
    const SymbolInfo* info = ctx.find(GiNaC::ex_to<GiNaC::symbol>(s));
    if (info && info->domain.unrestricted()) names.push_back(info->name);
  }
  SymbolTable narrowed = ctx;
  for (const auto& n : names) narrowed.narrow_domain(n, Domain::positive());
  if (!kernel::probe(lhs, rhs, narrowed, opt, "").holds()) return "";
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i) list += (i ? ", " : "") + names[i];
  return "holds if " + list + (names.size() > 1 ? " are" : " is") + " positive: declare " + list + " positive";
}

}  // namespace

Verdict prove_equal(const ex& lhs, const ex& rhs, const SymbolTable& ctx, const ProveOptions& opt) {
  Verdict v = with_integer_periods(lhs, rhs, ctx, opt, cascade);
  if (v.kind == VerdictKind::Refuted && opt.numeric) {
    std::string hint = declaration_hint(lhs, rhs, ctx, opt, v);
    v.hint = hint;
  }
  if (v.kind != VerdictKind::Proved || !opt.numeric) return v;
  // Proved symbolically: re-witness numerically. A contradiction is a bug in a symbolic stage
  // (or a rewrite used outside its domain): never shown as proved.
  std::string contra = kernel::witness_contradiction(lhs, rhs, ctx, opt);
  if (contra.empty()) return v;
  Verdict u;
  u.kind = VerdictKind::Undecided;
  u.method = v.method;
  u.reason = "internal error: the symbolic proof (" + v.method + ") is contradicted by the numeric witness " + contra +
             "; please report this";
  u.detail = u.reason;
  return u;
}

Verdict prove_zero(const ex& e, const SymbolTable& ctx, const ProveOptions& opt) {
  return prove_equal(e, 0, ctx, opt);
}

// ------------------------------------------------------------------ side conditions

namespace {

std::string condition_text(CondKind k, const ex& a, const SymbolTable& ctx) {
  switch (k) {
    case CondKind::Nonzero: {
      return print_text_up_to_sign(a, ctx) + " != 0";
    }
    case CondKind::Positive: return print_text(a, ctx) + " > 0";
    case CondKind::Nonnegative: return print_text(a, ctx) + " >= 0";
    case CondKind::UnitInterval: return "-1 <= " + print_text(a, ctx) + " <= 1";
  }
  return "";
}

// The condition with its argument divided by its positive numeric content (2*x - 2 > 0 is
// x - 1 > 0), and for != 0 its sign chosen canonically.
std::string condition_key(CondKind k, const ex& a) {
  try {
    ex e = GiNaC::expand(a);
    const numeric c = e.integer_content();
    if (!c.is_zero()) e = GiNaC::expand(e / c);
    std::string t = detail::canon_text(e);
    if (k == CondKind::Nonzero) t = std::min(t, detail::canon_text(GiNaC::expand(-e)));
    return std::to_string(static_cast<int>(k)) + "|" + t;
  } catch (const std::exception&) {
    return std::to_string(static_cast<int>(k)) + "|" + detail::canon_text(a);
  }
}

std::string domains_text(const ex& a, const SymbolTable& ctx) {
  std::string s;
  for (const auto& sym : detail::ordered_symbols(a, ctx)) {
    if (!s.empty()) s += ", ";
    s += GiNaC::ex_to<GiNaC::symbol>(sym).get_name() + " " + detail::domain_of(sym, ctx).to_string();
  }
  return s.empty() ? "a constant" : s;
}

// Does an assumed constraint give the condition? (arg equals +-(lhs - rhs) of an assumption)
// Does the constraint c fix the sign that condition k needs of a? True when a is the
// constraint's difference lhs - rhs times a factor of evident sign (-g*(r2 - y2) from y2 > r2).
bool constraint_implies(CondKind k, const ex& a, const Constraint& c, const SymbolTable& ctx) {
  ex cd = c.lhs - c.rhs;
  bool same = false, opposite = false;
  try {
    same = GiNaC::normal(a - cd).is_zero();
    opposite = !same && GiNaC::normal(a + cd).is_zero();
    if (!same && !opposite && !cd.is_zero()) {
      ex q = GiNaC::normal(a / cd);
      same = detail::provably_positive(q, ctx);
      opposite = !same && detail::provably_positive(-q, ctx);
    }
  } catch (const std::exception&) {
    return false;
  }
  if (!same && !opposite) return false;
  using Op = Constraint::Op;
  // sign of cd implied by the constraint
  bool pos = c.op == Op::Gt, neg = c.op == Op::Lt, nonneg = c.op == Op::Ge || c.op == Op::Gt,
       nonpos = c.op == Op::Le || c.op == Op::Lt, nz = c.op == Op::Ne || pos || neg;
  if (opposite) {
    std::swap(pos, neg);
    std::swap(nonneg, nonpos);
  }
  switch (k) {
    case CondKind::Nonzero: return nz;
    case CondKind::Positive: return pos;
    case CondKind::Nonnegative: return nonneg;
    case CondKind::UnitInterval: return false;
  }
  return false;
}

}  // namespace

std::vector<SideCondition> side_conditions(const ex& e, const SymbolTable& ctx) {
  std::vector<RawCond> raw;
  collect_conditions(e, raw, &ctx);
  std::map<std::string, SideCondition> by_text;  // sorted, deduplicated: deterministic order
  for (const RawCond& rc : raw) {
    SideCondition sc;
    sc.what = condition_text(rc.kind, rc.arg, ctx);
    sc.reason = rc.reason;
    if (by_text.count(sc.what)) continue;
    // each condition is listed with the conditions of its parts, so the range where the
    // argument is real decides it
    detail::Range range = detail::range_where_defined(rc.arg, ctx);
    bool guaranteed = false;
    // (range analysis and GiNaC's flags here; Sturm and subdivision below, named in the evidence)
    const detail::Range plain = detail::range_of(rc.arg, ctx);
    const bool pos_flag = rc.arg.info(GiNaC::info_flags::positive);
    switch (rc.kind) {
      case CondKind::Nonzero:
        guaranteed = range.nonzero() || plain.nonzero() || pos_flag || rc.arg.info(GiNaC::info_flags::negative);
        break;
      case CondKind::Positive: guaranteed = range.positive() || plain.positive() || pos_flag; break;
      case CondKind::Nonnegative: guaranteed = range.nonnegative() || plain.positive() || pos_flag; break;
      case CondKind::UnitInterval: guaranteed = range.within(-1, 1); break;
    }
    if (guaranteed) {
      sc.status = SideCondition::Status::Guaranteed;
      sc.evidence = "follows from the domains: " + domains_text(rc.arg, ctx);
      by_text[sc.what] = sc;
      continue;
    }
    for (const Constraint& c : ctx.constraints())
      if (constraint_implies(rc.kind, rc.arg, c, ctx)) {
        sc.status = SideCondition::Status::Guaranteed;
        sc.evidence = "assumed: " + c.text;
        guaranteed = true;
        break;
      }
    if (guaranteed) {
      by_text[sc.what] = sc;
      continue;
    }
    // Sturm sequences for a polynomial in one symbol, Arb subdivision on bounded domains
    {
      using W = kernel::SignWant;
      const bool unit = rc.kind == CondKind::UnitInterval;
      const ex arg = unit ? 1 - GiNaC::pow(rc.arg, 2) : rc.arg;
      const W want = rc.kind == CondKind::Nonzero ? W::Nonzero : rc.kind == CondKind::Positive ? W::Positive : W::Nonnegative;
      if (auto how = kernel::decide_sign(arg, want, ctx)) {
        sc.status = SideCondition::Status::Guaranteed;
        sc.evidence = "decided on the declared domain by " + *how;
        by_text[sc.what] = sc;
        continue;
      }
    }
    if (detail::has_abstract_application(rc.arg)) {
      sc.status = SideCondition::Status::Unknown;
      sc.evidence = "depends on an abstract function; not implied by the domains";
      by_text[sc.what] = sc;
      continue;
    }
    // Look for an admissible point that breaks it.
    detail::PointSampler sampler({rc.arg}, ctx);
    detail::Rng rng(20261121 ^ detail::hash_text(sc.what, 7));
    int tested = 0;
    bool violated = false;
    for (int attempt = 0; attempt < 60 && tested < 16 && !violated; ++attempt) {
      bool adm = false;
      GiNaC::exmap p = sampler.draw(rng, attempt >= 30, &adm);
      if (!adm) continue;
      const ex& val = rc.arg;
      // The argument's sign at the point, certified by ball arithmetic (an argument that is
      // itself not real breaks an inner condition, which reports it).
      kernel::Ball b = kernel::enclose_sign_at(val, &p);
      if (b.status != kernel::BallStatus::Value) continue;
      ++tested;
      bool bad = false;
      std::string value_text = b.text(20);
      switch (rc.kind) {
        case CondKind::Nonzero: bad = b.exact_zero(); break;
        case CondKind::Positive: bad = b.negative() || b.exact_zero(); break;
        case CondKind::Nonnegative: bad = b.negative(); break;
        case CondKind::UnitInterval: bad = kernel::enclose_sign_at(GiNaC::abs(val) - 1, &p).positive(); break;
      }
      if (bad) {
        violated = true;
        sc.status = SideCondition::Status::Violated;
        sc.point = sampler.describe(p);
        sc.evidence = "fails at " + detail::join_point(sc.point) + " (value " + value_text + ")";
      }
    }
    if (!violated) {
      sc.status = SideCondition::Status::Unknown;
      sc.evidence = "not implied by the domains (" + domains_text(rc.arg, ctx) + "); held at " +
                    std::to_string(tested) + " sampled points";
    }
    by_text[sc.what] = sc;
  }
  std::vector<SideCondition> out;
  for (auto& [k, sc] : by_text) out.push_back(sc);
  return out;
}

// check_satisfiable lives in satisfiable.cpp.

int defined_at_point(const GiNaC::lst& parts, const GiNaC::exmap& p, const SymbolTable* ctx) {
  std::vector<RawCond> raw;
  collect_conditions(parts, raw, ctx);
  bool all_hold = true;
  for (const RawCond& rc : raw) {
    const ex arg = rc.kind == CondKind::UnitInterval ? 1 - GiNaC::pow(rc.arg, 2) : rc.arg;
    kernel::Ball b = kernel::enclose_sign_at(arg, &p, 128, 1 << 12);
    if (b.status == kernel::BallStatus::NotReal || b.status == kernel::BallStatus::Pole) return -1;
    if (b.status != kernel::BallStatus::Value) {
      all_hold = false;
      continue;
    }
    switch (rc.kind) {
      case CondKind::Nonzero:
        if (b.exact_zero()) return -1;
        all_hold = all_hold && (b.positive() || b.negative());
        break;
      case CondKind::Positive:
        if (b.negative() || b.exact_zero()) return -1;
        all_hold = all_hold && b.positive();
        break;
      case CondKind::Nonnegative:
      case CondKind::UnitInterval:
        if (b.negative()) return -1;
        all_hold = all_hold && (b.positive() || b.exact_zero());
        break;
    }
  }
  if (!all_hold) return 0;
  for (std::size_t i = 0; i < parts.nops(); ++i) {
    kernel::Ball b = kernel::enclose_sign_at(parts.op(i), &p, 128, 1 << 12);
    if (b.status == kernel::BallStatus::NotReal || b.status == kernel::BallStatus::Pole) return -1;
    if (b.status != kernel::BallStatus::Value) return 0;
  }
  return 1;
}

std::map<std::string, std::string> side_condition_keys(const ex& e, const SymbolTable& ctx) {
  std::vector<RawCond> raw;
  collect_conditions(e, raw, &ctx);
  std::map<std::string, std::string> out;
  for (const RawCond& rc : raw) out.emplace(condition_text(rc.kind, rc.arg, ctx), condition_key(rc.kind, rc.arg));
  return out;
}

std::vector<SideCondition> side_conditions_of_tree(const Node& n, const SymbolTable& ctx, const std::string& free_of) {
  GiNaC::lst parts;
  return side_conditions_of_tree_parts(n, ctx, free_of, parts);
}

std::vector<SideCondition> side_conditions_of_tree_parts(const Node& n, const SymbolTable& ctx,
                                                         const std::string& free_of, GiNaC::lst& parts_out) {
  GiNaC::lst parts;
  std::function<void(const Node&)> walk;
  std::function<bool(const Node&, const std::string&)> mentions = [&](const Node& m, const std::string& x) {
    if (m.kind == NodeKind::Symbol && m.text == x) return true;
    for (const auto& a : m.args)
      if (mentions(a, x)) return true;
    return false;
  };
  // Inside limit(f, x, p) and integral(f, x, a, b) the variable is bound: x ranges near p or
  // over (a, b), not over the domain declared for the quantity x. Only the parts of f free of x
  // carry conditions of the claim (the limit engine and the integral's methods answer for the
  // rest); the point and the limits of integration carry their own. The integrand of an
  // indefinite integral(f, x) is given, not claimed: `integral(f, x) = F` claims dF/dx = f where
  // f is defined (require_antiderivative_defined answers for F), so its parts in x carry no
  // condition either (integral(sqrt(x)^2, x) = x^2/2 holds for x real).
  std::function<void(const Node&, const std::string&)> free_parts = [&](const Node& m, const std::string& x) {
    if (!mentions(m, x)) return walk(m);
    for (const auto& a : m.args) free_parts(a, x);
  };
  walk = [&](const Node& m) {
    const bool binds = m.kind == NodeKind::Call &&
                       ((m.text == "limit" && m.args.size() == 3) ||
                        (m.text == "integral" && (m.args.size() == 4 || m.args.size() == 2)) ||
                        (m.text == "eval_between" && m.args.size() == 4)) &&
                       m.args[1].kind == NodeKind::Symbol;
    if (binds) {
      for (std::size_t i = 2; i < m.args.size(); ++i) {
        const Node& a = m.args[i].kind == NodeKind::Neg ? m.args[i].args[0] : m.args[i];
        if (!(a.kind == NodeKind::Symbol && a.text == "oo")) walk(m.args[i]);
      }
      // [F]_a^b is F(b) - F(a): what F needs at the ends is a condition of the claim
      if (m.text == "eval_between") try {
          parts.append(to_ginac(m, ctx));
        } catch (const std::exception&) {
        }
      return free_parts(m.args[0], m.args[1].text);
    }
    for (const auto& a : m.args) walk(a);
    bool calculus = m.kind == NodeKind::Call && (m.text == "integral" || m.text == "diff" || m.text == "limit");
    if (calculus || !(m.kind == NodeKind::Call || m.kind == NodeKind::Pow || m.kind == NodeKind::Div)) return;
    try {
      parts.append(to_ginac(m, ctx));
    } catch (const std::exception&) {
      // reported where the expression is used
    }
  };
  if (free_of.empty()) walk(n);
  else free_parts(n, free_of);
  parts_out = parts;
  return side_conditions(parts, ctx);
}

}  // namespace dc
