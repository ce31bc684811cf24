// Bounded oscillating factors (see limits.hpp, reduce_oscillation).
//
// g is split into additive terms. A term with a limit contributes it. A term that oscillates
// must be B * R with B a product of bounded factors (sin, cos, atan and their positive integer
// powers) and R a factor with a limit:
//   R -> 0                       the term tends to 0 (bounded times a null factor);
//   R -> c != 0 or +-oo, B = sin(u)^n or cos(u)^n with u -> +-oo
//                                the term oscillates (B takes two different values for
//                                arbitrarily large x, u being continuous and unbounded).
// Then: no oscillating term left: the sum of the limits; the other terms tend to +-oo: the
// same infinity (a bounded oscillating term does not change it); the others have a finite
// limit and exactly one term oscillates: the limit does not exist. Anything else (two
// oscillating terms, which might cancel) is undecided.
#include <optional>

#include "derivations/limit_engine/gruntz.hpp"
#include "derivations/limit_engine/limits.hpp"
#include "derivations/limit_engine/internal/bounded.hpp"

namespace dc::limits {

using GiNaC::ex;

namespace {

std::string fname(const ex& e) {
  return GiNaC::is_a<GiNaC::function>(e) ? GiNaC::ex_to<GiNaC::function>(e).get_name() : std::string();
}

}  // namespace

namespace {

LimitOutcome from_limit(const LimitValue& v, const std::string& method) {
  LimitOutcome out;
  out.kind = v.finite() ? LimitOutcome::Kind::Value
                        : (v.kind == LimitValue::Kind::PlusInfinity ? LimitOutcome::Kind::PlusInfinity
                                                                    : LimitOutcome::Kind::MinusInfinity);
  out.value = v.finite() ? v.value : ex(0);
  out.method = method;
  return out;
}

// g = F(u) with F continuous on the extended line where it matters: exp, atan, sin, cos
// of an argument u whose limit needs the reductions. nullopt when g is not of that form.
std::optional<LimitOutcome> outer_function(Gruntz& G, const ex& g) {
  const std::string n = fname(g);
  if (g.nops() != 1 || (n != "exp" && n != "atan" && n != "sin" && n != "cos")) return std::nullopt;
  LimitOutcome u = reduce_oscillation(G, g.op(0));
  if (u.kind == LimitOutcome::Kind::Value) {
    LimitOutcome out = u;
    out.value = GiNaC::function(GiNaC::ex_to<GiNaC::function>(g).get_serial(), u.value);
    out.method = u.method + " + continuity of " + n;
    return out;
  }
  if (!u.infinite()) return u;   // the argument oscillates without a limit: undecided below
  const int s = u.kind == LimitOutcome::Kind::PlusInfinity ? 1 : -1;
  LimitOutcome out;
  out.method = u.method + " + the limit of " + n + " at " + (s > 0 ? "oo" : "-oo");
  if (n == "exp") {
    out.kind = s > 0 ? LimitOutcome::Kind::PlusInfinity : LimitOutcome::Kind::Value;
    out.value = 0;
  } else if (n == "atan") {
    out.kind = LimitOutcome::Kind::Value;
    out.value = s * GiNaC::Pi / 2;
  } else {
    out.kind = LimitOutcome::Kind::DoesNotExist;
    out.method = "oscillation";
    out.reason = "the limit does not exist: " + n + " of an argument that tends to infinity oscillates";
  }
  return out;
}

}  // namespace

namespace {

// One oscillating term T = B * R, B the product of the factors that have no limit.
struct OscTerm {
  enum class Kind { Null, Bounded, Oscillator, Diverges, Limit } kind;
  bool unbounded = false;   // Oscillator with an amplitude that tends to infinity
  ex base;                  // Oscillator: the sin or cos
  int sign = 0;             // Diverges: the sign of the infinity
  ex value;                 // Limit: the term's (finite) limit
};

// sin(u) or cos(u) with u -> +-oo; false when that is not shown
bool is_oscillator(Gruntz& G, const ex& e) {
  const std::string n = fname(e);
  if (n != "sin" && n != "cos") return false;
  try {
    return !G.limit(e.op(0)).finite();
  } catch (const Oscillates&) {
    return false;
  }
}

// The sign of an x-free quantity, 2 when the declarations do not fix it.
int sign_or_unknown(Gruntz& G, const ex& c) {
  try {
    return G.constant_sign(c);
  } catch (const BudgetExceeded&) {
    throw;
  } catch (const Undecided&) {
    return 2;
  }
}

OscTerm classify(Gruntz& G, const ex& T) {
  ex B = 1, R = 1;
  std::vector<ex> factors;
  if (GiNaC::is_a<GiNaC::mul>(T))
    for (std::size_t i = 0; i < T.nops(); ++i) factors.push_back(T.op(i));
  else
    factors.push_back(T);
  ex known = 1;   // the limits of oscillating factors b^p whose base has a limit c != 0 (1 + sin(x)/x)
  for (const ex& f : factors) {
    bool oscillates = false;
    if (f.has(G.variable())) {
      try {
        G.limit(f);
      } catch (const Oscillates&) {
        oscillates = true;
      }
    }
    if (oscillates && GiNaC::is_a<GiNaC::power>(f) && !f.op(1).has(G.variable())) {
      std::optional<LimitOutcome> o;
      try {
        o = reduce_oscillation(G, f.op(0));
      } catch (const BudgetExceeded&) {
        throw;
      } catch (const Undecided&) {
      } catch (const Oscillates&) {
      }
      if (o && o->kind == LimitOutcome::Kind::Value) {
        const int cs = sign_or_unknown(G, o->value);
        if ((cs == 1 || cs == -1) && (f.op(1).info(GiNaC::info_flags::integer) || cs == 1)) {
          known *= GiNaC::pow(o->value, f.op(1));
          continue;
        }
      }
    }
    (oscillates ? B : R) *= f;
  }
  if (B.is_equal(1) && !known.is_equal(1)) {
    // every oscillating factor has a limit: the term's limit is the product
    const LimitValue r = G.limit(R);
    if (r.finite()) return {OscTerm::Kind::Limit, false, ex(), 0, r.value * known};
    const int ks = sign_or_unknown(G, known);
    if (ks != 1 && ks != -1) throw Undecided("the sign of a limit factor is not determined by the declarations");
    return {OscTerm::Kind::Diverges, false, ex(), (r.kind == LimitValue::Kind::PlusInfinity ? 1 : -1) * ks};
  }
  B *= known;
  // B must be bounded: an interval enclosure (sin, cos in [-1, 1], ...) shows it
  const std::optional<Enclosure> b = B.is_equal(1) ? std::nullopt : enclose(G, B);
  if (!b) throw Undecided("an oscillating subexpression that is not a bounded factor of its term");
  const LimitValue r = G.limit(R);
  if (r.finite() && G.constant_sign(r.value) == 0) return {OscTerm::Kind::Null};
  // B = sin(u)^n or cos(u)^n, u -> +-oo: B takes two different values (1 and 0 or -1) for
  // arbitrarily large x; times R -> c != 0 or R -> +-oo the term oscillates
  const ex base = GiNaC::is_a<GiNaC::power>(B) ? B.op(0) : B;
  if (is_oscillator(G, base)) return {OscTerm::Kind::Oscillator, !r.finite(), base};
  if (r.finite()) return {OscTerm::Kind::Bounded};
  // R -> +-oo times B inside [lo, hi] with lo > 0 (or hi < 0): B stays away from 0, so the
  // term diverges like R (x*exp(sin(x)) -> oo, x/(2 + sin(x)) -> oo)
  const int rs = r.kind == LimitValue::Kind::PlusInfinity ? 1 : -1;
  if (sign_or_unknown(G, b->lo) == 1) return {OscTerm::Kind::Diverges, false, ex(), rs};
  if (sign_or_unknown(G, b->hi) == -1) return {OscTerm::Kind::Diverges, false, ex(), -rs};
  throw Undecided("an oscillating factor times a factor that does not tend to 0");
}

LimitOutcome reduce_terms(Gruntz& G, const ex& e) {
  std::vector<ex> terms;
  if (GiNaC::is_a<GiNaC::add>(e))
    for (std::size_t i = 0; i < e.nops(); ++i) terms.push_back(e.op(i));
  else
    terms.push_back(e);
  // terms without an oscillating factor are summed before their limit is taken (x - log(x)
  // must not become oo - oo)
  ex regular = 0;
  ex known = 0;                     // the finite limits of oscillating terms that have one
  int oscillators = 0, bounded = 0;
  int diverges = 0;                 // the sign of the diverging terms (bounded away from 0 times +-oo)
  bool mixed_divergence = false;    // diverging terms of both signs (they might cancel)
  bool unbounded = false;
  ex oscillator;
  for (const ex& T : terms) {
    try {
      G.limit(T);
      regular += T;
      continue;
    } catch (const Oscillates&) {
    }
    OscTerm t = classify(G, T);
    if (t.kind == OscTerm::Kind::Limit) {
      known += t.value;
      continue;
    }
    if (t.kind == OscTerm::Kind::Bounded) ++bounded;
    if (t.kind == OscTerm::Kind::Diverges) {
      if (diverges != 0 && diverges != t.sign) mixed_divergence = true;
      diverges = t.sign;
    }
    if (t.kind == OscTerm::Kind::Oscillator) {
      ++oscillators;
      oscillator = t.base;
      unbounded = unbounded || t.unbounded;
    }
  }
  LimitValue acc = G.limit(regular);
  if (acc.finite()) acc.value += known;
  if (diverges != 0) {
    // terms that tend to the same infinity, next to bounded ones and a part with a limit that
    // is finite or the same infinity
    const int as = acc.finite() ? 0 : (acc.kind == LimitValue::Kind::PlusInfinity ? 1 : -1);
    if (mixed_divergence || unbounded || as == -diverges)
      throw Undecided("oscillating terms that diverge next to terms that might cancel them");
    return from_limit(LimitValue::infinity(diverges),
                      "Gruntz (mrv) + a factor bounded away from 0 (interval enclosure) times a divergent factor");
  }
  if (oscillators == 0 && bounded == 0)
    return from_limit(acc, "Gruntz (mrv) + bounded oscillating factor times a factor that tends to 0");
  if (!acc.finite() && !unbounded)
    return from_limit(acc, "Gruntz (mrv) + a bounded oscillating term does not change the divergence");
  if (oscillators == 1 && bounded == 0 && acc.finite()) {
    LimitOutcome out;
    out.kind = LimitOutcome::Kind::DoesNotExist;
    out.method = "oscillation";
    out.reason = "the limit does not exist: the term with " + fname(oscillator) +
                 " of an argument that tends to infinity oscillates with an amplitude that does not tend to 0";
    return out;
  }
  if (oscillators + bounded > 1) throw Undecided("several oscillating terms (they might cancel)");
  if (bounded == 1) throw Undecided("a bounded term that oscillates next to a finite limit: its own limit is not decided");
  throw Undecided("an oscillating term with an unbounded amplitude next to a divergent part");
}

// g = f1 * f2 * ... or f^p (p constant): each factor's limit on its own (with the reductions),
// combined by the product rules when every factor has a limit and no 0 * oo arises
// ((1 + 1/x)/(cos(x) - 2 x) -> 1 * 0). nullopt when that does not apply.
std::optional<LimitOutcome> product_of_limits(Gruntz& G, const ex& g) {
  std::vector<std::pair<ex, ex>> factors;   // (base, exponent)
  auto add = [&](const ex& f) {
    if (GiNaC::is_a<GiNaC::power>(f) && !f.op(1).has(G.variable())) factors.push_back({f.op(0), f.op(1)});
    else factors.push_back({f, 1});
  };
  if (GiNaC::is_a<GiNaC::mul>(g))
    for (std::size_t i = 0; i < g.nops(); ++i) add(g.op(i));
  else if (GiNaC::is_a<GiNaC::power>(g))
    add(g);
  else
    return std::nullopt;
  if (factors.size() < 2 && factors[0].second.is_equal(1)) return std::nullopt;
  ex value = 1;
  int inf_sign = 0;   // the product of the infinite factors' signs, 0: none
  bool zero = false;
  for (const auto& [base, p] : factors) {
    LimitOutcome o;
    try {
      o = from_limit(G.limit(base), "");
    } catch (const Oscillates&) {
      o = reduce_oscillation(G, base);
    }
    if (!o.decided_limit()) return std::nullopt;
    const int ps = G.constant_sign(p);
    if (o.infinite()) {
      const int s = o.kind == LimitOutcome::Kind::PlusInfinity ? 1 : -1;
      if (ps < 0) {
        zero = true;   // (+-oo)^p, p < 0
        continue;
      }
      if (!p.info(GiNaC::info_flags::integer) && s < 0) return std::nullopt;
      const int ps_int = p.info(GiNaC::info_flags::even) ? 1 : s;
      inf_sign = (inf_sign == 0 ? 1 : inf_sign) * ps_int;
      continue;
    }
    const int vs = G.constant_sign(o.value);
    if (vs == 0) {
      if (ps < 0) return std::nullopt;   // 0^p, p < 0: a one-sided question
      zero = true;
      continue;
    }
    if (vs < 0 && !p.info(GiNaC::info_flags::integer)) return std::nullopt;
    value *= GiNaC::pow(o.value, p);
  }
  if (zero && inf_sign != 0) return std::nullopt;   // 0 * oo
  LimitOutcome out;
  out.method = "Gruntz (mrv) + limits of the factors (bounded oscillating factors reduced)";
  if (zero) {
    out.kind = LimitOutcome::Kind::Value;
    out.value = 0;
  } else if (inf_sign != 0) {
    const int s = inf_sign * G.constant_sign(value);
    out.kind = s > 0 ? LimitOutcome::Kind::PlusInfinity : LimitOutcome::Kind::MinusInfinity;
    out.value = 0;
  } else {
    out.kind = LimitOutcome::Kind::Value;
    out.value = value;
  }
  return out;
}

}  // namespace

namespace {

// The reductions on g as written, then on g expanded ((x + sin(x))/x = 1 + sin(x)/x).
LimitOutcome reduce_as_written(Gruntz& G, const ex& g) {
  try {
    if (auto o = product_of_limits(G, g)) return *o;
  } catch (const Undecided&) {
  } catch (const Oscillates&) {
  }
  // the product as written first ((x^2 + sin(x)) cos(1/x) at 0: a null factor times a
  // bounded one), then expanded
  try {
    return reduce_terms(G, g);
  } catch (const Undecided&) {
    if (GiNaC::is_a<GiNaC::add>(g) || tree_size(g, 500) > 500) throw;
    ex expanded = make_tractable(g.expand(), G.variable());
    if (!GiNaC::is_a<GiNaC::add>(expanded)) throw;
    return reduce_terms(G, expanded);
  } catch (const Oscillates&) {
    if (GiNaC::is_a<GiNaC::add>(g) || tree_size(g, 500) > 500) throw;
    ex expanded = make_tractable(g.expand(), G.variable());
    if (!GiNaC::is_a<GiNaC::add>(expanded)) throw;
    return reduce_terms(G, expanded);
  }
}

// g with its sums written through their dominant part (internal/bounded.hpp), reduced again;
// nullopt when nothing was rewritten or the rewritten form is not decided either.
std::optional<LimitOutcome> reduce_dominant(Gruntz& G, const ex& g) {
  bool changed = false;
  const ex h = factor_dominant(G, g, changed);
  if (!changed || h.is_equal(g)) return std::nullopt;
  try {
    LimitOutcome o = reduce_as_written(G, h);
    o.method += " (each sum with an oscillating term written as its dominant part times a factor that tends to 1)";
    return o;
  } catch (const BudgetExceeded&) {
    throw;
  } catch (const Undecided&) {
  } catch (const Oscillates&) {
  }
  return std::nullopt;
}

}  // namespace

LimitOutcome reduce_oscillation(Gruntz& G, const ex& g) {
  DepthGuard guard(G.budget(), "oscillation");
  if (auto o = outer_function(G, g)) {
    if (o->kind == LimitOutcome::Kind::Undecided) throw Undecided(o->reason);
    return *o;
  }
  try {
    return reduce_as_written(G, g);
  } catch (const BudgetExceeded&) {
    throw;
  } catch (const Undecided&) {
    if (auto o = reduce_dominant(G, g)) return *o;
    throw;
  } catch (const Oscillates&) {
    if (auto o = reduce_dominant(G, g)) return *o;
    throw;
  }
}

}  // namespace dc::limits
