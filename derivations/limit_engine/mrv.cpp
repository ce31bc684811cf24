// Most rapidly varying subexpressions, their comparison, moving up and the rewriting in w
// (steps 1-3 of Gruntz's algorithm; see gruntz.hpp).
#include <algorithm>

#include "derivations/limit_engine/gruntz.hpp"

namespace dc::limits {

using GiNaC::ex;

namespace {

bool is_exp(const ex& e) {
  return GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "exp";
}

bool contains(const std::vector<ex>& v, const ex& e) {
  return std::any_of(v.begin(), v.end(), [&](const ex& a) { return a.is_equal(e); });
}

std::vector<ex> set_union(std::vector<ex> a, const std::vector<ex>& b) {
  for (const ex& e : b)
    if (!contains(a, e)) a.push_back(e);
  return a;
}

}  // namespace

std::vector<ex> Gruntz::mrv(const ex& f) {
  if (!f.has(x_)) return {};
  if (f.is_equal(x_)) return {x_};
  auto it = mrv_cache_.find(f);
  if (it != mrv_cache_.end()) return it->second;
  b_.tick("mrv");
  DepthGuard guard(b_, "mrv");
  std::vector<ex> out;
  if (GiNaC::is_a<GiNaC::add>(f) || GiNaC::is_a<GiNaC::mul>(f)) {
    for (std::size_t i = 0; i < f.nops(); ++i) out = mrv_max(out, mrv(f.op(i)));
  } else if (GiNaC::is_a<GiNaC::power>(f)) {
    if (f.op(1).has(x_)) throw Undecided("internal: a power with a variable exponent reached the mrv step");
    out = mrv(f.op(0));
  } else if (is_exp(f)) {
    LimitValue L = limit(f.op(0));
    out = L.finite() ? mrv(f.op(0)) : mrv_max({f}, mrv(f.op(0)));
  } else if (GiNaC::is_a<GiNaC::function>(f)) {
    for (std::size_t i = 0; i < f.nops(); ++i) out = mrv_max(out, mrv(f.op(i)));
  } else {
    throw Undecided("internal: an unexpected subexpression in the mrv step");
  }
  mrv_cache_.emplace(f, out);
  return out;
}

std::vector<ex> Gruntz::mrv_max(const std::vector<ex>& a, const std::vector<ex>& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  for (const ex& e : b)
    if (contains(a, e)) return set_union(a, b);
  int c = compare_classes(a[0], b[0]);
  if (c > 0) return a;
  if (c < 0) return b;
  return set_union(a, b);
}

// f, g: x or exponentials tending to 0 or oo. Compares lim log(f)/log(g).
int Gruntz::compare_classes(const ex& f, const ex& g) {
  auto log_of = [&](const ex& e) { return e.is_equal(x_) ? GiNaC::log(x_) : e.op(0); };
  LimitValue L = limit(make_tractable(log_of(f) / log_of(g), x_));
  if (!L.finite()) return 1;
  return constant_sign(L.value) == 0 ? -1 : 0;
}

ex Gruntz::moveup(const ex& f) { return make_tractable(f.subs(x_ == GiNaC::exp(x_)), x_); }

namespace {

class Rewriter : public GiNaC::map_function {
 public:
  Rewriter(const ex& x, const std::vector<ex>& omega, const std::vector<ex>& coeffs, const ex& garg, const ex& wpow_sign,
           const ex& w)
      : x_(x), omega_(omega), coeffs_(coeffs), garg_(garg), sgn_(wpow_sign), w_(w) {}

  ex operator()(const ex& e) override {
    if (!e.has(x_)) return e;
    for (std::size_t i = 0; i < omega_.size(); ++i) {
      if (!e.is_equal(omega_[i])) continue;
      // exp(a) = exp(a - c g) * exp(c g) with exp(g) = w^(+-1)
      ex arg = (*this)(omega_[i].op(0));
      ex rest = arg - coeffs_[i] * garg_;
      if (tree_size(rest, 400) <= 400) rest = rest.expand();
      return GiNaC::exp(rest) * GiNaC::pow(w_, sgn_ * coeffs_[i]);
    }
    return e.map(*this);
  }

 private:
  ex x_;
  const std::vector<ex>& omega_;
  const std::vector<ex>& coeffs_;
  ex garg_, sgn_, w_;
};

}  // namespace

ex Gruntz::rewrite(const ex& f, const std::vector<ex>& omega, const ex& w, ex& logw) {
  // g: an element in which no other element of omega occurs, the smallest such
  ex g;
  std::size_t best = 0;
  for (const ex& a : omega) {
    bool minimal = true;
    for (const ex& b : omega)
      if (!b.is_equal(a) && a.has(b)) minimal = false;
    if (!minimal) continue;
    std::size_t n = tree_size(a, 100000);
    if (g.is_zero() || n < best) {
      g = a;
      best = n;
    }
  }
  if (g.is_zero()) throw Undecided("internal: the mrv set has no minimal element");
  const ex garg = g.op(0);
  int sg = sign(garg);
  if (sg == 0) throw Undecided("internal: an element of the mrv set does not tend to 0 or oo");
  // sg > 0: g -> oo, w = 1/g; sg < 0: g -> 0, w = g
  logw = sg > 0 ? ex(-garg) : garg;
  std::vector<ex> coeffs;
  GiNaC::numeric denominators = 1;
  for (const ex& a : omega) {
    LimitValue c = limit(make_tractable(a.op(0) / garg, x_));
    if (!c.finite() || constant_sign(c.value) == 0)
      throw Undecided("internal: two elements of the mrv set are not comparable");
    coeffs.push_back(c.value);
    if (GiNaC::is_a<GiNaC::numeric>(c.value) && GiNaC::ex_to<GiNaC::numeric>(c.value).is_rational())
      denominators = GiNaC::lcm(denominators, GiNaC::ex_to<GiNaC::numeric>(c.value).denom());
  }
  // integer exponents where possible: with exp(-x) and exp(1000 x) in the set, w = exp(-x/1000)
  // would give powers w^(k/1000); the series is taken in w^(1/L) instead
  if (denominators > 1000) denominators = 1;
  for (ex& c : coeffs) c *= denominators;
  logw = logw / denominators;
  Rewriter rw(x_, omega, coeffs, garg / denominators, sg > 0 ? -1 : 1, w);
  ex out = rw(f);
  for (const ex& a : omega)
    if (out.has(a)) throw Undecided("internal: the rewriting in w left an element of the mrv set");
  return out;
}

}  // namespace dc::limits
