// Truncated generalized power series in w; see wseries.hpp.
#include "derivations/limit_engine/wseries.hpp"

#include <string>

namespace dc::limits {

using GiNaC::ex;
using GiNaC::numeric;

std::size_t tree_size(const ex& e, std::size_t cap) {
  std::size_t n = 1;
  for (std::size_t i = 0; i < e.nops() && n <= cap; ++i) n += tree_size(e.op(i), cap - n + 1);
  return n;
}

ex pooled_symbol(const std::string& stem, std::size_t index) {
  static std::map<std::string, std::vector<ex>> pool;
  std::vector<ex>& v = pool[stem];
  while (v.size() <= index) v.push_back(GiNaC::possymbol(stem + (v.empty() ? "" : std::to_string(v.size()))));
  return v[index];
}

SeriesExpander::SeriesExpander(Oracle& oracle, const ex& w, const ex& x, const ex& logw, long relative_order)
    : o_(oracle), w_(w), x_(x), logw_(logw), rel_(relative_order) {}

int SeriesExpander::cmp(const ex& a, const ex& b) {
  if (GiNaC::is_a<numeric>(a) && GiNaC::is_a<numeric>(b)) {
    const numeric &p = GiNaC::ex_to<numeric>(a), &q = GiNaC::ex_to<numeric>(b);
    if (p.is_real() && q.is_real()) return p < q ? -1 : (q < p ? 1 : 0);
  }
  return o_.compare_exponents(a, b);
}

ex SeriesExpander::min_order(const ex& a, const ex& b) { return cmp(a, b) <= 0 ? a : b; }

void SeriesExpander::insert_term(std::vector<Term>& v, const ex& e, const ex& c) {
  if (c.is_zero()) return;
  std::size_t lo = 0, hi = v.size();
  while (lo < hi) {
    std::size_t mid = (lo + hi) / 2;
    int k = cmp(v[mid].exp, e);
    if (k == 0) {
      v[mid].coeff = v[mid].coeff + c;
      if (v[mid].coeff.is_zero()) v.erase(v.begin() + static_cast<long>(mid));
      return;
    }
    if (k < 0) lo = mid + 1;
    else hi = mid;
  }
  v.insert(v.begin() + static_cast<long>(lo), Term{e, c});
}

// Keep rel_ units of exponent beyond the first term (relative truncation: w^-100 (1 + w)^100
// needs no term beyond w^(-100 + rel_)); drop terms beyond the order; keep coefficients small.
WSeries SeriesExpander::finish(WSeries s) {
  Budget& b = o_.budget();
  b.tick("series");
  bool dropped = false;
  std::vector<Term> kept;
  ex cut;
  for (auto& t : s.terms) {
    if (!s.exact && cmp(t.exp, s.order) >= 0) continue;
    if (kept.empty() && !dropped) cut = t.exp + rel_;
    else if (cmp(t.exp, cut) >= 0) {
      dropped = true;
      continue;
    }
    if (tree_size(t.coeff, b.max_coeff_nodes) > b.max_coeff_nodes / 3) {
      t.coeff = GiNaC::normal(t.coeff);
      if (tree_size(t.coeff, b.max_coeff_nodes) > b.max_coeff_nodes)
        throw BudgetExceeded("a series coefficient grew beyond " + std::to_string(b.max_coeff_nodes) + " nodes");
    }
    if (t.coeff.is_zero()) continue;
    kept.push_back(std::move(t));
  }
  s.terms = std::move(kept);
  if (static_cast<int>(s.terms.size()) > b.max_terms_per_series)
    throw BudgetExceeded("a series with more than " + std::to_string(b.max_terms_per_series) + " terms");
  if (dropped) {
    s.order = s.exact ? cut : min_order(s.order, cut);
    s.exact = false;
  }
  return s;
}

ex SeriesExpander::low_valuation(const WSeries& s) { return s.terms.empty() ? s.order : s.terms[0].exp; }

bool SeriesExpander::settle_lead(WSeries& s) {
  while (!s.terms.empty()) {
    if (!o_.coefficient_is_zero(s.terms[0].coeff)) return true;
    s.terms.erase(s.terms.begin());
  }
  if (s.exact) return false;
  throw NeedMoreTerms();
}

WSeries SeriesExpander::add(const WSeries& a, const WSeries& b) {
  WSeries r;
  r.exact = a.exact && b.exact;
  if (!r.exact) r.order = a.exact ? b.order : (b.exact ? a.order : min_order(a.order, b.order));
  r.terms = a.terms;
  for (const auto& t : b.terms) insert_term(r.terms, t.exp, t.coeff);
  return finish(std::move(r));
}

WSeries SeriesExpander::mul(const WSeries& a, const WSeries& b) {
  if ((a.exact && a.terms.empty()) || (b.exact && b.terms.empty())) return WSeries::zero();
  WSeries r;
  r.exact = a.exact && b.exact;
  if (!r.exact) {
    if (!a.exact && !b.exact) r.order = min_order(a.order + low_valuation(b), b.order + low_valuation(a));
    else if (!a.exact) r.order = a.order + low_valuation(b);
    else r.order = b.order + low_valuation(a);
  }
  // products beyond rel_ past the leading product are dropped by finish() anyway
  const bool bounded = !a.terms.empty() && !b.terms.empty();
  const ex cut = bounded ? a.terms[0].exp + b.terms[0].exp + rel_ : ex(0);
  bool dropped = false;
  for (const auto& ta : a.terms)
    for (const auto& tb : b.terms) {
      ex e = ta.exp + tb.exp;
      if (!r.exact && cmp(e, r.order) >= 0) continue;
      if (bounded && cmp(e, cut) >= 0) {
        dropped = true;
        continue;
      }
      insert_term(r.terms, e, ta.coeff * tb.coeff);
    }
  if (dropped) {
    r.order = r.exact ? cut : min_order(r.order, cut);
    r.exact = false;
  }
  return finish(std::move(r));
}

WSeries SeriesExpander::scale(const WSeries& a, const ex& c, const ex& e) {
  WSeries r;
  r.exact = a.exact;
  if (!a.exact) r.order = a.order + e;
  if (!c.is_zero())
    for (const auto& t : a.terms) r.terms.push_back({t.exp + e, t.coeff * c});
  return r;
}

WSeries SeriesExpander::compose(const std::function<ex(int)>& d, const WSeries& r) {
  Budget& b = o_.budget();
  const ex d0 = d(0);
  WSeries result = finish(WSeries::monomial(d0, 0));
  if (r.exact && r.terms.empty()) return result;
  const ex v = low_valuation(r);   // > 0
  // the result starts at w^0 (d0 != 0) or at w^v: terms up to rel_ beyond that are kept
  const ex bound = (d0.is_zero() ? v : ex(0)) + rel_;
  WSeries p = WSeries::monomial(1, 0);
  for (int k = 1;; ++k) {
    if (k > b.max_terms_per_series)
      throw BudgetExceeded("a composed series needs more than " + std::to_string(b.max_terms_per_series) + " terms");
    p = mul(p, r);
    if (p.exact && p.terms.empty()) break;
    const ex pv = low_valuation(p);
    if (cmp(pv, bound) >= 0) {   // this and every further power: O(w^pv)
      WSeries rest;
      rest.order = pv;
      result = add(result, rest);
      break;
    }
    result = add(result, scale(p, d(k), 0));
  }
  return result;
}

WSeries SeriesExpander::split_lead(const WSeries& s, ex& c0, ex& e0) {
  c0 = s.terms[0].coeff;
  e0 = s.terms[0].exp;
  WSeries r;
  r.exact = s.exact;
  if (!s.exact) r.order = s.order - e0;
  for (std::size_t i = 1; i < s.terms.size(); ++i) r.terms.push_back({s.terms[i].exp - e0, s.terms[i].coeff / c0});
  return r;
}

WSeries SeriesExpander::inverse(WSeries s) {
  if (!settle_lead(s)) throw Undecided("a division by an expression that vanishes identically near the point");
  // 1/s divides by the leading coefficient, so it must be nonzero for every parameter value the
  // declarations allow, not only generically: (a*x + 1)/(a*x + 2) -> 1 as x -> oo holds for
  // a != 0 only. Deciding its sign shows that (eventual_sign throws when the declarations do
  // not determine it).
  if (o_.eventual_sign(s.terms[0].coeff) == 0)
    throw Undecided("a division by an expression whose leading coefficient vanishes");
  ex c0, e0;
  WSeries r = split_lead(s, c0, e0);
  WSeries g = compose([](int k) { return ex(k % 2 ? -1 : 1); }, r);
  return finish(scale(g, 1 / c0, -e0));
}

WSeries SeriesExpander::power(WSeries s, const ex& p) {
  if (GiNaC::is_a<numeric>(p) && GiNaC::ex_to<numeric>(p).is_integer()) {
    numeric n = GiNaC::ex_to<numeric>(p);
    if (n.is_zero()) return WSeries::monomial(1, 0);
    if (n.is_negative()) {
      s = inverse(std::move(s));
      n = -n;
    }
    if (n > 100000) throw BudgetExceeded("an integer power above 100000");
    long k = n.to_long();
    WSeries result = WSeries::monomial(1, 0), base = s;
    while (k > 0) {
      if (k & 1) result = mul(result, base);
      k >>= 1;
      if (k) base = mul(base, base);
    }
    return result;
  }
  if (!settle_lead(s)) {
    if (o_.eventual_sign(p) > 0) return WSeries::zero();
    throw Undecided("a non-positive power of an expression that vanishes identically near the point");
  }
  ex c0, e0;
  WSeries r = split_lead(s, c0, e0);
  if (o_.eventual_sign(c0) < 0)
    throw NotRealNear("a fractional power of a quantity that is negative near the point");
  std::vector<ex> binom{1};
  auto d = [&](int k) {
    while (static_cast<int>(binom.size()) <= k) {
      int j = static_cast<int>(binom.size());
      binom.push_back(binom.back() * (p - (j - 1)) / j);
    }
    return binom[static_cast<std::size_t>(k)];
  };
  WSeries g = compose(d, r);
  return finish(scale(g, GiNaC::pow(c0, p), e0 * p));
}

WSeries SeriesExpander::exp_of(WSeries s) {
  while (!s.terms.empty() && cmp(s.terms[0].exp, 0) < 0) {
    if (!o_.coefficient_is_zero(s.terms[0].coeff))
      throw Undecided("internal: the exponential of a divergent series in w (the rewriting should have removed it)");
    s.terms.erase(s.terms.begin());
  }
  if (!s.exact && cmp(s.order, 0) <= 0) throw NeedMoreTerms();
  ex c = 0;
  if (!s.terms.empty() && cmp(s.terms[0].exp, 0) == 0) {
    c = s.terms[0].coeff;
    s.terms.erase(s.terms.begin());
  }
  std::vector<ex> inv_fact{1};
  auto d = [&](int k) {
    while (static_cast<int>(inv_fact.size()) <= k)
      inv_fact.push_back(inv_fact.back() / static_cast<long>(inv_fact.size()));
    return inv_fact[static_cast<std::size_t>(k)];
  };
  WSeries g = compose(d, s);
  return finish(scale(g, GiNaC::exp(c), 0));
}

WSeries SeriesExpander::log_of(WSeries s) {
  if (!settle_lead(s)) throw Undecided("the logarithm of an expression that vanishes identically near the point");
  ex c0, e0;
  WSeries r = split_lead(s, c0, e0);
  if (o_.eventual_sign(c0) < 0) throw NotRealNear("the logarithm of a quantity that is negative near the point");
  auto d = [](int k) -> ex { return k == 0 ? ex(0) : ex(numeric(k % 2 ? 1 : -1, k)); };
  WSeries g = compose(d, r);
  return add(WSeries::monomial(GiNaC::log(c0) + e0 * logw_, 0), g);
}

WSeries SeriesExpander::abs_of(WSeries s) {
  if (!settle_lead(s)) return WSeries::zero();
  int sg = o_.eventual_sign(s.terms[0].coeff);
  return sg > 0 ? s : scale(s, -1, 0);
}

WSeries SeriesExpander::function_of(const ex& e, WSeries s) {
  const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
  static const std::vector<std::string> known{"sin", "cos", "atan", "asin", "acos", "tan"};
  if (std::find(known.begin(), known.end(), name) == known.end())
    throw Undecided("the limit algorithm does not handle the function " + name + " here");
  bool diverges = false;
  while (!s.terms.empty() && cmp(s.terms[0].exp, 0) < 0) {
    if (!o_.coefficient_is_zero(s.terms[0].coeff)) {
      diverges = true;
      break;
    }
    s.terms.erase(s.terms.begin());
  }
  if (diverges) {
    // the argument diverges for every parameter value only if its leading coefficient is
    // nonzero for all of them (sin(a*x) tends to 0 for a = 0)
    if (o_.eventual_sign(s.terms[0].coeff) == 0)
      throw Undecided("the leading coefficient of " + name + "'s argument vanishes");
    if (name == "sin" || name == "cos" || name == "tan") throw Oscillates(e);
    if (name == "asin" || name == "acos")
      throw NotRealNear(name + " of a quantity that tends to infinity has no real value");
    // atan(s) = sign(s) pi/2 - atan(1/s)
    int sg = o_.eventual_sign(s.terms[0].coeff);
    WSeries inv = inverse(std::move(s));
    WSeries a = function_of(e, std::move(inv));
    return add(WSeries::monomial(sg * GiNaC::Pi / 2, 0), scale(a, -1, 0));
  }
  if (!s.exact && cmp(s.order, 0) <= 0) throw NeedMoreTerms();
  ex c0 = 0;
  if (!s.terms.empty() && cmp(s.terms[0].exp, 0) == 0) {
    c0 = s.terms[0].coeff;
    s.terms.erase(s.terms.begin());
  }
  if (name != "sin" && name != "cos" && name != "atan") {
    // not entire with bounded derivatives: the expansion point must tend to a regular point
    LimitValue L = o_.limit_of(c0);
    if (!L.finite()) throw Undecided(name + " of a quantity that tends to infinity");
    int ok = name == "tan" ? o_.eventual_sign(GiNaC::pow(GiNaC::cos(L.value), 2))
                           : o_.eventual_sign(1 - GiNaC::pow(L.value, 2));
    if (ok <= 0) throw Undecided(name + " at a singular point of its argument's limit (a branch point or a pole)");
  }
  const ex u = pooled_symbol("u", 0);
  std::vector<ex> derivs{GiNaC::function(GiNaC::ex_to<GiNaC::function>(e).get_serial(), u)};
  std::vector<ex> inv_fact{1};
  auto d = [&](int k) -> ex {
    while (static_cast<int>(derivs.size()) <= k) derivs.push_back(derivs.back().diff(GiNaC::ex_to<GiNaC::symbol>(u)));
    while (static_cast<int>(inv_fact.size()) <= k)
      inv_fact.push_back(inv_fact.back() / static_cast<long>(inv_fact.size()));
    try {
      return derivs[static_cast<std::size_t>(k)].subs(u == c0) * inv_fact[static_cast<std::size_t>(k)];
    } catch (const std::exception&) {
      throw Undecided(name + " is singular at the expansion point");
    }
  };
  return compose(d, s);
}

// A coefficient log(a(x)) or a(x)^p (p not an integer) with a(x) < 0 for all large x has no
// real value near the point: certified by the sign of a. Undecided signs are left alone here.
void SeriesExpander::require_real(const ex& c) {
  for (GiNaC::const_preorder_iterator i = c.preorder_begin(); i != c.preorder_end(); ++i) {
    ex arg;
    if (GiNaC::is_a<GiNaC::function>(*i) && GiNaC::ex_to<GiNaC::function>(*i).get_name() == "log") arg = i->op(0);
    else if (GiNaC::is_a<GiNaC::power>(*i) && !i->op(1).info(GiNaC::info_flags::integer)) arg = i->op(0);
    else continue;
    if (!arg.has(x_)) continue;
    int s = 0;
    try {
      s = o_.eventual_sign(arg);
    } catch (const Undecided&) {
      continue;
    } catch (const Oscillates&) {
      continue;
    }
    if (s < 0)
      throw NotRealNear(GiNaC::is_a<GiNaC::power>(*i) ? "a fractional power of a quantity that is negative near the point"
                                                      : "the logarithm of a quantity that is negative near the point");
  }
}

WSeries SeriesExpander::expand(const ex& e) {
  auto it = memo_.find(e);
  if (it != memo_.end()) return it->second;
  WSeries s = expand_uncached(e);
  memo_.emplace(e, s);
  return s;
}

WSeries SeriesExpander::expand_uncached(const ex& e) {
  o_.budget().tick("series expansion");
  if (!e.has(w_)) {
    if (e.has(x_)) require_real(e);
    return e.is_zero() ? WSeries::zero() : WSeries::monomial(e, 0);
  }
  if (e.is_equal(w_)) return WSeries::monomial(1, 1);
  if (GiNaC::is_a<GiNaC::add>(e)) {
    WSeries s = expand(e.op(0));
    for (std::size_t i = 1; i < e.nops(); ++i) s = add(s, expand(e.op(i)));
    return s;
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    // factors free of w first: they are exact monomials
    WSeries s = WSeries::monomial(1, 0);
    for (std::size_t i = 0; i < e.nops(); ++i) s = mul(s, expand(e.op(i)));
    return s;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const ex &b = e.op(0), &p = e.op(1);
    if (p.has(w_) || p.has(x_)) return expand(GiNaC::exp(p * GiNaC::log(b)));
    return power(expand(b), p);
  }
  if (GiNaC::is_a<GiNaC::function>(e)) {
    if (e.nops() != 1)
      throw Undecided("the limit algorithm does not handle the function " +
                      GiNaC::ex_to<GiNaC::function>(e).get_name() + " of several arguments");
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    WSeries a = expand(e.op(0));
    if (name == "exp") return exp_of(std::move(a));
    if (name == "log") return log_of(std::move(a));
    if (name == "abs") return abs_of(std::move(a));
    return function_of(e, std::move(a));
  }
  throw Undecided("the limit algorithm cannot expand a subexpression of this kind");
}

}  // namespace dc::limits
