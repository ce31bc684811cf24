// `by differentiate A, ... wrt t`: the claim follows from the references and their derivatives
// in t. Without references the claim's own diff(...) is carried out and each link must hold.
// Only equations that contain a function of t (x(t) = a*t^2/2) hold for every t and may be
// differentiated; differentiating y = F0*t with y a plain symbol would "derive" 0 = F0. A
// plain symbol that a cited definition or given `y = expr` expresses through t is instead a
// function of t in the claim: its value there is expr (names_through, context.hpp), so
// `diff(y, t) = F0` holds and `0 = F0` is still refuted.
#include "derivations/rules/dispatch.hpp"
#include "derivations/steps/follows.hpp"
#include "derivations/symbolic/vectors.hpp"

namespace dc::rules {

namespace {

bool has_diff_call(const Node& n) {
  if (n.kind == NodeKind::Call && n.text == "diff") return true;
  for (const auto& a : n.args)
    if (has_diff_call(a)) return true;
  return false;
}

}  // namespace

Verdict differentiate(StepContext& c, const Relation& claim) {
  const RuleSpec& rule = c.rule();
  if (rule.refs.empty()) {
    // The claim's own derivative: `diff(A*sin(omega*t), t) = A*omega*cos(omega*t)`; each link
    // of the chain must hold with diff(...) carried out.
    bool any = false;
    for (const auto& side : claim.sides) any = any || has_diff_call(resolve_definitions(c.d, side));
    if (!any)
      c.fail(c.s.claim_pos, "without a cited equation the claim of 'by differentiate' must contain diff(...)");
    std::vector<ex> sd = c.sides(claim);
    if (sd.size() < 2) c.fail(c.s.claim_pos, "the claim of 'by differentiate' must be an equation");
    c.res.derived = c.text(sd[0]);
    return links_follow(c, sd, {}, "differentiate");
  }
  ex t = c.symbol_of(*rule.var);
  const GiNaC::symbol& ts = GiNaC::ex_to<GiNaC::symbol>(t);
  std::vector<Eq> eqs, originals;
  for (const auto& a : rule.refs)
    for (auto& q : c.equations(a)) {
      originals.push_back(q);
      if (has_application_at(q.e, t)) eqs.push_back({q.e.diff(ts), ex(), q.from});
    }
  // A name that is a function of t by a cited definition (`p = (m0 + k*t)*u  by definition`,
  // `H(t) = ...`) or given (`q = (m0 + k*t)*u  by given`, q a plain symbol): every use of it
  // in the claim is its value at t, so the claim's own derivative carries the reference (its
  // equation is an identity once the name is resolved).
  const ThroughT through_t = names_through(c, t);
  if (eqs.empty() && !through_t.evidence.empty()) {
    std::vector<ex> sd = through_t.sides(c, claim);
    if (sd.size() < 2) c.fail(c.s.claim_pos, "the claim of 'by differentiate' must be an equation");
    Verdict v = links_follow(c, sd, originals, "differentiate");
    v.detail += (v.detail.empty() ? "" : "; ") + through_t.evidence;
    return v;
  }
  if (eqs.empty()) {
    const RuleArg& a = rule.refs[0];
    c.fail(a.pos, "'" + a.label + "' contains no function of " + c.text(t) +
                      ": a plain symbol is one value and cannot be differentiated (declare the quantities that vary "
                      "with " + c.text(t) + " as functions of " + c.text(t) + ")",
           a.length);
  }
  // the derivative of the first equation, as derived
  std::string derived;
  if (const Relation& first = claim_of(c.ref_step(rule.refs[0])); vector_shape(first, c.d.symbols) == 0) {
    std::vector<ex> as = c.sides(first);
    if (as.size() >= 2) derived = c.text(as[0].diff(ts)) + " = " + c.text(as[1].diff(ts));
  }
  c.res.derived = derived;
  eqs.insert(eqs.end(), originals.begin(), originals.end());
  std::vector<ex> sd = through_t.sides(c, claim);
  if (sd.size() < 2) c.fail(c.s.claim_pos, "the claim of 'by differentiate' must be an equation");
  Verdict v = links_follow(c, sd, eqs, "differentiate");
  if (!through_t.given_values.empty()) v.detail += (v.detail.empty() ? "" : "; ") + through_t.evidence;
  return v;
}

}  // namespace dc::rules
