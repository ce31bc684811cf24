// Integer-valued symbols in the cascade (integer.hpp).
#include "derivations/decide/integer.hpp"

#include <map>
#include <string>

namespace dc {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

bool integer_symbol(const ex& e, const SymbolTable& ctx) {
  if (!GiNaC::is_a<GiNaC::symbol>(e)) return false;
  const SymbolInfo* info = ctx.find(GiNaC::ex_to<GiNaC::symbol>(e));
  return info && !info->is_function && info->domain.integer;
}

bool has_integer_symbol(const ex& e, const SymbolTable& ctx) {
  if (integer_symbol(e, ctx)) return true;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_integer_symbol(e.op(i), ctx)) return true;
  return false;
}

bool is_minus_one(const ex& e) { return GiNaC::is_a<numeric>(e) && GiNaC::ex_to<numeric>(e) == -1; }

// The parity of an integer-valued k as the sum of its odd terms, each power of an integer
// symbol replaced by the symbol: (-1)^k = (-1)^parity(k).
ex parity(const ex& k) {
  const ex e = k.expand();
  std::map<ex, int, GiNaC::ex_is_less> count;   // monomial -> number of odd terms, mod 2
  auto term = [&](const ex& t) {
    numeric c = 1;
    ex m = 1;
    auto factor = [&](const ex& f) {
      if (GiNaC::is_a<numeric>(f)) c *= GiNaC::ex_to<numeric>(f);
      else if (GiNaC::is_a<GiNaC::power>(f)) m *= f.op(0);   // n^j, j >= 1: the parity of n
      else m *= f;
    };
    if (GiNaC::is_a<GiNaC::mul>(t))
      for (std::size_t i = 0; i < t.nops(); ++i) factor(t.op(i));
    else
      factor(t);
    if (!c.is_even()) count[m] ^= 1;
  };
  if (GiNaC::is_a<GiNaC::add>(e))
    for (std::size_t i = 0; i < e.nops(); ++i) term(e.op(i));
  else
    term(e);
  ex out = 0;
  for (const auto& [m, odd] : count)
    if (odd) out += m;
  return out;
}

ex minus_one_to(const ex& k) {
  const ex p = parity(k);
  if (p.is_zero()) return 1;
  if (p.is_equal(1)) return -1;
  return GiNaC::pow(-1, p);
}

// a = k*pi*unit + rest with k integer-valued (unit 1 for sin/cos/tan, I for exp): {k, rest}.
std::pair<ex, ex> split_period(const ex& a, const ex& unit, const SymbolTable& ctx) {
  const ex e = a.expand();
  ex k = 0, rest = 0;
  auto term = [&](const ex& t) {
    const ex c = (t / (GiNaC::Pi * unit)).expand();
    if (!c.has(GiNaC::Pi) && !c.has(GiNaC::I) && integer_valued(c, ctx)) k += c;
    else rest += t;
  };
  if (GiNaC::is_a<GiNaC::add>(e))
    for (std::size_t i = 0; i < e.nops(); ++i) term(e.op(i));
  else
    term(e);
  return {k, rest};
}

bool is_fn(const ex& e, const char* name) {
  return GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == name;
}

struct Reduce : GiNaC::map_function {
  const SymbolTable& ctx;
  explicit Reduce(const SymbolTable& t) : ctx(t) {}
  ex operator()(const ex& e0) override {
    const ex e = e0.nops() ? e0.map(*this) : e0;
    if (!has_integer_symbol(e, ctx)) return e;
    if (is_fn(e, "sin") || is_fn(e, "cos") || is_fn(e, "tan")) {
      auto [k, rest] = split_period(e.op(0), 1, ctx);
      if (k.is_zero()) return e;
      if (is_fn(e, "tan")) return GiNaC::tan(rest);
      return minus_one_to(k) * (is_fn(e, "sin") ? GiNaC::sin(rest) : GiNaC::cos(rest));
    }
    if (is_fn(e, "exp")) {
      auto [k, rest] = split_period(e.op(0), GiNaC::I, ctx);
      if (k.is_zero()) return e;
      return minus_one_to(k) * GiNaC::exp(rest);
    }
    if (GiNaC::is_a<GiNaC::power>(e)) {
      const ex& b = e.op(0);
      const ex& x = e.op(1);
      if (is_minus_one(b) && integer_valued(x, ctx)) return minus_one_to(x);
      // ((-1)^j)^k = (-1)^(j*k) for integers j, k
      if (GiNaC::is_a<GiNaC::power>(b) && is_minus_one(b.op(0)) && integer_valued(b.op(1), ctx) &&
          integer_valued(x, ctx))
        return minus_one_to(b.op(1) * x);
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
      // (-1)^j * (-1)^k = (-1)^(j + k)
      ex k = 0, others = 1;
      int powers = 0;
      for (std::size_t i = 0; i < e.nops(); ++i) {
        const ex& f = e.op(i);
        if (GiNaC::is_a<GiNaC::power>(f) && is_minus_one(f.op(0)) && integer_valued(f.op(1), ctx)) {
          k += f.op(1);
          ++powers;
        } else {
          others *= f;
        }
      }
      if (powers >= 2) return others * minus_one_to(k);
    }
    return e;
  }
};

}  // namespace

bool integer_valued(const ex& e, const SymbolTable& ctx) {
  if (GiNaC::is_a<numeric>(e)) return GiNaC::ex_to<numeric>(e).is_integer();
  if (GiNaC::is_a<GiNaC::symbol>(e)) return integer_symbol(e, ctx);
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!integer_valued(e.op(i), ctx)) return false;
    return true;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const ex& x = e.op(1);
    return GiNaC::is_a<numeric>(x) && GiNaC::ex_to<numeric>(x).is_nonneg_integer() && integer_valued(e.op(0), ctx);
  }
  return false;
}

ex reduce_integer_periods(const ex& e, const SymbolTable& ctx) {
  if (!has_integer_symbol(e, ctx)) return e;
  Reduce r(ctx);
  ex out = e;
  for (int pass = 0; pass < 3; ++pass) {   // a rewriting can expose another: ((-1)^n)^2 after sin(n*pi)^2
    ex next = r(out);
    if (next.is_equal(out)) break;
    out = next;
  }
  return out;
}

Verdict with_integer_periods(const ex& lhs, const ex& rhs, const SymbolTable& ctx, const ProveOptions& opt,
                             Cascade cascade) {
  if (opt.symbolic && has_integer_symbol(lhs - rhs, ctx)) {
    ex l = lhs, r = rhs;
    try {
      l = reduce_integer_periods(lhs, ctx);
      r = reduce_integer_periods(rhs, ctx);
    } catch (const std::exception&) {
      l = lhs;
      r = rhs;
    }
    if (!l.is_equal(lhs) || !r.is_equal(rhs)) {
      ProveOptions symbolic_only = opt;
      symbolic_only.numeric = false;
      Verdict v = cascade(l, r, ctx, symbolic_only);
      if (v.kind == VerdictKind::Proved) {
        v.method = "integer periods + " + v.method;
        v.detail = "sin, cos, tan and exp of integer multiples of pi and powers of -1 reduced for the integer "
                   "symbols, then " + v.detail;
        return v;
      }
    }
  }
  return cascade(lhs, rhs, ctx, opt);
}

}  // namespace dc
