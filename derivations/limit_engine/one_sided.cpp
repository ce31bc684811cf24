// one_sided_limit: the substitution to t -> +oo and the call of Gruntz's algorithm.
#include "derivations/decide/prove.hpp"
#include "derivations/limit_engine/gruntz.hpp"
#include "derivations/limit_engine/limits.hpp"

namespace dc::limits {

using GiNaC::ex;

namespace {

LimitOutcome undecided(const std::string& why) {
  LimitOutcome o;
  o.kind = LimitOutcome::Kind::Undecided;
  o.reason = why;
  return o;
}

}  // namespace

LimitOutcome one_sided_limit(const ex& f, const ex& x, const ex& point, int at_infinity, int dir, const SymbolTable& ctx,
                        const Budget& budget) {
  const ex t = pooled_symbol("t", 0);
  ex g;
  try {
    ex sub = at_infinity != 0 ? ex(at_infinity * t) : point + dir / ex(t);
    g = f.subs(x == sub, GiNaC::subs_options::no_pattern);
    g = make_tractable(g, t);
  } catch (const Undecided& e) {
    return undecided(e.what());
  } catch (const std::exception&) {
    return undecided("the expression could not be rewritten for the limit (GiNaC failed on the substitution)");
  }
  Budget b = budget;
  b.start = cpu_seconds();
  Gruntz G(t, ctx, b);
  LimitOutcome out;
  try {
    try {
      LimitValue v = G.limit(g);
      out.method = "Gruntz (mrv)";
      if (v.finite()) {
        out.kind = LimitOutcome::Kind::Value;
        out.value = v.value;
      } else {
        out.kind = v.kind == LimitValue::Kind::PlusInfinity ? LimitOutcome::Kind::PlusInfinity
                                                            : LimitOutcome::Kind::MinusInfinity;
        out.value = 0;
      }
      return out;
    } catch (const Oscillates&) {
      return reduce_oscillation(G, g);
    }
  } catch (const Oscillates&) {
    return undecided("the expression oscillates in a way the bounded-factor reductions do not cover");
  } catch (const NotRealNear& e) {
    out.kind = LimitOutcome::Kind::NotReal;
    out.method = "Gruntz (mrv)";
    out.reason = e.what();
    return out;
  } catch (const Undecided& e) {
    // an expression that vanishes identically (sin(x)^2 + cos(x)^2 - 1) has only zero
    // coefficients, or one the zero test cannot settle: the prove cascade may show it is 0
    const std::string why = e.what();
    if (why.rfind("budget: the series in w", 0) == 0 || why.rfind("could not decide whether the series", 0) == 0) {
      try {
        ProveOptions opt;
        opt.numeric = false;
        if (prove_zero(g, ctx, opt).kind == VerdictKind::Proved) {
          out.kind = LimitOutcome::Kind::Value;
          out.value = 0;
          out.method = "the expression vanishes identically near the point (symbolic cascade)";
          return out;
        }
      } catch (const std::exception&) {
      }
    }
    return undecided(why);
  } catch (const std::bad_alloc&) {
    return undecided("budget: out of memory");
  } catch (const std::exception&) {
    // GiNaC's own errors (a pole met while evaluating a coefficient, ...): their text names
    // GiNaC internals, so it is not passed on.
    return undecided("the limit algorithm failed on a subexpression (a pole or an unsupported form in GiNaC)");
  }
}

}  // namespace dc::limits
