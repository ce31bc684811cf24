// `by solves_ode A wrt t [with y(T0) = value, y'(T0) = v0, ...]`: the claim `y(t) = G` solves
// the ODE A: its residual with y and its derivatives (up to the fourth) replaced by G's vanishes,
// and G meets every initial condition (a prime: that derivative of G at T0).
#include "derivations/symbolic/functions.hpp"
#include "derivations/rules/dispatch.hpp"

namespace dc::rules {

Verdict solves_ode(StepContext& c, const Relation& claim) {
  const RuleSpec& rule = c.rule();
  const SymbolTable& symbols = c.d.symbols;
  ex t = c.symbol_of(*rule.var);
  const GiNaC::symbol& ts = GiNaC::ex_to<GiNaC::symbol>(t);
  if (claim.sides.size() < 2) c.fail(c.s.claim_pos, "expected the claim 'y(t) = G'");
  ex Y = c.conv(claim.sides[0]);
  if (pool_function_index(Y) < 0 || pool_derivative_order(Y) != 0)
    c.fail(claim.sides[0].pos, "the claim must be 'y(t) = G' with y a declared function", claim.sides[0].length);
  ex G = c.conv(claim.sides.back());
  GiNaC::exmap m;
  ex dY = Y, dG = G;
  for (int n = 1; n <= 4; ++n) {
    dY = dY.diff(ts);
    dG = dG.diff(ts);
    m[dY] = dG;
  }
  m[Y] = G;

  Combiner all;
  // the ODE's residual
  std::vector<ex> as = c.sides(claim_of(c.ref_step(rule.refs[0])));
  if (as.size() < 2)
    c.fail(rule.refs[0].pos, "'" + rule.refs[0].label + "' must be an ODE (an equation)", rule.refs[0].length);
  for (std::size_t i = 0; i + 1 < as.size(); ++i) {
    ex a = as[i].subs(m, GiNaC::subs_options::no_pattern), b = as[i + 1].subs(m, GiNaC::subs_options::no_pattern);
    Verdict v = prove_equal(a, b, symbols, c.opt);
    v.method = prefix_method("ODE residual", v.method);
    all.add(v, "the ODE");
  }
  // the initial conditions
  for (const auto& w : rule.with) {
    const Node& l = w.equation.sides[0];
    if (l.kind != NodeKind::Call || l.args.size() != 1)
      c.fail(w.pos, "expected an initial condition 'y(T0) = value' after 'with'", w.length);
    ex at = c.conv(l.args[0]);
    ex lhs = c.conv(l);
    const std::string primes(static_cast<std::size_t>(w.prime_order), '\'');
    if (!lhs.is_equal(Y.subs(t == at))) {
      std::string y = c.text(Y.subs(t == at));
      auto paren = y.find('(');
      if (paren != std::string::npos) y.insert(paren, primes);
      c.fail(w.pos, "the initial condition must be for the claimed function, e.g. '" + y + " = value'", w.length);
    }
    // y^(k)(T0) = value: the k-th derivative of the claimed solution at T0
    ex Gk = G;
    for (int k = 0; k < w.prime_order; ++k) Gk = Gk.diff(ts);
    Verdict v = prove_equal(Gk.subs(t == at), c.conv(w.equation.sides[1]), symbols, c.opt);
    v.method = prefix_method(w.prime_order ? "initial condition (derivative of order " + std::to_string(w.prime_order) + ")"
                                           : "initial condition",
                             v.method);
    all.add(v, "initial condition " + w.label);
  }
  // the middle sides of a chain y(t) = G1 = G
  for (std::size_t i = 1; i + 1 < claim.sides.size(); ++i) {
    Verdict v = prove_equal(c.conv(claim.sides[i]), G, symbols, c.opt);
    all.add(v, "side " + std::to_string(i + 1));
  }
  c.res.derived = "residual of the ODE with " + c.text(Y) + " = " + c.text(G);
  return all.result();
}

}  // namespace dc::rules
