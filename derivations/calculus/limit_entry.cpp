// Limits and first-order expansions (GiNaC has no limit()); see limit.hpp.
#include "derivations/calculus/limit_entry.hpp"

#include "derivations/calculus/big_o.hpp"

#include "derivations/kernel/ball.hpp"

#include <sstream>
#include <stdexcept>

#include "derivations/decide/prove.hpp"
#include "derivations/symbolic/inspect.hpp"
#include "derivations/symbolic/printer.hpp"
#include "derivations/kernel/range.hpp"
#include "derivations/kernel/sample.hpp"
#include "derivations/limit_engine/limits.hpp"

namespace dc {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

numeric pow10(long k) { return GiNaC::pow(numeric(10), numeric(k)); }

void collect_syms(const ex& e, GiNaC::exset& out) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) out.insert(e);
  for (std::size_t i = 0; i < e.nops(); ++i) collect_syms(e.op(i), out);
}

// The symbol of f that `s` stands for. A realsymbol/possymbol copied into a GiNaC::symbol
// (e.g. a std::vector<GiNaC::symbol>) is sliced and no longer compares equal to the original;
// such a copy is matched back by name (names are unique within a SymbolTable).
ex resolve_symbol(const GiNaC::symbol& s, const ex& f) {
  GiNaC::exset syms;
  collect_syms(f, syms);
  ex by_name;
  int same_name = 0;
  for (const ex& t : syms) {
    if (t.is_equal(s)) return t;
    if (GiNaC::ex_to<GiNaC::symbol>(t).get_name() == s.get_name()) {
      by_name = t;
      ++same_name;
    }
  }
  if (same_name == 1) return by_name;
  return s;
}

std::string classify_series_failure(const std::string& what) {
  // GiNaC reports Puiseux terms (sqrt(eps)), essential singularities (exp(-1/eps)) and
  // logarithmic branch points as poles or "division by zero" during the expansion.
  // `what` is GiNaC's own message (with its internal function names): not shown to users.
  (void)what;
  return "series in eps failed: the expansion is not a Laurent series in eps (e.g. a Puiseux term sqrt(eps), an "
         "essential singularity exp(-1/eps) or a logarithm)";
}

}  // namespace

namespace {

namespace L = dc::limits;

bool x_constrained(const ex& x, const SymbolTable& ctx) {
  for (const Constraint& c : ctx.constraints())
    if (c.lhs.has(x) || c.rhs.has(x)) return true;
  return false;
}

// Do the assumptions (constraints such as x > 1) that involve x allow x = point + side*eps?
// Checked at a few admissible points of the other symbols: 1 at all of them, 0 at none,
// -1 mixed or not evaluable.
int constraints_allow(const ex& x, const ex& point, int side, const SymbolTable& ctx) {
  std::vector<const Constraint*> mine;
  for (const Constraint& c : ctx.constraints())
    if (c.lhs.has(x) || c.rhs.has(x)) mine.push_back(&c);
  if (mine.empty()) return 1;
  std::vector<ex> exprs{point, x};
  for (const Constraint* c : mine) exprs.push_back(c->lhs - c->rhs);
  detail::PointSampler sampler(exprs, ctx);
  detail::Rng rng(20261207);
  int yes = 0, no = 0;
  for (int attempt = 0; attempt < 12 && yes + no < 4; ++attempt) {
    bool adm = false;
    GiNaC::exmap p = sampler.draw(rng, 0, &adm);
    // admissible for the other symbols: the constraints without x must hold
    bool others = true;
    for (const Constraint& c : ctx.constraints())
      if (!(c.lhs.has(x) || c.rhs.has(x)) && !kernel::holds_at(c, p)) others = false;
    if (!others) continue;
    p[x] = point.subs(p, GiNaC::subs_options::no_pattern) + side * pow10(-40);
    bool all = true;
    for (const Constraint* c : mine) all = all && kernel::holds_at(*c, p);
    (all ? yes : no) += 1;
  }
  if (yes > 0 && no == 0) return 1;
  if (no > 0 && yes == 0) return 0;
  return -1;
}

// Can x approach `point` from `side` inside its declared domain and the assumptions on it?
// 1 yes, 0 no, -1 unknown.
int side_allowed(const ex& x, const ex& point, int side, const SymbolTable& ctx) {
  const int by_assumptions = constraints_allow(x, point, side, ctx);
  if (by_assumptions == 0) return 0;
  const Domain dom = detail::domain_of(x, ctx);
  if (dom.kind == Domain::Kind::Real) return by_assumptions;
  // the conditions "point + side*eps lies inside": v - lo > 0 and/or hi - v > 0
  std::vector<ex> must_be_positive;
  const ex v = point + side * pow10(-40);
  switch (dom.kind) {
    case Domain::Kind::Positive:
    case Domain::Kind::Nonnegative: must_be_positive.push_back(v); break;
    case Domain::Kind::Negative: must_be_positive.push_back(-v); break;
    case Domain::Kind::Interval:
      must_be_positive.push_back(v - dom.lo);
      must_be_positive.push_back(dom.hi - v);
      break;
    default: return 1;
  }
  // (a declared symbol is "real" to GiNaC too, so it is the absence of symbols that counts)
  bool constant = GiNaC::is_a<numeric>(point) || detail::ordered_symbols(point, ctx).empty();
  int verdict = by_assumptions;
  for (const ex& c : must_be_positive) {
    if (constant) {
      kernel::Ball b = kernel::enclose_sign(c, 128, 1 << 12);
      if (b.positive()) continue;
      if (b.negative() || b.exact_zero()) return 0;
      verdict = -1;
    } else {
      if (detail::provably_positive(c, ctx)) continue;
      if (detail::provably_positive(-c, ctx)) return 0;
      verdict = -1;
    }
  }
  if (verdict != -1 || constant) return verdict;
  // A symbolic point: the side is open when the point lies strictly inside the domain on that
  // side (c - eps is in [0, oo) for every small eps when c > 0, whatever c's size): the end it
  // moves away from may be reached, the one it moves toward may not.
  auto inside = [&](const ex& gap, bool strict) {   // gap > 0 (strict) or gap >= 0
    return strict ? detail::provably_positive(gap, ctx) : detail::range_of(gap, ctx).nonnegative();
  };
  switch (dom.kind) {
    case Domain::Kind::Positive:
    case Domain::Kind::Nonnegative: return inside(point, side < 0) ? by_assumptions : -1;
    case Domain::Kind::Negative: return inside(-point, side > 0) ? by_assumptions : -1;
    case Domain::Kind::Interval:
      return inside(point - dom.lo, side < 0) && inside(dom.hi - point, side > 0) ? by_assumptions : -1;
    default: return -1;
  }
}

// "mu -> 0+", "x -> oo"
std::string side_text(const ex& x, const ex& point, int at_infinity, int dir) {
  const std::string name = GiNaC::ex_to<GiNaC::symbol>(x).get_name();
  if (at_infinity) return name + (at_infinity > 0 ? " -> oo" : " -> -oo");
  std::string p = detail::canon_text(point);
  if (GiNaC::is_a<GiNaC::add>(point) || GiNaC::is_a<GiNaC::mul>(point)) p = "(" + p + ")";
  return name + " -> " + p + (dir > 0 ? "+" : "-");
}

std::string outcome_text(const L::LimitOutcome& o, const SymbolTable& ctx) {
  switch (o.kind) {
    case L::LimitOutcome::Kind::Value: return detail::canon_text(o.value);
    case L::LimitOutcome::Kind::PlusInfinity: return "oo";
    case L::LimitOutcome::Kind::MinusInfinity: return "-oo";
    case L::LimitOutcome::Kind::DoesNotExist: return "does not exist";
    case L::LimitOutcome::Kind::NotReal: return "not real";
    case L::LimitOutcome::Kind::Undecided: return "undecided";
  }
  return "";
}

// One side: the algorithm, then the numeric witness. A contradicted value becomes Undecided.
L::LimitOutcome checked_side(const ex& f, const ex& x, const ex& point, int at_infinity, int dir, const SymbolTable& ctx,
                        L::SequenceCheck& check) {
  L::LimitOutcome o = L::one_sided_limit(f, x, point, at_infinity, dir, ctx);
  if (!o.decided_limit()) return o;
  check = L::check_sequence(f, x, point, at_infinity, dir, o, ctx);
  if (check.kind == L::SequenceCheck::Kind::Contradicted) {
    L::LimitOutcome bad;
    bad.kind = L::LimitOutcome::Kind::Undecided;
    bad.reason = "internal inconsistency (please report): " + o.method + " gives " + outcome_text(o, ctx) + " for " +
                 side_text(x, point, at_infinity, dir) + ", but the numeric sequence contradicts it: " + check.note;
    return bad;
  }
  return o;
}

void set_value(LimitResult& r, const L::LimitOutcome& o) {
  r.ok = true;
  r.infinite = o.kind == L::LimitOutcome::Kind::PlusInfinity ? 1 : (o.kind == L::LimitOutcome::Kind::MinusInfinity ? -1 : 0);
  r.value = r.infinite ? ex(0) : o.value;
}

void set_not_ok(LimitResult& r, const L::LimitOutcome& o, const std::string& prefix) {
  r.ok = false;
  r.does_not_exist = o.kind == L::LimitOutcome::Kind::DoesNotExist || o.kind == L::LimitOutcome::Kind::NotReal;
  if (o.kind == L::LimitOutcome::Kind::NotReal)
    r.reason = prefix + "the limit does not exist: f has no real value close to the point (" + o.reason + ")";
  else
    r.reason = prefix + o.reason;
  r.method = o.method;
}

// Are two one-sided finite limits equal (1), different (0), or undecided (-1)?
int same_value(const ex& a, const ex& b, const SymbolTable& ctx) {
  ex diff = a - b;
  try {
    if (GiNaC::normal(diff).is_zero()) return 1;
  } catch (const std::exception&) {
  }
  if (detail::provably_nonzero(diff, ctx)) return 0;
  Verdict v = prove_equal(a, b, ctx);
  if (v.kind == VerdictKind::Proved) return 1;
  if (v.kind == VerdictKind::Refuted && detail::ordered_symbols(diff, ctx).empty()) return 0;
  return -1;
}

}  // namespace

namespace {
LimitResult real_limit(const ex& f, const GiNaC::symbol& x_in, const ex& point, int at_infinity, int dir,
                       const SymbolTable& ctx);
}  // namespace

// An integer variable: only n -> oo or -oo (a sequence). A limit of f over the reals is also
// the sequence's; when f has none over the reals (sin(n*pi)), the sequence may still have one,
// which is not decided.
LimitResult compute_limit(const ex& f, const GiNaC::symbol& x, const ex& point, int at_infinity, int dir,
                          const SymbolTable& ctx) {
  const SymbolInfo* info = ctx.find(x);
  if (!info || !info->domain.integer) return real_limit(f, x, point, at_infinity, dir, ctx);
  LimitResult res;
  if (at_infinity == 0) {
    res.reason = "'" + info->name + "' is an integer: it has limits only at oo or -oo (a sequence), not at a finite point";
    return res;
  }
  res = real_limit(f, x, point, at_infinity, dir, ctx);
  if (!res.ok) {
    res.does_not_exist = false;
    res.reason = "no limit over the real numbers (" + res.reason + "); whether the sequence in the integer " +
                 info->name + " has one is not decided";
  }
  return res;
}

namespace {
LimitResult real_limit(const ex& f, const GiNaC::symbol& x_in, const ex& point, int at_infinity, int dir,
                       const SymbolTable& ctx) {
  LimitResult res;
  res.dir = at_infinity ? 0 : dir;
  const ex x = resolve_symbol(x_in, f);
  if (at_infinity != 0) {
    L::SequenceCheck check;
    L::LimitOutcome o = checked_side(f, x, point, at_infinity, 0, ctx, check);
    if (o.decided_limit()) set_value(res, o);
    else set_not_ok(res, o, "");
    res.method = o.method.empty() ? res.method : o.method;
    res.confirmed_numerically = check.kind == L::SequenceCheck::Kind::Confirmed;
    res.numeric_note = check.note;
    return res;
  }
  std::vector<int> sides;
  for (int s : {+1, -1}) {
    if (dir != 0 && s != dir) continue;
    int a = side_allowed(x, point, s, ctx);
    if (a == -1) {
      res.reason = "cannot tell whether " + x_in.get_name() + " can approach the point from " + (s > 0 ? "above" : "below") +
                   " within its declared domain" + (x_constrained(x, ctx) ? " and the assumptions" : "");
      return res;
    }
    if (a == 1) sides.push_back(s);
  }
  if (sides.empty()) {
    const std::string where = x_constrained(x, ctx) ? " within its declared domain and the assumptions"
                                                    : " within its declared domain";
    res.reason = dir != 0 ? x_in.get_name() + " cannot approach the point from " + (dir > 0 ? "above" : "below") + where
                          : x_in.get_name() + " cannot approach the point from either side" + where;
    return res;
  }
  std::vector<L::LimitOutcome> out;
  std::vector<L::SequenceCheck> checks(sides.size());
  for (std::size_t i = 0; i < sides.size(); ++i)
    out.push_back(checked_side(f, x, point, 0, sides[i], ctx, checks[i]));
  auto from = [](int s) { return std::string(s > 0 ? "from above: " : "from below: "); };
  const std::string xname = GiNaC::ex_to<GiNaC::symbol>(x).get_name();
  const std::string via_domain =
      dir == 0 && sides.size() == 1
          ? " (the only side in the declared domain of " + xname + (x_constrained(x, ctx) ? " and the assumptions)" : ")")
          : "";
  if (sides.size() == 1) {
    const L::LimitOutcome& o = out[0];
    if (o.decided_limit()) set_value(res, o);
    else set_not_ok(res, o, "");
    res.method = o.method + ", " + side_text(x, point, 0, sides[0]) + via_domain;
    res.confirmed_numerically = checks[0].kind == L::SequenceCheck::Kind::Confirmed;
    res.numeric_note = checks[0].note;
    return res;
  }
  // two sides
  const L::LimitOutcome &up = out[0], &down = out[1];
  res.confirmed_numerically = checks[0].kind == L::SequenceCheck::Kind::Confirmed &&
                              checks[1].kind == L::SequenceCheck::Kind::Confirmed;
  res.numeric_note = from(+1) + checks[0].note + "; " + from(-1) + checks[1].note;
  for (std::size_t i = 0; i < 2; ++i)
    if (out[i].kind == L::LimitOutcome::Kind::Undecided) {
      set_not_ok(res, out[i], from(sides[i]));
      return res;
    }
  // f not real on one side: the limit is the other side's (the limit within f's domain)
  for (std::size_t i = 0; i < 2; ++i) {
    const L::LimitOutcome &o = out[i], &other = out[1 - i];
    if (o.kind == L::LimitOutcome::Kind::NotReal && other.kind != L::LimitOutcome::Kind::NotReal) {
      if (other.decided_limit()) set_value(res, other);
      else set_not_ok(res, other, from(sides[1 - i]));
      res.method = other.method + ", " + side_text(x, point, 0, sides[1 - i]) +
                   " (f has no real value on the other side: " + o.reason + ")";
      res.confirmed_numerically = checks[1 - i].kind == L::SequenceCheck::Kind::Confirmed;
      res.numeric_note = checks[1 - i].note;
      return res;
    }
  }
  if (up.kind == L::LimitOutcome::Kind::NotReal) {   // both sides
    set_not_ok(res, up, "");
    return res;
  }
  for (std::size_t i = 0; i < 2; ++i)
    if (out[i].kind == L::LimitOutcome::Kind::DoesNotExist) {
      set_not_ok(res, out[i], from(sides[i]));
      return res;
    }
  const std::string both = up.method == down.method ? up.method : up.method + " / " + down.method;
  auto differ = [&](const std::string& why) {
    res.ok = false;
    res.does_not_exist = true;
    res.method = both + ", one-sided limits";
    res.reason = "the limit does not exist: the one-sided limits differ (" + why + ")";
  };
  if (up.infinite() || down.infinite()) {
    if (up.kind == down.kind) {
      set_value(res, up);
      res.method = both + ", both one-sided limits agree";
    } else {
      differ(outcome_text(up, ctx) + " from above, " + outcome_text(down, ctx) + " from below");
    }
    return res;
  }
  int same = same_value(up.value, down.value, ctx);
  if (same == 1) {
    set_value(res, up);
    res.method = both + ", both one-sided limits agree";
  } else if (same == 0) {
    differ(outcome_text(up, ctx) + " from above, " + outcome_text(down, ctx) + " from below");
  } else {
    res.reason = "the one-sided limits " + outcome_text(up, ctx) + " (from above) and " + outcome_text(down, ctx) +
                 " (from below) could not be compared";
  }
  return res;
}

}  // namespace

LimitResult compute_limit(const ex& f, const GiNaC::symbol& x, const ex& point, int at_infinity,
                          const SymbolTable& ctx) {
  return compute_limit(f, x, point, at_infinity, 0, ctx);
}

ex first_order(const ex& f, const std::vector<GiNaC::symbol>& smalls) {
  // f(0) + sum_i s_i * df/ds_i(0): the same as scaling every s_i by eps, expanding to
  // O(eps^2) and setting eps = 1, without the series machinery.
  GiNaC::lst zero;
  std::vector<ex> xs;
  for (const auto& s : smalls) {
    xs.push_back(resolve_symbol(s, f));
    zero.append(xs.back() == 0);
  }
  try {
    ex res = f.subs(zero);
    for (const ex& s : xs) res += s * GiNaC::diff(f, GiNaC::ex_to<GiNaC::symbol>(s)).subs(zero);
    return res;
  } catch (const std::exception& e) {
    throw std::domain_error(std::string("first_order: the expression is singular when the small "
                                        "quantities are 0 (") + e.what() + ")");
  }
}

namespace {

// f - s = O((x - point)^2) on the side `side` of the point, checked with ball arithmetic at
// h = 10^-8 and 10^-16 (other symbols at an admissible sample point): the remainder must fall
// by at least 10^-14 when h falls by 10^-8 (a remainder of order h or h log h does not). An
// expansion taken from one side (GiNaC expands abs(eps), sqrt(eps^2) for eps > 0) is caught
// on the other. Returns "" when the check passes or cannot be carried out on this side.
std::string check_series_side(const ex& f, const ex& s, const ex& x, const ex& point, int side, const SymbolTable& ctx) {
  detail::PointSampler sampler({f, s, point}, ctx);
  detail::Rng rng(20261123);
  for (int attempt = 0; attempt < 10; ++attempt) {
    bool adm = false;
    GiNaC::exmap p = sampler.draw(rng, 0, &adm);
    if (!adm) continue;
    p.erase(x);
    ex rem[2];
    try {
      const long ks[2] = {8, 16};
      for (int i = 0; i < 2; ++i) {
        GiNaC::exmap q = p;
        q[x] = point.subs(p, GiNaC::subs_options::no_pattern) + side * pow10(-ks[i]);
        // this side must belong to the declared domain and the assumptions
        const ex xv = q[x];
        if (GiNaC::is_a<numeric>(xv) && !detail::domain_of(x, ctx).contains(GiNaC::ex_to<numeric>(xv))) return "";
        for (const Constraint& c : ctx.constraints())
          if (!kernel::holds_at(c, q)) return "";
        rem[i] = GiNaC::abs(f.subs(q, GiNaC::subs_options::no_pattern) - s.subs(q, GiNaC::subs_options::no_pattern));
      }
    } catch (const std::exception&) {
      continue;   // undefined there
    }
    kernel::Ball b = kernel::enclose_sign(rem[1] - pow10(-14) * rem[0], 256, 1 << 14);
    if (b.status != kernel::BallStatus::Value) continue;   // not defined on this side here
    if (b.positive())
      return std::string("the first-order expansion does not hold for x ") + (side > 0 ? ">" : "<") +
             " the point: the remainder is not O((x - point)^2) there (the expansion was taken from the other side; "
             "restrict the declared domain to one side)";
    return "";
  }
  return "";
}

}  // namespace

static std::optional<ex> series_first_order_raw(const ex& f, const ex& x, const ex& point, std::string* reason) {
  try {
    ex f0 = f.subs(x == point);
    ex f1 = GiNaC::diff(f, GiNaC::ex_to<GiNaC::symbol>(x)).subs(x == point);
    return f0 + f1 * (x - point);
  } catch (const std::exception&) {
    // f or f' undefined by plain substitution (0/0): try a series
  }
  GiNaC::possymbol eps("eps");
  try {
    ex s = f.subs(x == point + eps).series(eps == 0, 2);
    const auto& ps = GiNaC::ex_to<GiNaC::pseries>(s);
    if (ps.ldegree(eps) < 0) {
      if (reason) *reason = "f has a pole at the point: no first-order Taylor expansion";
      return std::nullopt;
    }
    ex c0 = GiNaC::normal(ps.coeff(eps, 0)), c1 = GiNaC::normal(ps.coeff(eps, 1));
    if (c0.has(eps) || c1.has(eps)) {
      if (reason) *reason = "the series coefficients depend on eps (a logarithmic term)";
      return std::nullopt;
    }
    return c0 + c1 * (x - point);
  } catch (const std::exception& e) {
    if (reason) *reason = classify_series_failure(e.what());
    return std::nullopt;
  }
}

std::optional<ex> series_first_order(const ex& f, const GiNaC::symbol& x_in, const ex& point, std::string* reason,
                                     const SymbolTable* ctx) {
  const ex x = resolve_symbol(x_in, f);
  auto s = series_first_order_raw(f, x, point, reason);
  if (!s || !ctx) return s;
  // The expansion must hold on every side of the point that the declared domain of x allows.
  const Domain dom = detail::domain_of(x, *ctx);
  for (int side : {+1, -1}) {
    bool allowed = true;
    try {
      ex probe_pt = point + side * pow10(-8);
      if (GiNaC::is_a<numeric>(probe_pt)) allowed = dom.contains(GiNaC::ex_to<numeric>(probe_pt));
    } catch (const std::exception&) {
    }
    if (!allowed) continue;
    std::string why = check_series_side(f, *s, x, point, side, *ctx);
    if (!why.empty()) {
      if (reason) *reason = why;
      return std::nullopt;
    }
  }
  // The expansion above treats the parameters as generic (sqrt(x^2 + a^2) = |a| + ... assumes
  // a != 0, where it is |x|): the remainder must be O((x - point)^2) by the limit algorithm,
  // which decides the signs of coefficients from the declarations.
  if (GiNaC::is_a<GiNaC::symbol>(x)) {
    const Verdict r = remainder_is_big_o(f - *s, GiNaC::ex_to<GiNaC::symbol>(x), point, 0, 0, 2, *ctx);
    if (r.kind != VerdictKind::Proved) {
      if (reason)
        *reason = "the first-order expansion " + detail::canon_text(*s) + " is not shown to leave a remainder O((x - point)^2) "
                  "for every value the declarations allow: " + (r.reason.empty() ? r.detail : r.reason);
      return std::nullopt;
    }
  }
  return s;
}

}  // namespace dc
