// Gruntz's algorithm: the limit, the eventual sign, the leading term, and the decisions the
// series expansion asks for (see gruntz.hpp).
#include "derivations/limit_engine/gruntz.hpp"

#include <algorithm>

#include "derivations/symbolic/printer.hpp"
#include "derivations/decide/prove.hpp"
#include "derivations/kernel/range.hpp"
#include "derivations/kernel/sample.hpp"
#include "derivations/kernel/ball.hpp"

namespace dc::limits {

using GiNaC::ex;
using GiNaC::numeric;

Gruntz::Gruntz(const ex& x, const SymbolTable& ctx, Budget& budget) : x_(x), ctx_(ctx), b_(budget) {}

std::string Gruntz::text(const ex& e) const {
  if (tree_size(e, 300) > 300) return "(an expression of more than 300 nodes)";
  return detail::canon_text(e);
}

LimitValue Gruntz::limit(const ex& f) {
  if (!f.has(x_)) return LimitValue::of(f);
  if (f.is_equal(x_)) return LimitValue::infinity(1);
  auto it = limit_cache_.find(f);
  if (it != limit_cache_.end()) return it->second;
  b_.tick("limit");
  DepthGuard guard(b_, "limit");
  Lead l = leadterm(f);
  LimitValue out;
  int s = constant_sign(l.e0);
  if (s > 0) {
    out = LimitValue::of(0);
  } else if (s < 0) {
    int sc = sign(l.c0);
    if (sc == 0) throw Undecided("internal: the leading coefficient vanishes");
    out = LimitValue::infinity(sc);
  } else {
    if (l.c0.is_equal(f)) throw Undecided("internal: the leading term is the expression itself");
    out = limit(l.c0);
  }
  limit_cache_.emplace(f, out);
  return out;
}

int Gruntz::sign(const ex& f) {
  if (!f.has(x_)) return constant_sign(f);
  if (f.is_equal(x_)) return 1;
  auto it = sign_cache_.find(f);
  if (it != sign_cache_.end()) return it->second;
  b_.tick("sign");
  DepthGuard guard(b_, "sign");
  int s;
  if (GiNaC::is_a<GiNaC::mul>(f)) {
    s = 1;
    for (std::size_t i = 0; i < f.nops() && s != 0; ++i) s *= sign(f.op(i));
  } else if (GiNaC::is_a<GiNaC::function>(f) && GiNaC::ex_to<GiNaC::function>(f).get_name() == "exp") {
    s = 1;
  } else if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<numeric>(f.op(1)) &&
             GiNaC::ex_to<numeric>(f.op(1)).is_integer()) {
    int sb = sign(f.op(0));
    if (sb == 0) throw Undecided("internal: a power of an expression that vanishes identically");
    s = GiNaC::ex_to<numeric>(f.op(1)).is_even() ? 1 : sb;
  } else {
    Lead l = leadterm(f);
    s = l.c0.is_zero() ? 0 : sign(l.c0);
  }
  sign_cache_.emplace(f, s);
  return s;
}

Gruntz::Lead Gruntz::leadterm(const ex& f) {
  if (!f.has(x_)) return {f, 0};
  b_.tick("leadterm");
  DepthGuard guard(b_, "leadterm");
  std::vector<ex> omega = mrv(f);
  if (omega.empty()) return {f, 0};
  ex h = f;
  if (std::any_of(omega.begin(), omega.end(), [&](const ex& e) { return e.is_equal(x_); })) {
    // x -> exp(x): the same limit. The mrv set moves up with the expression (computing it
    // again would compare x with exp(x) once more, without end): its exponentials move up,
    // and x itself now appears as exp(c*x), c constant (x^c became exp(c*x)).
    h = moveup(f);
    std::vector<ex> up;
    for (const ex& e : omega) {
      if (e.is_equal(x_)) continue;
      ex m = moveup(e);
      if (!h.has(m)) throw Undecided("internal: an element of the mrv set was lost when moving up");
      up.push_back(m);
    }
    for (GiNaC::const_preorder_iterator i = h.preorder_begin(); i != h.preorder_end(); ++i) {
      if (!GiNaC::is_a<GiNaC::function>(*i) || GiNaC::ex_to<GiNaC::function>(*i).get_name() != "exp") continue;
      ex c = i->op(0) / x_;
      if (c.has(x_) || c.is_zero()) continue;
      if (std::none_of(up.begin(), up.end(), [&](const ex& e) { return e.is_equal(*i); })) up.push_back(*i);
    }
    // none left: every occurrence of x sat inside a logarithm (log(x) became x), so the moved
    // up expression is of lower class and is its own leading coefficient
    if (up.empty()) return {h, 0};
    omega = up;
  }
  const ex w = pooled_symbol("w", static_cast<std::size_t>(b_.depth));
  ex logw;
  ex g = rewrite(h, omega, w, logw);
  for (long order = 2; order <= b_.max_relative_order; order *= 2) {
    SeriesExpander se(*this, w, x_, logw, order);
    try {
      WSeries s = se.expand(g);
      if (!se.settle_lead(s)) return {0, 0};
      return {s.terms[0].coeff, s.terms[0].exp};
    } catch (const NeedMoreTerms&) {
      continue;
    }
  }
  throw BudgetExceeded("the series in w shows no nonzero term within " + std::to_string(b_.max_relative_order) +
                       " orders of its first term");
}

int Gruntz::constant_sign(const ex& c) {
  if (GiNaC::is_a<numeric>(c)) {
    const numeric& n = GiNaC::ex_to<numeric>(c);
    if (!n.is_real()) throw Undecided("a quantity in the limit is not real");
    return n.is_zero() ? 0 : (n.is_positive() ? 1 : -1);
  }
  auto it = const_sign_cache_.find(c);
  if (it != const_sign_cache_.end()) return it->second;
  b_.tick("constant sign");
  ex cn = c;
  if (tree_size(c, b_.max_coeff_nodes) <= b_.max_coeff_nodes) cn = GiNaC::normal(c);
  int s = 2;
  if (cn.is_zero()) s = 0;
  else if (GiNaC::is_a<numeric>(cn)) return constant_sign(cn);
  GiNaC::exset syms;
  for (GiNaC::const_preorder_iterator i = cn.preorder_begin(); i != cn.preorder_end(); ++i)
    if (GiNaC::is_a<GiNaC::symbol>(*i)) syms.insert(*i);
  if (s == 2 && syms.empty()) {
    kernel::Ball b = kernel::enclose_sign(cn, 128, 1 << 12);
    if (b.status == kernel::BallStatus::NotReal) throw Undecided("a quantity in the limit is not real: " + text(c));
    if (b.positive()) s = 1;
    else if (b.negative()) s = -1;
    else if (b.exact_zero()) s = 0;
  } else if (s == 2) {
    if (detail::provably_positive(cn, ctx_) || detail::provably_positive(c, ctx_)) s = 1;
    else if (detail::provably_positive(-cn, ctx_) || detail::provably_positive(-c, ctx_)) s = -1;
  }
  if (s == 2) {
    ProveOptions opt;
    opt.numeric = false;
    if (prove_zero(cn, ctx_, opt).kind == VerdictKind::Proved) s = 0;
  }
  if (s == 2) {
    // The sign of c or of -c: the same words whichever sign GiNaC's term order gave c.
    const std::string named = text_up_to_sign(text(c), text(-c));
    throw Undecided(syms.empty() ? "the sign of the constant " + named + " could not be decided"
                                 : "the sign of " + named + " is not determined by the declarations");
  }
  const_sign_cache_.emplace(c, s);
  return s;
}

int Gruntz::compare_exponents(const ex& a, const ex& b) { return constant_sign(a - b); }

bool Gruntz::coefficient_is_zero(const ex& c) {
  if (GiNaC::is_a<numeric>(c)) return c.is_zero();
  auto it = zero_cache_.find(c);
  if (it != zero_cache_.end()) return it->second != 0;
  b_.tick("zero test");
  if (tree_size(c, b_.max_coeff_nodes) > b_.max_coeff_nodes)
    throw BudgetExceeded("a series coefficient of more than " + std::to_string(b_.max_coeff_nodes) + " nodes");
  ex cn = GiNaC::normal(c);
  bool zero = cn.is_zero();
  bool decided = zero;
  if (!decided) {
    // nonzero at one point of the domain (x and the parameters): not identically zero
    detail::PointSampler sampler({cn}, ctx_);
    detail::Rng rng(20261201);
    const numeric xs[] = {numeric(3001, 3), numeric(7, 3), numeric(7000001, 7), numeric(33, 2), numeric(3, 7),
                          numeric(1000000000003, 3)};
    for (int i = 0; i < 12 && !decided; ++i) {
      bool adm = false;
      GiNaC::exmap p = sampler.draw(rng, i < 6 ? 0 : 1, &adm);
      if (!adm) continue;
      p[x_] = xs[i % 6];
      kernel::Ball b = kernel::enclose_sign_at(cn, &p, 128, 1 << 11);
      if (b.positive() || b.negative()) decided = true;
    }
  }
  if (!decided) {
    ProveOptions opt;
    opt.numeric = false;
    if (prove_zero(cn, ctx_, opt).kind == VerdictKind::Proved) zero = decided = true;
  }
  if (!decided)
    throw Undecided("could not decide whether the series coefficient " + text(c) + " vanishes identically");
  zero_cache_.emplace(c, zero ? 1 : 0);
  return zero;
}

}  // namespace dc::limits
