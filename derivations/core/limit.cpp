// Limits and first-order expansions (GiNaC has no limit()); see limit.hpp.
#include "derivations/core/limit.hpp"

#include "derivations/kernel/ball.hpp"

#include <sstream>
#include <stdexcept>

#include "derivations/core/prove.hpp"
#include "derivations/core/prove_detail.hpp"

namespace dc {

using GiNaC::ex;
using GiNaC::numeric;
namespace d = detail;

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

// Confirm numerically that f -> L (or diverges with sign `inf`) along x = point +- 10^-k, or
// x = +-10^k at infinity, at a random admissible point of the other symbols (50 digits).
// Returns "" when confirmed, "?" when nothing could be evaluated, else the reason it failed.
std::string confirm_numerically(const ex& f, const ex& x, const ex& point, int at_infinity,
                                const ex& L, int inf, const SymbolTable& ctx) {
  d::PointSampler sampler({f}, ctx);
  d::Rng rng(20261121);
  const long ks[] = {8, 16, 24, 32};
  for (int attempt = 0; attempt < 30; ++attempt) {
    bool adm = false;
    GiNaC::exmap p = sampler.draw(rng, false, &adm);
    if (!adm) continue;
    p.erase(x);
    ex fp, Lp;
    try {
      fp = d::subs_point(f, p);
      Lp = d::subs_point(L, p);
    } catch (const std::exception&) {
      continue;
    }
    d::RealValue lv;
    if (inf == 0) {
      lv = d::eval_real(Lp, 50);
      if (!lv.ok) continue;
    }
    bool any_side = false;
    for (int side : {+1, -1}) {
      if (at_infinity != 0 && side == -1) break;
      std::vector<numeric> errs, vals;
      bool ok = true;
      for (long k : ks) {
        ex xv = at_infinity != 0 ? ex(at_infinity * pow10(k)) : point + side * pow10(-k);
        d::RealValue fv;
        try {
          fv = d::eval_real(d::subs_point(fp, GiNaC::exmap{{x, xv}}), 50);
        } catch (const std::exception&) {
          fv.ok = false;
        }
        if (!fv.ok) {
          ok = false;
          break;
        }
        vals.push_back(fv.value);
        if (inf == 0) {
          numeric scale = std::max(numeric(1), GiNaC::abs(lv.value));
          errs.push_back(GiNaC::abs(fv.value - lv.value) / scale);
        }
      }
      if (!ok) continue;  // not defined on this side (e.g. sqrt left of 0)
      any_side = true;
      std::string at = at_infinity != 0 ? (at_infinity > 0 ? "x = 1e32" : "x = -1e32")
                                        : (side > 0 ? "x = point + 1e-32" : "x = point - 1e-32");
      if (inf == 0) {
        if (!(errs.back() < numeric(1, 1000000)) || errs.back() > errs.front())
          return "the value is not confirmed numerically: relative distance " +
                 d::format_number(errs.back(), 6) + " at " + at;
      } else {
        const numeric& last = vals.back();
        bool sign_ok = inf > 0 ? last.is_positive() : last.is_negative();
        if (!sign_ok || GiNaC::abs(last) < GiNaC::abs(vals.front()) || GiNaC::abs(last) < 1000000)
          return std::string("divergence to ") + (inf > 0 ? "+" : "-") +
                 "infinity is not confirmed numerically at " + at;
      }
    }
    if (any_side) return "";
  }
  return "?";
}

}  // namespace

LimitResult compute_limit(const ex& f, const GiNaC::symbol& x_in, const ex& point, int at_infinity,
                          const SymbolTable& ctx) {
  LimitResult res;
  const ex x = resolve_symbol(x_in, f);
  bool have = false;
  // 1. direct substitution (a finite point where f is defined: no pole is hit)
  if (at_infinity == 0) {
    try {
      ex v = f.subs(x == point);
      if (!v.has(x)) {
        res.value = v;
        res.method = "substitution";
        have = true;
      }
    } catch (const std::exception&) {
      // a pole or 0/0 at the point: fall through to the series
    }
  }
  // 2. series in eps, x = point + eps or x = +-1/eps
  if (!have) {
    GiNaC::possymbol eps("eps");
    ex g;
    try {
      g = at_infinity != 0 ? f.subs(x == at_infinity / ex(eps)) : f.subs(x == point + eps);
    } catch (const std::exception& e) {
      res.reason = std::string("substitution failed: ") + e.what();
      return res;
    }
    bool found = false;
    for (int n : {1, 2, 3, 4, 6, 8, 12}) {
      ex s;
      try {
        s = g.series(eps == 0, n);
      } catch (const std::exception& e) {
        res.reason = classify_series_failure(e.what());
        return res;
      }
      if (!GiNaC::is_a<GiNaC::pseries>(s)) {
        res.reason = "series in eps did not produce a power series";
        return res;
      }
      const auto& ps = GiNaC::ex_to<GiNaC::pseries>(s);
      int lo = ps.ldegree(eps);
      // the last exponent of a truncated series is the Order term, not a coefficient
      int hi = ps.is_terminating() ? ps.degree(eps) : ps.degree(eps) - 1;
      for (int k = lo; k <= hi; ++k) {
        ex c;
        try {
          c = GiNaC::normal(ps.coeff(eps, k));
        } catch (const std::exception&) {
          continue;
        }
        if (c.is_zero()) continue;
        if (c.has(eps)) {
          res.reason = "the leading coefficient of the series depends on eps (a logarithmic term such as eps*log(eps))";
          return res;
        }
        found = true;
        if (k > 0) {
          res.value = 0;
        } else if (k == 0) {
          res.value = c;
        } else {
          bool pos = d::provably_positive(c, ctx), neg = d::provably_positive(-c, ctx);
          if (!pos && !neg) {
            res.reason = "f diverges like eps^" + std::to_string(k) +
                         " but the sign of its coefficient is not evident from the domains";
            return res;
          }
          if (at_infinity == 0 && (-k) % 2 == 1) {
            res.reason = "f has a pole of odd order at the point: the one-sided limits are +infinity and -infinity";
            return res;
          }
          res.infinite = pos ? 1 : -1;
          res.value = 0;
        }
        break;
      }
      if (found) break;
    }
    if (!found) {
      res.reason = "every coefficient up to eps^11 vanishes: the limit could not be determined";
      return res;
    }
    res.method = at_infinity != 0 ? "series at 0 of eps = 1/x" : "series";
  }
  // 3. numeric confirmation along a sequence approaching the point
  std::string why = confirm_numerically(f, x, point, at_infinity, res.value, res.infinite, ctx);
  if (why.empty()) {
    res.confirmed_numerically = true;
  } else if (why != "?") {
    res.ok = false;
    res.reason = why;
    return res;
  }
  res.ok = true;
  return res;
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
  d::PointSampler sampler({f, s, point}, ctx);
  d::Rng rng(20261123);
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
        q[x] = d::subs_point(point, p) + side * pow10(-ks[i]);
        // this side must belong to the declared domain and the assumptions
        const ex xv = q[x];
        if (GiNaC::is_a<numeric>(xv) && !d::domain_of(x, ctx).contains(GiNaC::ex_to<numeric>(xv))) return "";
        for (const Constraint& c : ctx.constraints())
          if (!c.holds_at(q)) return "";
        rem[i] = GiNaC::abs(d::subs_point(f, q) - d::subs_point(s, q));
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
  const Domain dom = d::domain_of(x, *ctx);
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
  return s;
}

}  // namespace dc
