// `by integrate [refs] wrt t [from T0] [with y(T0) = value, ...]`, two forms:
//   - the claim `integral(f, x, a, b) = G`: dG/db = f(b) and G = 0 at b = a (or, when the
//     upper limit also appears in the integrand, rigorous quadrature at sampled parameters);
//   - the ODE form: the reference A is `diff(Y, t) = f` and the claim `Y = G`: dG/dt = f with
//     Y = G, and G takes the initial value at T0;
//   - its change form: the claim `Y(b) - Y(a) = G` (or `= integral(g, t, a, b) = G`, the
//     fundamental theorem), see change_form.
// The references hold at the bounds: only equations between function applications of t hold
// for every t (see has_application_at); the others are used as they are.
#include <functional>
#include <map>
#include <optional>

#include "derivations/calculus/definite.hpp"
#include "derivations/calculus/integral_equal.hpp"
#include "derivations/symbolic/differential.hpp"
#include "derivations/symbolic/functions.hpp"
#include "derivations/symbolic/inspect.hpp"
#include "derivations/kernel/quadrature.hpp"
#include "derivations/rules/dispatch.hpp"
#include "derivations/steps/follows.hpp"

namespace dc::rules {

namespace {

// The references, plus their instances at each of `at` (for those that hold for every t).
std::vector<Eq> at_points(const std::vector<Eq>& eqs, const ex& t, const std::vector<ex>& at) {
  std::vector<Eq> out = eqs;
  for (const auto& p : at)
    for (const auto& q : eqs)
      if (has_application_at(q.e, t)) out.push_back({q.e.subs(t == p), ex(), q.from});
  return out;
}

// integral(f, x, a, b) = G when a reference mentions the upper limit b: the integrand's declared
// functions replaced by what the references give them (`F(t) = expr` with t the rule's
// variable), the integral computed as a function of b by the definite-integral methods, and
// each closed form must follow from that value and the references (which may pin b). An
// integrand the references do not make explicit, or an integral the methods cannot compute,
// leaves the step undecided.
Verdict integral_through_references(StepContext& c, const Relation& claim, const Integrand& in, const ex& a,
                                    const ex& b, const ex& t, const std::vector<Eq>& ref_eqs, const ThroughT& through_t) {
  ex f = in.f;
  for (const auto& q : ref_eqs)
    if (pool_function_index(q.hint) >= 0 && pool_derivative_order(q.hint) == 0 && q.hint.nops() == 1 &&
        q.hint.op(0).is_equal(t))
      f = f.subs(q.hint.subs(t == in.x) == (q.hint - q.e).subs(t == in.x), GiNaC::subs_options::no_pattern);
  const std::string why = "a reference mentions the upper limit " + c.text(b) + ", so the derivative test (which needs " +
                          c.text(b) + " free) does not apply";
  if (detail::has_abstract_application(f))
    return undecided("integrate", why + ", and the references do not give the integrand explicitly");
  const integrals::Definite value =
      integrals::definite_integral(f, GiNaC::ex_to<GiNaC::symbol>(in.x), a, 0, b, 0, in.table);
  if (value.kind != integrals::Definite::Kind::Value)
    return undecided("integrate", why + ", and the integral of " + c.text(f) + " was not computed" +
                                      (value.why.empty() ? std::string() : ": " + value.why));
  c.res.derived = "integral = " + c.text(value.value);
  Combiner all;
  for (std::size_t i = 1; i < claim.sides.size(); ++i) {
    Verdict v = follows(c, c.conv(through_t.resolve(resolve_definitions(c.d, claim.sides[i]))), value.value, ref_eqs);
    v.method = prefix_method("the integral as a function of " + c.text(b), v.method);
    all.add(v, claim.sides.size() > 2 ? "side " + std::to_string(i + 1) : "");
  }
  return all.result();
}

// integral(f, x, a, b) = G (side0 is the integral, resolved).
// A name that a cited given expresses through t (`q = (m0 + k*t)*u`) is that function of t
// in the claim (names_through, context.hpp): its integral is the integral of its value.
Verdict definite_integral(StepContext& c, const Relation& claim, const Node& side0_in, const ex& t,
                          const std::vector<Eq>& ref_eqs) {
  const SymbolTable& symbols = c.d.symbols;
  const ThroughT through_t = names_through(c, t);
  const Node side0 = through_t.resolve(side0_in);
  std::vector<ex> sd{ex(0)};   // the closed forms (side 0, the integral, is not converted)
  for (std::size_t i = 1; i < claim.sides.size(); ++i)
    sd.push_back(c.conv(through_t.resolve(resolve_definitions(c.d, claim.sides[i]))));
  if (side0.args.size() != 4) c.fail(side0.pos, "expected integral(f, x, a, b)", side0.length);
  if (!to_ginac(side0.args[1], symbols).is_equal(t))
    c.fail(side0.args[1].pos, "the integration variable must be the rule's 'wrt' variable", side0.args[1].length);
  // the integrand in a fresh variable of integration (it ranges over (a, b), not over the domain
  // declared for the quantity of the same name); the references speak of it at b and a only
  const Integrand in = integrand_of(side0, symbols);
  const ex f = in.f, x = in.x;
  ex a = to_ginac(side0.args[2], symbols);
  ex b = to_ginac(side0.args[3], symbols);
  if (!GiNaC::is_a<GiNaC::symbol>(b))
    c.fail(side0.args[3].pos, "the upper limit of the integral must be a symbol (it is differentiated)",
           side0.args[3].length);
  if (claim.sides.size() < 2) c.fail(c.s.claim_pos, "expected 'integral(f, x, a, b) = G'");
  // The derivative test below treats the upper limit b as free. A reference that mentions b pins
  // it (T = 2*pi/omega: dG/dT = f(T) would be checked at one T only, and sin(omega*t/2) from 0
  // to T "integrates" to 0) or makes the integrand depend on it (F(t) = F0*t/T): the integral
  // is then computed as a function of b instead.
  for (const auto& q : ref_eqs)
    if (q.e.has(b)) return integral_through_references(c, claim, in, a, b, t, ref_eqs, through_t);
  std::vector<Eq> eqs = at_points(ref_eqs, t, {b, a});
  const GiNaC::symbol& bs = GiNaC::ex_to<GiNaC::symbol>(b);
  Combiner all;
  // The derivative test needs the integrand continuous in x and every claimed closed form
  // continuous in b (a G that jumps, such as atan(1/b) + atan(b), has the right derivative
  // wherever it is defined).
  bool continuous = continuous_everywhere(f, GiNaC::ex_to<GiNaC::symbol>(x));
  for (std::size_t i = 1; i < claim.sides.size() && continuous; ++i)
    continuous = continuous_everywhere(sd[i], GiNaC::ex_to<GiNaC::symbol>(b));
  if (f.has(b) || !continuous) {
    // The upper limit also appears in the integrand (d/db of the integral is not f(b)), or the
    // integrand is not known to be continuous between the limits (1/x from -1 to b: the
    // derivative test would accept log(b^2)/2 for a divergent integral): the closed form is
    // checked against a rigorous quadrature at sampled parameter values.
    // A refutation stands only when every reference can be satisfied independently of the
    // point (it constrains a function that neither the integrand nor the claim uses).
    bool refs_independent = true;
    for (const auto& q : ref_eqs)
      refs_independent =
          refs_independent && detail::has_abstract_application(q.e) && !detail::has_abstract_application(f);
    for (std::size_t i = 1; i < claim.sides.size(); ++i) {
      ex G = sd[i];
      refs_independent = refs_independent && !detail::has_abstract_application(G);
      Verdict v = kernel::probe_definite_integral(f, GiNaC::ex_to<GiNaC::symbol>(x), a, b, G, symbols, c.opt);
      if (v.kind == VerdictKind::Refuted && !refs_independent)
        v = undecided("rigorous quadrature", "the quadrature differs from the closed form at a point that need not "
                                             "satisfy the references");
      all.add(v, claim.sides.size() > 2 ? "side " + std::to_string(i + 1) : "");
    }
    c.res.derived = f.has(b) ? "the integrand depends on the upper limit " + c.text(b) + ": checked by rigorous quadrature"
                             : "the integrand or the closed form is not known to be continuous between the limits: "
                               "checked by rigorous quadrature";
    if (!through_t.given_values.empty()) c.res.derived += "; " + through_t.evidence;
    return all.result();
  }
  for (std::size_t i = 1; i < claim.sides.size(); ++i) {
    ex G = sd[i];
    Verdict v1 = follows(c, G.diff(bs), f.subs(x == b), eqs);
    v1.method = prefix_method("d/d" + c.text(b) + " of the closed form", v1.method);
    all.add(v1, "side " + std::to_string(i + 1) + ", derivative");
    Verdict v2 = follows(c, G.subs(b == a), 0, eqs);
    v2.method = prefix_method("value at the lower limit", v2.method);
    all.add(v2, "side " + std::to_string(i + 1) + ", at " + c.text(b) + " = " + c.text(a));
    if (i == 1) c.res.derived = "d/d" + c.text(b) + " (" + c.text(G) + ") = " + c.text(G.diff(bs));
  }
  if (!through_t.given_values.empty()) c.res.derived += "; " + through_t.evidence;
  return all.result();
}

// The cited ODE `diff(Y, t) = f` (the first reference).
struct Ode {
  ex Y, f;
  Node y_node;
};

Ode ode_of(StepContext& c) {
  const RuleSpec& rule = c.rule();
  const Relation& ar = claim_of(c.ref_step(rule.refs[0]));
  Node alhs = resolve_definitions(c.d, ar.sides[0]);
  if (ar.sides.size() < 2 || alhs.kind != NodeKind::Call || alhs.text != "diff" || alhs.args.size() < 2 ||
      (alhs.args.size() == 3 && to_text(alhs.args[2]) != "1"))
    c.fail(rule.refs[0].pos, "'" + rule.refs[0].label + "' must be an ODE 'diff(y(t), t) = f' for 'by integrate'",
           rule.refs[0].length);
  return {to_ginac(alhs.args[0], c.d.symbols), c.conv(ar.sides.back()), alhs.args[0]};
}

// `Y(b) - Y(a) = G  by integrate A wrt t [from a]`, and the fundamental-theorem chain
// `Y(b) - Y(a) = integral(g, t, a, b) = G`: the claim's first side is the change of the ODE's
// function between two points, b a symbol. Every further side must equal it:
//   - an integral from a to b whose integrand equals f (the references hold at every t);
//   - a closed form G: with Y(b) = Y(a) + G, dG/db = f at t = b and G = 0 at b = a (the
//     initial value problem in b that the change solves; f and G continuous, so it is the
//     integral of f from a to b).
// nullopt when the first side is not such a change.
std::optional<Verdict> change_form(StepContext& c, const Relation& claim, const ex& t, const Ode& ode,
                                   const std::vector<Eq>& ref_eqs) {
  const int fn = pool_function_index(ode.Y);
  if (fn < 0 || pool_derivative_order(ode.Y) != 0 || claim.sides.size() < 2) return std::nullopt;
  const ex cl = c.conv(claim.sides[0]);
  std::map<std::string, ex> at;   // the points where the claim's first side takes Y, by text
  bool plain = true;
  std::function<void(const ex&)> collect = [&](const ex& e) {
    if (pool_function_index(e) == fn) {
      plain = plain && pool_derivative_order(e) == 0;
      if (e.nops() == 1) at.emplace(c.text(e.op(0)), e.op(0));
      return;
    }
    for (std::size_t i = 0; i < e.nops(); ++i) collect(e.op(i));
  };
  collect(cl);
  if (!plain || at.size() != 2) return std::nullopt;
  const ex p = at.begin()->second, q = std::next(at.begin())->second;
  const GiNaC::symbol& ts = GiNaC::ex_to<GiNaC::symbol>(t);
  ex a, b;
  bool found = false;
  for (const auto& [hi, lo] : {std::pair{p, q}, std::pair{q, p}}) {
    if (!GiNaC::is_a<GiNaC::symbol>(hi)) continue;
    const ex change = ode.Y.subs(t == hi) - ode.Y.subs(t == lo);
    if (cl.is_equal(change) || prove_equal(cl, change, c.d.symbols, c.opt).kind == VerdictKind::Proved) {
      a = lo, b = hi, found = true;
      break;
    }
  }
  if (!found) return std::nullopt;
  const RuleSpec& rule = c.rule();
  if (rule.point && !c.conv(rule.point->value).is_equal(a))
    c.fail(rule.point->pos, "the claim is the change of " + c.text(ode.Y) + " from " + c.text(a) + " to " + c.text(b) +
                                ": the lower end after 'from' must be " + c.text(a),
           rule.point->length);
  const GiNaC::symbol& bs = GiNaC::ex_to<GiNaC::symbol>(b);
  const ex Ya = ode.Y.subs(t == a), Yb = ode.Y.subs(t == b);
  // A reference that mentions the end b pins it (t2 = 2*pi/omega): the derivative test in b
  // would hold at that b only. The change is then the integral of f from a to b, computed as a
  // function of b, and each side must follow from it and the references.
  for (const auto& q : ref_eqs) {
    if (!q.e.has(b)) continue;
    const std::string why = "a reference mentions the end " + c.text(b) + ", so the derivative test (which needs " +
                            c.text(b) + " free) does not apply";
    if (detail::has_abstract_application(ode.f))
      return undecided("integrate", why + ", and the right side of the ODE is not explicit");
    const GiNaC::symbol s("s_" + c.text(t));   // the variable of integration, unknown to the table
    const integrals::Definite value = integrals::definite_integral(ode.f.subs(t == s), s, a, 0, b, 0, c.d.symbols);
    if (value.kind != integrals::Definite::Kind::Value)
      return undecided("integrate", why + ", and the integral of " + c.text(ode.f) + " was not computed" +
                                        (value.why.empty() ? std::string() : ": " + value.why));
    c.res.derived = c.text(Yb) + " - " + c.text(Ya) + " = " + c.text(value.value);
    Combiner all;
    for (std::size_t i = 1; i < claim.sides.size(); ++i) {
      Verdict v = follows(c, c.conv(claim.sides[i]), value.value, ref_eqs);
      v.method = prefix_method("the change as a function of " + c.text(b), v.method);
      all.add(v, claim.sides.size() > 2 ? "side " + std::to_string(i + 1) : "");
    }
    return all.result();
  }
  const std::vector<Eq> at_ends = at_points(ref_eqs, t, {b, a});
  const bool f_continuous = continuous_everywhere(ode.f, ts);
  Combiner all;
  for (std::size_t i = 1; i < claim.sides.size(); ++i) {
    const std::string what = "side " + std::to_string(i + 1);
    const Node side = resolve_definitions(c.d, claim.sides[i]);
    if (side.kind == NodeKind::Call && side.text == "integral" && side.args.size() == 4) {
      const Integrand in = integrand_of(side, c.d.symbols);
      Verdict lo = prove_equal(to_ginac(side.args[2], c.d.symbols), a, c.d.symbols, c.opt);
      Verdict hi = prove_equal(to_ginac(side.args[3], c.d.symbols), b, c.d.symbols, c.opt);
      lo.method = prefix_method("lower limit", lo.method);
      hi.method = prefix_method("upper limit", hi.method);
      all.add(lo, what + ", lower limit " + c.text(a));
      all.add(hi, what + ", upper limit " + c.text(b));
      Verdict g = follows(c, in.f.subs(in.x == t, GiNaC::subs_options::no_pattern), ode.f, ref_eqs);
      g.method = prefix_method("the integrand is d/d" + c.text(t) + " " + c.text(ode.Y), g.method);
      all.add(g, what + ", integrand");
      continue;
    }
    const ex G = c.conv(claim.sides[i]);
    if (G.has(Yb) || !f_continuous || !continuous_everywhere(G, bs)) {
      all.add(undecided("integrate", "the right side of the ODE or the closed form " + c.text(G) +
                                         " is not known to be continuous between " + c.text(a) + " and " + c.text(b)),
              what);
      continue;
    }
    const ex fb = ode.f.subs(t == b).subs(Yb == Ya + G, GiNaC::subs_options::no_pattern);
    Verdict v1 = follows(c, G.diff(bs), fb, at_ends);
    v1.method = prefix_method("d/d" + c.text(b) + " of the closed form", v1.method);
    all.add(v1, what + ", derivative");
    Verdict v2 = follows(c, G.subs(bs == a), 0, at_ends);
    v2.method = prefix_method("value at " + c.text(b) + " = " + c.text(a), v2.method);
    all.add(v2, what + ", at " + c.text(b) + " = " + c.text(a));
    if (c.res.derived.empty()) c.res.derived = "d/d" + c.text(b) + " (" + c.text(G) + ") = " + c.text(G.diff(bs));
  }
  return all.result();
}

// The ODE form: A is diff(Y, t) = f; the claim is Y = G.
Verdict ode_form(StepContext& c, const Relation& claim, const ex& t, const ex& T0, const Ode& ode) {
  const RuleSpec& rule = c.rule();
  const GiNaC::symbol& ts = GiNaC::ex_to<GiNaC::symbol>(t);
  const ex Y = ode.Y, f = ode.f;
  if (claim.sides.size() < 2) c.fail(c.s.claim_pos, "expected the claim 'y(t) = G'");
  ex cl = c.conv(claim.sides[0]);
  if (!cl.is_equal(Y)) {
    Verdict v = prove_equal(cl, Y, c.d.symbols, c.opt);
    if (!v.holds())
      c.fail(claim.sides[0].pos,
             "the claim must start with '" + to_text(ode.y_node) + " = ...' (the function of the ODE), or be its "
             "change '" + to_text(ode.y_node) + " at b - at a = ...'",
             claim.sides[0].length);
  }
  // initial value
  ex y0 = Y.subs(t == T0), y0_value = y0;
  Substitutions at_T0;   // other values at T0, e.g. m_r(0) = m0
  for (const auto& w : rule.with) {
    ex l = c.conv(w.equation.sides[0]), r = c.conv(w.equation.sides[1]);
    if (l.is_equal(y0)) y0_value = r;
    else if (GiNaC::is_a<GiNaC::symbol>(l) || GiNaC::is_a<GiNaC::function>(l)) at_T0.push_back({l, r});
    else
      c.fail(w.pos,
             "expected 'y(T0) = value' after 'with' (the initial value of " + c.text(y0) + " or of another function)",
             w.length);
  }
  std::vector<Eq> extra;
  for (std::size_t i = 1; i < rule.refs.size(); ++i) {
    auto e = c.equations(rule.refs[i]);
    extra.insert(extra.end(), e.begin(), e.end());
  }
  extra = at_points(extra, t, {T0});
  Combiner all;
  for (std::size_t i = 1; i < claim.sides.size(); ++i) {
    ex G = c.conv(claim.sides[i]);
    ex fG = f.subs(Y == G);
    Verdict v1 = follows(c, G.diff(ts), fG, extra);
    v1.method = prefix_method("d/d" + c.text(t) + " of the closed form", v1.method);
    all.add(v1, "side " + std::to_string(i + 1) + ", derivative");
    Verdict v2 = follows(c, apply_subs(G.subs(t == T0), at_T0), apply_subs(y0_value, at_T0), extra);
    v2.method = prefix_method("initial value", v2.method);
    all.add(v2, "side " + std::to_string(i + 1) + ", at " + c.text(t) + " = " + c.text(T0));
    if (i == 1) c.res.derived = "d/d" + c.text(t) + " (" + c.text(G) + ") = " + c.text(G.diff(ts));
  }
  return all.result();
}

}  // namespace

// Without cited equations: each closed form against the integral by the whole cascade of
// integral_equal.hpp (exact, antiderivative test, an antiderivative found by rules with its
// limits -- improper integrals too --, rigorous quadrature).
Verdict integral_claim(StepContext& c, const Relation& claim, std::size_t at) {
  Combiner all;
  const Node integral = resolve_definitions(c.d, claim.sides[at]);
  for (std::size_t i = at + 1; i < claim.sides.size(); ++i) {
    std::optional<Verdict> v = integral_equality(integral, resolve_definitions(c.d, claim.sides[i]), c.d.symbols, c.opt);
    all.add(v ? *v : undecided("integral", "no integral to compare"),
            claim.sides.size() > at + 2 ? "side " + std::to_string(i + 1) : "");
  }
  return all.result();
}

Verdict integrate(StepContext& c, const Relation& claim) {
  const RuleSpec& rule = c.rule();
  // `W = integral(...) = G`: W names the result (Step::names_result); the integral is side 1
  const std::size_t at = c.s.names_result ? 1 : 0;
  Node side0 = resolve_definitions(c.d, claim.sides[at]);
  const bool is_integral = side0.kind == NodeKind::Call && side0.text == "integral";
  if (is_integral && rule.refs.empty()) {
    if (claim.sides.size() < at + 2) c.fail(c.s.claim_pos, "expected 'integral(f, x, a, b) = G'");
    if (rule.var && side0.args.size() == 4 && !c.symbol_of(*rule.var).is_equal(to_ginac(side0.args[1], c.d.symbols)))
      c.fail(side0.args[1].pos, "the integration variable must be the rule's 'wrt' variable", side0.args[1].length);
    return integral_claim(c, claim, at);
  }
  if (rule.refs.empty() && !rule.point) {
    // Integrals inside the claim's expressions, `U = -integral(F, s, oo, r) = -G*M*m/r`: each
    // link is compared with its integrals evaluated (integral_equal.hpp)
    bool any = false;
    std::function<bool(const Node&)> has = [&](const Node& n) {
      if (n.kind == NodeKind::Call && n.text == "integral") return true;
      for (const auto& a : n.args)
        if (has(a)) return true;
      return false;
    };
    std::vector<Node> sides;
    for (std::size_t i = at; i < claim.sides.size(); ++i) {
      sides.push_back(resolve_definitions(c.d, claim.sides[i]));
      any = any || has(sides.back());
    }
    if (any && sides.size() >= 2) {
      Combiner all;
      for (std::size_t i = 0; i + 1 < sides.size(); ++i) {
        std::optional<Verdict> v = integral_equality(sides[i], sides[i + 1], c.d.symbols, c.opt);
        all.add(v ? *v : prove_equal(to_ginac(sides[i], c.d.symbols), to_ginac(sides[i + 1], c.d.symbols), c.d.symbols, c.opt),
                sides.size() > 2 ? "link " + std::to_string(i + 1) : "");
      }
      return all.result();
    }
  }
  if (!rule.var && !rule.refs.empty()) {   // a differential equation (integrate_differential.cpp)
    const std::vector<Eq> a = c.equations(rule.refs[0]);
    if (!a.empty() && !differentials_in(a[0].e, c.d.symbols).empty()) return integrate_differential(c, claim);
  }
  if (!rule.var)
    c.fail(rule.pos, "'by integrate' with cited equations needs the variable: 'by integrate A wrt t ...' (or, for a "
                     "differential equation A such as d(v) = a*d(t), its start: 'by integrate A with v = v0, t = t0')",
           static_cast<int>(rule.text.size()));
  ex t = c.symbol_of(*rule.var);
  std::vector<Eq> ref_eqs = c.all_equations(rule.refs);
  if (is_integral) return definite_integral(c, claim, side0, t, ref_eqs);
  if (rule.refs.empty())
    c.fail(rule.pos, "without a cited ODE the claim of 'by integrate' must be 'integral(f, x, a, b) = G'; to solve an ODE "
                     "write 'by integrate A wrt t from T0' with A the ODE 'diff(y(t), t) = f'",
           static_cast<int>(rule.text.size()));
  const Ode ode = ode_of(c);
  if (auto v = change_form(c, claim, t, ode, ref_eqs)) return *v;
  if (!rule.point)
    c.fail(rule.pos, "the ODE form of 'by integrate' needs the initial time: 'by integrate " + rule.refs[0].label +
                         " wrt " + rule.var->label + " from T0'",
           static_cast<int>(rule.text.size()));
  ex T0 = c.conv(rule.point->value);
  return ode_form(c, claim, t, T0, ode);
}

}  // namespace dc::rules
