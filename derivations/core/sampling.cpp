// Sampling points from the declared domain (prove_detail.hpp): exact rationals for each
// symbol, and admissible points for the probe (derivations/kernel/probe.cpp), the limit helper
// and quadrature.
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "derivations/core/prove.hpp"
#include "derivations/core/prove_detail.hpp"

namespace dc::detail {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

double to_double_approx(const ex& e) {
  DigitsGuard g(30);
  ex v = e.evalf();
  if (!GiNaC::is_a<numeric>(v)) return std::nan("");
  const numeric& n = GiNaC::ex_to<numeric>(v);
  if (!n.is_real()) return std::nan("");
  return n.to_double();
}

}  // namespace

numeric rational_near(double x, double resolution, Rng& rng) {
  long long den0 = 1009 + static_cast<long long>(rng.below(98983));  // [1009, 99991]
  int k = 0;
  while (static_cast<double>(den0) * std::pow(10.0, k) * resolution < 1000.0 && k < 40) ++k;
  double scale = static_cast<double>(den0) * std::pow(10.0, k);
  double nx = x * scale;
  numeric num;
  if (std::fabs(nx) < 9e15) {
    num = numeric(static_cast<long>(std::llround(nx)));
  } else {
    // beyond double's integer range: round via text of the scaled value (rare: huge bounds)
    std::ostringstream os;
    os.precision(0);
    os << std::fixed << nx;
    num = numeric(os.str().c_str());
  }
  numeric den = numeric(den0) * pow10(k);
  if (num.is_zero()) num = 1;
  numeric q = num / den;
  if (q.is_integer()) q = (num + 1) / den;
  return q;
}


std::optional<LinearBound> linear_bound(const Constraint& c, const ex& s, const GiNaC::exmap& p,
                                        const std::function<std::optional<numeric>(const ex&)>& value) {
  const GiNaC::symbol& sym = GiNaC::ex_to<GiNaC::symbol>(s);
  ex a, b;
  try {
    ex d = (c.lhs - c.rhs).expand();
    if (!d.has(sym) || !d.is_polynomial(sym) || d.degree(sym) != 1) return std::nullopt;
    GiNaC::exmap others = p;
    others.erase(s);
    a = subs_point(d.coeff(sym, 1), others);
    b = subs_point(d.coeff(sym, 0), others);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  auto av = value(a), bv = value(b);
  if (!av || !bv || av->is_zero()) return std::nullopt;
  return LinearBound{-*bv / *av, av->is_positive() ? c.op : flipped(c.op)};
}

numeric sample_value(const Domain& d, Rng& rng, int tier) {
  using K = Domain::Kind;
  const bool wide = tier > 0;
  if (d.kind != K::Interval) {
    double decades = tier >= 2 ? 30.0 : tier == 1 ? 6.0 : 2.0;
    double u = -decades + 2 * decades * rng.uniform();
    double mag = std::pow(10.0, u);
    int sign = 1;
    if (d.kind == K::Real) sign = rng.below(2) ? -1 : 1;
    if (d.kind == K::Negative) sign = -1;
    return rational_near(sign * mag, mag, rng);
  }
  double lo = to_double_approx(d.lo), hi = to_double_approx(d.hi);
  if (!(hi > lo)) {
    // a single point [a, a]
    if (GiNaC::is_a<numeric>(d.lo)) return GiNaC::ex_to<numeric>(d.lo);
    return rational_near(lo, std::max(1e-12, std::fabs(lo) * 1e-12), rng);
  }
  double width = hi - lo;
  for (int attempt = 0; attempt < 30; ++attempt) {
    double t = tier == 2   ? 1e-9 * (1 + rng.uniform())
               : tier >= 3 ? 1 - 1e-9 * (1 + rng.uniform())
               : wide     ? 1e-6 + (1 - 2e-6) * rng.uniform()
                          : 0.02 + 0.96 * rng.uniform();
    double x = lo + t * width;
    numeric q = rational_near(x, width * std::min(1e-2, std::min(t, 1 - t)), rng);
    if (q == 1 || q == -1) continue;
    if (d.contains(q)) return q;
  }
  // Degenerate tiny interval: the exact midpoint when both ends are rational.
  if (GiNaC::is_a<numeric>(d.lo) && GiNaC::is_a<numeric>(d.hi))
    return (GiNaC::ex_to<numeric>(d.lo) + GiNaC::ex_to<numeric>(d.hi)) / 2;
  return rational_near(lo + width / 2, width * 1e-3, rng);
}

PointSampler::PointSampler(const std::vector<ex>& exprs, const SymbolTable& ctx) {
  GiNaC::exset set;
  for (const ex& e : exprs) collect_symbols(e, set);
  const auto& all = ctx.constraints();
  std::vector<bool> used(all.size(), false);
  bool changed = true;
  while (changed) {
    changed = false;
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (used[i]) continue;
      GiNaC::exset cs;
      collect_symbols(all[i].lhs - all[i].rhs, cs);
      bool touches = false;
      for (const ex& s : cs)
        if (set.count(s)) touches = true;
      if (touches) {
        used[i] = true;
        changed = true;
        for (const ex& s : cs) set.insert(s);
      }
    }
  }
  GiNaC::lst l;
  for (const ex& s : set) l.append(s);
  syms_ = ordered_symbols(l, ctx);
  for (const auto& s : syms_) doms_.push_back(domain_of(s, ctx));
  for (std::size_t i = 0; i < all.size(); ++i)
    if (used[i]) cons_.push_back(&all[i]);
}

namespace {

std::optional<numeric> exact_value(const ex& e) {
  if (GiNaC::is_a<numeric>(e) && GiNaC::ex_to<numeric>(e).is_rational()) return GiNaC::ex_to<numeric>(e);
  return std::nullopt;
}

// Move one symbol of the constraint c (linear in it, with the other symbols at their values in
// p) just inside the constraint's boundary: value t + dir * |t| * 10^[-15, -1] (or an absolute
// 10^[-30, -1] when t = 0). Claims that fail only in a thin slice the assumption leaves open
// (x > 1 - 1e-9 with abs(x - 1) = x - 1) are found there.
void move_to_boundary(const Constraint& c, const std::vector<ex>& syms, const std::vector<Domain>& doms,
                      GiNaC::exmap& p, Rng& rng) {
  using Op = Constraint::Op;
  for (std::size_t i = 0; i < syms.size(); ++i) {
    auto bound = linear_bound(c, syms[i], p, exact_value);
    if (!bound) continue;
    const numeric& t = bound->at;
    // the side of the boundary where the constraint holds
    int dir = (bound->op == Op::Gt || bound->op == Op::Ge) ? 1
              : (bound->op == Op::Lt || bound->op == Op::Le) ? -1
                                                             : (rng.below(2) ? 1 : -1);
    double e = t.is_zero() ? -30.0 + 29.0 * rng.uniform() : -15.0 + 14.0 * rng.uniform();
    numeric off = rational_near(std::pow(10.0, e), std::pow(10.0, e) * 1e-3, rng);
    if (!t.is_zero()) off *= GiNaC::abs(t);
    numeric v = t + dir * off;
    if (!doms[i].contains(v)) continue;
    p[syms[i]] = v;
    return;
  }
}

// A value inside the interval (lo, hi) that a symbol's domain `d` and the assumptions leave it
// (either end may be missing; nullopt when both are): just inside one end, between an end and 0
// (the values of the other sign that the end allows: y in (-1, 0) for y > -1), near 0 from
// either side when the interval contains it, or an ordinary point: an ordinary draw from the
// domain (sample_value, tier 0) that falls inside, so that inside the interval the points are
// spread as the other draws are (a claim false on part of (1, 3) is met as often).
std::optional<numeric> value_between(const std::optional<numeric>& lo, const std::optional<numeric>& hi,
                                     const Domain& d, Rng& rng) {
  auto magnitude = [&](double lo_exp, double hi_exp) {   // an exact rational in 10^[lo_exp, hi_exp]
    double x = std::pow(10.0, lo_exp + (hi_exp - lo_exp) * rng.uniform());
    return rational_near(x, x * 1e-3, rng);
  };
  auto fraction = [&] { return rational_near(0.02 + 0.96 * rng.uniform(), 1e-4, rng); };   // in (0, 1)
  auto ordinary = [&](const numeric& fallback) {
    for (int k = 0; k < 16; ++k) {
      numeric v = sample_value(d, rng, 0);
      if ((!lo || v > *lo) && (!hi || v < *hi)) return v;
    }
    return fallback;
  };
  if (lo && hi) {
    numeric w = *hi - *lo;
    switch (rng.below(4)) {
      case 0: return *lo + w * magnitude(-15, -1);
      case 1: return *hi - w * magnitude(-15, -1);
      case 2:
        if (lo->is_negative() && hi->is_positive()) {
          numeric m = std::min(-*lo, *hi) * magnitude(-15, -1);
          return rng.below(2) ? m : -m;
        }
        [[fallthrough]];
      default: return ordinary(*lo + w * fraction());
    }
  }
  if (!lo && !hi) return std::nullopt;
  const numeric end = lo ? *lo : *hi;
  const int inward = lo ? 1 : -1;
  const numeric scale = end.is_zero() ? numeric(1) : GiNaC::abs(end);
  switch (rng.below(3)) {
    case 0: return end + inward * scale * magnitude(-15, -1);
    case 1:
      if (lo ? end.is_negative() : end.is_positive()) return end * fraction();
      [[fallthrough]];
    default: return ordinary(end + inward * magnitude(-2, 2));
  }
}

// Tier 5: the symbols one after another, each drawn inside the interval that its domain and the
// assumptions linear in it leave once the symbols drawn before it have their values; the next
// symbol is the one most assumptions bound at that moment (x > y, y > -1: y in (-1, oo) first,
// then x in (y, oo)), so a chain of assumptions is followed to its ends and across 0.
GiNaC::exmap draw_within(const std::vector<ex>& syms, const std::vector<Domain>& doms,
                         const std::vector<const Constraint*>& cons, Rng& rng) {
  using Op = Constraint::Op;
  GiNaC::exmap p;
  std::vector<bool> done(syms.size(), false);
  for (std::size_t step = 0; step < syms.size(); ++step) {
    std::vector<std::vector<LinearBound>> bounds(syms.size());
    std::vector<std::size_t> best;
    std::size_t most = 0;
    for (std::size_t i = 0; i < syms.size(); ++i) {
      if (done[i]) continue;
      for (const Constraint* c : cons)
        if (auto b = linear_bound(*c, syms[i], p, exact_value); b && b->op != Op::Ne) bounds[i].push_back(*b);
      if (best.empty() || bounds[i].size() > most) best.clear(), most = bounds[i].size();
      if (bounds[i].size() == most) best.push_back(i);
    }
    const std::size_t i = best[rng.below(best.size())];
    done[i] = true;
    std::optional<numeric> lo, hi;
    const Domain& d = doms[i];
    if (d.kind == Domain::Kind::Positive || d.kind == Domain::Kind::Nonnegative) lo = numeric(0);
    if (d.kind == Domain::Kind::Negative) hi = numeric(0);
    if (d.kind == Domain::Kind::Interval) {
      if (auto v = exact_value(d.lo)) lo = *v;
      if (auto v = exact_value(d.hi)) hi = *v;
    }
    for (const auto& b : bounds[i]) {
      if ((b.op == Op::Gt || b.op == Op::Ge) && (!lo || b.at > *lo)) lo = b.at;
      if ((b.op == Op::Lt || b.op == Op::Le) && (!hi || b.at < *hi)) hi = b.at;
    }
    std::optional<numeric> v;
    if (!(lo && hi && *lo >= *hi)) v = value_between(lo, hi, d, rng);
    if (!v || v->is_integer() || !d.contains(*v)) v = sample_value(d, rng, 0);
    p[syms[i]] = *v;
  }
  return p;
}

}  // namespace

GiNaC::exmap PointSampler::draw(Rng& rng, int tier, bool* admissible) const {
  GiNaC::exmap p;
  if (tier == 5 && !cons_.empty()) {
    p = draw_within(syms_, doms_, cons_, rng);
  } else {
    // tier 4: an ordinary point moved to the boundary of one of the assumptions; tier 5 without
    // assumptions: an ordinary point
    int base = tier >= 4 ? 0 : tier;
    for (std::size_t i = 0; i < syms_.size(); ++i) p[syms_[i]] = sample_value(doms_[i], rng, base);
    if (tier == 4 && !cons_.empty()) move_to_boundary(*cons_[rng.below(cons_.size())], syms_, doms_, p, rng);
  }
  bool ok = true;
  for (const Constraint* c : cons_)
    if (!c->holds_at(p)) {
      ok = false;
      break;
    }
  if (admissible) *admissible = ok;
  return p;
}

std::vector<std::pair<std::string, std::string>> PointSampler::describe(const GiNaC::exmap& p) const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& s : syms_) {
    auto it = p.find(s);
    if (it == p.end()) continue;
    out.push_back({GiNaC::ex_to<GiNaC::symbol>(s).get_name(), exact_text(GiNaC::ex_to<numeric>(it->second))});
  }
  return out;
}

std::string join_point(const std::vector<std::pair<std::string, std::string>>& pt) {
  std::string s;
  for (std::size_t i = 0; i < pt.size(); ++i) {
    if (i) s += ", ";
    s += pt[i].first + " = " + pt[i].second;
  }
  return s;
}

}  // namespace dc::detail
