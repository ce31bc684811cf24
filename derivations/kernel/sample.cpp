// Sampling points from the declared domain (sample.hpp): exact rationals for each
// symbol, and admissible points for the probe (derivations/kernel/probe.cpp), the limit helper
// and quadrature.
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "derivations/kernel/sample.hpp"

#include <cln/float.h>
#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/real.h>

#include "derivations/kernel/ball.hpp"
#include "derivations/kernel/range.hpp"
#include "derivations/symbolic/printer.hpp"

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

namespace {

numeric floor_of(const numeric& x) { return numeric(cln::floor1(cln::the<cln::cl_R>(x.to_cl_N()))); }

// An integer of an integer domain: of every draw about half lie in [-12, 12] (where a claim
// such as sin(n*pi/2) = 0 or cos(n*pi) = 1 fails at every odd n), the others at magnitudes
// 10^[1, 2] (tier 0), 10^[1, 6] (tier 1) or 10^[1, 30] (tiers 2, 3); intervals: an integer
// inside, near the lower end at tier 2 and the upper end at tier 3.
numeric integer_sample(const Domain& d, Rng& rng, int tier) {
  using K = Domain::Kind;
  if (d.kind == K::Interval) {
    DigitsGuard g(40);
    ex l = d.lo.evalf(), h = d.hi.evalf();
    numeric lo = floor_of(GiNaC::ex_to<numeric>(l)), hi = floor_of(GiNaC::ex_to<numeric>(h)) + 1;
    for (int attempt = 0; attempt < 40; ++attempt) {
      numeric width = hi - lo + 1;
      numeric v;
      const double u = rng.uniform();
      if (tier == 2) v = lo + static_cast<long>(rng.below(3));
      else if (tier == 3) v = hi - static_cast<long>(rng.below(3));
      else if (width < numeric(1000000)) v = lo + static_cast<long>(rng.below(static_cast<std::uint64_t>(width.to_long())));
      else v = lo + floor_of(numeric(u) * width);
      if (d.contains(v)) return v;
    }
    for (numeric v = lo; v <= hi; v += 1)   // a narrow interval: its first integer
      if (d.contains(v)) return v;
    return lo;   // empty (declarations reject it): any integer
  }
  numeric mag;
  if (rng.below(2) == 0) {
    mag = static_cast<long>(rng.below(13));
  } else {
    const double decades = tier >= 2 ? 30.0 : tier == 1 ? 6.0 : 2.0;
    const double x = std::pow(10.0, 1.0 + (decades - 1.0) * rng.uniform());
    mag = x < 9e15 ? numeric(static_cast<long>(std::llround(x))) : floor_of(rational_near(x, x * 1e-6, rng));
  }
  switch (d.kind) {
    case K::Positive: return mag.is_zero() ? numeric(1) : mag;
    case K::Nonnegative: return mag;
    case K::Negative: return mag.is_zero() ? numeric(-1) : -mag;
    default: return rng.below(2) ? -mag : mag;
  }
}

}  // namespace

numeric sample_value(const Domain& d, Rng& rng, int tier) {
  using K = Domain::Kind;
  if (d.integer) return integer_sample(d, rng, tier);
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
    if (doms[i].integer) v = dir > 0 ? floor_of(t) + 1 : -floor_of(-t) - 1;   // the next integer inside
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
    // an integer symbol: the integer nearest to the value drawn, when the domain holds it
    if (v && d.integer) v = floor_of(*v + numeric(1, 2));
    if (!v || (v->is_integer() && !d.integer) || !d.contains(*v)) v = sample_value(d, rng, 0);
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
    if (!kernel::holds_at(*c, p)) {
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

// ---------------------------------------------------------------- random numbers

std::uint64_t Rng::next() {
  // splitmix64 (Steele, Lea, Flood 2014)
  std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double Rng::uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

std::uint64_t Rng::below(std::uint64_t n) { return n == 0 ? 0 : next() % n; }

std::uint64_t hash_text(const std::string& s, std::uint64_t seed) {
  std::uint64_t h = 1469598103934665603ull ^ (seed * 0x9E3779B97F4A7C15ull);
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

namespace {

struct AbstractReplacer : GiNaC::map_function {
  std::uint64_t seed;
  explicit AbstractReplacer(std::uint64_t s) : seed(s) {}
  ex operator()(const ex& e) override {
    if (is_abstract_application(e)) {
      const auto& f = GiNaC::ex_to<GiNaC::function>(e);
      std::string key = f.get_name();
      if (GiNaC::is_a<GiNaC::fderivative>(e)) {
        key += "#D";
        for (unsigned d : GiNaC::ex_to<GiNaC::fderivative>(e).derivatives())
          key += "," + std::to_string(d);
      }
      for (std::size_t i = 0; i < e.nops(); ++i) {
        ex a = (*this)(e.op(i));
        RealValue v = eval_real(a, 50);
        key += "|" + (v.ok ? format_number(v.value, 40) : std::string("?"));
      }
      Rng rng(hash_text(key, seed));
      return sample_value(Domain::real(), rng, false);
    }
    if (e.nops() == 0) return e;
    return e.map(*this);
  }
};

}  // namespace

ex replace_abstract(const ex& e, std::uint64_t seed) {
  if (!has_abstract_application(e)) return e;
  AbstractReplacer r(seed);
  return r(e);
}

// ---------------------------------------------------------------- evaluation

RealValue eval_real(const ex& e, long digits) {
  RealValue r;
  try {
    if (GiNaC::is_a<numeric>(e) && GiNaC::ex_to<numeric>(e).is_rational()) {
      r.ok = true;
      r.exact = true;
      r.value = GiNaC::ex_to<numeric>(e);
      return r;
    }
    DigitsGuard g(digits);
    ex v = e.evalf();
    if (!GiNaC::is_a<numeric>(v)) {
      r.why = "not a number (a symbol without a value or an unevaluable function)";
      return r;
    }
    const numeric& n = GiNaC::ex_to<numeric>(v);
    if (n.is_real()) {
      r.ok = true;
      r.exact = n.is_rational();
      r.value = n;
      return r;
    }
    numeric re = n.real(), im = n.imag();
    if (GiNaC::abs(im) <= GiNaC::abs(re) * pow10(static_cast<int>(-(digits - 10)))) {
      r.ok = true;
      r.value = re;
      return r;
    }
    r.why = "not real";
  } catch (const std::exception&) {
    r.why = "undefined (division by zero or a pole)";
  }
  return r;
}

namespace {

constexpr long kMaxExactPowerDigits = 1000000;

// Throws where GiNaC::pow(b, x) would throw (0^0, 0^(negative)) or would compute an exact
// power of more than kMaxExactPowerDigits digits: GiNaC computes c^q exactly for the integer
// part q of the exponent, which has about q * log10(max(|num c|, den c)) digits.
void check_exact_power(const ex& b, const ex& x) {
  if (!GiNaC::is_a<numeric>(b) || !GiNaC::is_a<numeric>(x)) return;
  const numeric& nb = GiNaC::ex_to<numeric>(b);
  const numeric& nx = GiNaC::ex_to<numeric>(x);
  if (nb.is_zero()) {
    if (nx.is_zero()) throw std::domain_error("0^0 is undefined");
    if (!nx.real().is_positive()) throw GiNaC::pole_error("division by zero", 1);
    return;
  }
  // A float exponent of astronomic size (10^(10^12), from a tower of powers at a sample point):
  // GiNaC asks CLN whether it is an integer by rounding it to one, an exact integer of that many
  // bits (855 GB).
  if (nx.is_real() && !nx.is_rational()) {
    cln::cl_F f = cln::the<cln::cl_F>(cln::the<cln::cl_R>(nx.to_cl_N()));
    if (!cln::zerop(f) && cln::float_exponent(f) > (1L << 22))
      throw std::range_error("a power with an exponent of more than a million digits cannot be evaluated at this point");
  }
  if (!nb.is_rational() || !nx.is_rational() || GiNaC::abs(nb) == 1) return;
  long bits = std::max(cln::integer_length(cln::the<cln::cl_I>(nb.numer().to_cl_N())),
                       cln::integer_length(cln::the<cln::cl_I>(nb.denom().to_cl_N())));
  if (GiNaC::abs(nx) * numeric(bits) * numeric(30103, 100000) > numeric(kMaxExactPowerDigits))
    throw std::range_error("an exact power at this point would have more than a million digits");
}

struct PointSubs : GiNaC::map_function {
  const GiNaC::exmap& p;
  explicit PointSubs(const GiNaC::exmap& m) : p(m) {}
  ex operator()(const ex& e) override {
    if (GiNaC::is_a<GiNaC::power>(e)) {
      ex b = (*this)(e.op(0));
      ex x = (*this)(e.op(1));
      check_exact_power(b, x);
      return GiNaC::pow(b, x);
    }
    if (e.nops() == 0) return e.subs(p, GiNaC::subs_options::no_pattern);
    return e.map(*this);
  }
};

}  // namespace

ex subs_point(const ex& e, const GiNaC::exmap& p) {
  PointSubs f(p);
  return f(e);
}

}  // namespace dc::detail

namespace dc::kernel {

bool holds_at(const Constraint& c, const GiNaC::exmap& point) {
  // The sign of lhs - rhs at the point, certified by ball arithmetic (exact for rationals; the
  // point's values are read during the evaluation, never substituted, so no exact power is
  // expanded); a point where it cannot be certified is not admissible.
  int s;
  Ball b = enclose_sign_at(c.lhs - c.rhs, &point, 128, 1 << 14);
  if (b.positive()) s = 1;
  else if (b.negative()) s = -1;
  else if (b.exact_zero()) s = 0;
  else return false;
  return sign_satisfies(c.op, s);
}

}  // namespace dc::kernel
