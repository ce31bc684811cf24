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

}  // namespace

namespace {

Outcome from_limit(const LimitValue& v, const std::string& method) {
  Outcome out;
  out.kind = v.finite() ? Outcome::Kind::Value
                        : (v.kind == LimitValue::Kind::PlusInfinity ? Outcome::Kind::PlusInfinity
                                                                    : Outcome::Kind::MinusInfinity);
  out.value = v.finite() ? v.value : ex(0);
  out.method = method;
  return out;
}

// g = F(u) with F continuous on the extended line where it matters: exp, atan, sin, cos
// of an argument u whose limit needs the reductions. nullopt when g is not of that form.
std::optional<Outcome> outer_function(Gruntz& G, const ex& g) {
  const std::string n = fname(g);
  if (g.nops() != 1 || (n != "exp" && n != "atan" && n != "sin" && n != "cos")) return std::nullopt;
  Outcome u = reduce_oscillation(G, g.op(0));
  if (u.kind == Outcome::Kind::Value) {
    Outcome out = u;
    out.value = GiNaC::function(GiNaC::ex_to<GiNaC::function>(g).get_serial(), u.value);
    out.method = u.method + " + continuity of " + n;
    return out;
  }
  if (!u.infinite()) return u;   // the argument oscillates without a limit: undecided below
  const int s = u.kind == Outcome::Kind::PlusInfinity ? 1 : -1;
  Outcome out;
  out.method = u.method + " + the limit of " + n + " at " + (s > 0 ? "oo" : "-oo");
  if (n == "exp") {
    out.kind = s > 0 ? Outcome::Kind::PlusInfinity : Outcome::Kind::Value;
    out.value = 0;
  } else if (n == "atan") {
    out.kind = Outcome::Kind::Value;
    out.value = s * GiNaC::Pi / 2;
  } else {
    out.kind = Outcome::Kind::DoesNotExist;
    out.method = "oscillation";
    out.reason = "the limit does not exist: " + n + " of an argument that tends to infinity oscillates";
  }
  return out;
}

}  // namespace

Outcome reduce_oscillation(Gruntz& G, const ex& g) {
  DepthGuard guard(G.budget(), "oscillation");
  if (auto o = outer_function(G, g)) {
    if (o->kind == Outcome::Kind::Undecided) throw Undecided(o->reason);
    return *o;
  }
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

  // terms without an oscillating factor are summed before their limit is taken (x - log(x)
  // must not become oo - oo)
  ex regular = 0;
  int oscillating = 0;
  bool unbounded = false;   // an oscillating term's amplitude tends to infinity
  ex oscillator;
  for (const ex& T : terms) {
    try {
      G.limit(T);
      regular += T;
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
  const LimitValue acc = G.limit(regular);
  Outcome out;
  if (oscillating == 0) return from_limit(acc, "Gruntz (mrv) + bounded oscillating factor times a factor that tends to 0");
  if (!acc.finite() && !unbounded)
    return from_limit(acc, "Gruntz (mrv) + a bounded oscillating term does not change the divergence");
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
