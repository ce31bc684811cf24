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
#include "derivations/core/prove_detail.hpp"
#include "derivations/limits/gruntz.hpp"
#include "derivations/limits/limits.hpp"

namespace dc::limits {

using GiNaC::ex;

namespace {

std::string fname(const ex& e) {
  return GiNaC::is_a<GiNaC::function>(e) ? GiNaC::ex_to<GiNaC::function>(e).get_name() : std::string();
}

bool is_bounded(const ex& e) {
  const std::string n = fname(e);
  if (n == "sin" || n == "cos" || n == "atan") return true;
  if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
      GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_pos_integer())
    return is_bounded(e.op(0));
  return false;
}

LimitValue add_limits(const LimitValue& a, const LimitValue& b) {
  if (a.finite() && b.finite()) return LimitValue::of(a.value + b.value);
  if (a.finite()) return b;
  if (b.finite()) return a;
  if (a.kind == b.kind) return a;
  throw Undecided("terms tend to +oo and -oo (the oscillating form oo - oo)");
}

}  // namespace

Outcome reduce_oscillation(Gruntz& G, const ex& g) {
  ex e = g;
  if (!GiNaC::is_a<GiNaC::add>(e) && tree_size(e, 500) <= 500) {
    ex ee = make_tractable(e.expand(), G.variable());
    if (GiNaC::is_a<GiNaC::add>(ee)) e = ee;
  }
  std::vector<ex> terms;
  if (GiNaC::is_a<GiNaC::add>(e))
    for (std::size_t i = 0; i < e.nops(); ++i) terms.push_back(e.op(i));
  else
    terms.push_back(e);

  LimitValue acc = LimitValue::of(0);
  int oscillating = 0;
  bool unbounded = false;   // an oscillating term's amplitude tends to infinity
  ex oscillator;
  for (const ex& T : terms) {
    try {
      acc = add_limits(acc, G.limit(T));
      continue;
    } catch (const Oscillates&) {
    }
    ex B = 1, R = 1;
    std::vector<ex> factors;
    if (GiNaC::is_a<GiNaC::mul>(T))
      for (std::size_t i = 0; i < T.nops(); ++i) factors.push_back(T.op(i));
    else
      factors.push_back(T);
    for (const ex& f : factors) (is_bounded(f) ? B : R) *= f;
    if (B.is_equal(1)) throw Undecided("an oscillating subexpression that is not a bounded factor of its term");
    LimitValue r = G.limit(R);
    if (r.finite() && G.constant_sign(r.value) == 0) {
      continue;
    }
    // B = sin(u)^n or cos(u)^n, u -> +-oo: B takes two different values (1 and 0 or -1) for
    // arbitrarily large x; times R -> c != 0 or R -> +-oo the term oscillates
    ex base = GiNaC::is_a<GiNaC::power>(B) ? B.op(0) : B;
    std::string n = fname(base);
    if ((n == "sin" || n == "cos") && !G.limit(base.op(0)).finite()) {
      ++oscillating;
      oscillator = base;
      unbounded = unbounded || !r.finite();
      continue;
    }
    throw Undecided("an oscillating factor times a factor that does not tend to 0");
  }
  Outcome out;
  if (oscillating == 0) {
    out.kind = acc.finite() ? Outcome::Kind::Value
                            : (acc.kind == LimitValue::Kind::PlusInfinity ? Outcome::Kind::PlusInfinity
                                                                          : Outcome::Kind::MinusInfinity);
    out.value = acc.finite() ? acc.value : ex(0);
    out.method = "Gruntz (mrv) + bounded oscillating factor times a factor that tends to 0";
    return out;
  }
  if (!acc.finite() && !unbounded) {
    out.kind = acc.kind == LimitValue::Kind::PlusInfinity ? Outcome::Kind::PlusInfinity : Outcome::Kind::MinusInfinity;
    out.value = 0;
    out.method = "Gruntz (mrv) + a bounded oscillating term does not change the divergence";
    return out;
  }
  if (oscillating == 1 && acc.finite()) {
    out.kind = Outcome::Kind::DoesNotExist;
    out.method = "oscillation";
    out.reason = "the limit does not exist: the term with " + fname(oscillator) +
                 " of an argument that tends to infinity oscillates with an amplitude that does not tend to 0";
    return out;
  }
  throw Undecided(oscillating > 1 ? "several oscillating terms (they might cancel)"
                                  : "an oscillating term with an unbounded amplitude next to a divergent part");
}

}  // namespace dc::limits
