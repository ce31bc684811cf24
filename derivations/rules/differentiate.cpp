// `by differentiate A, ... wrt t`: the claim follows from the references and their derivatives
// in t. Without references the claim's own diff(...) is carried out and each link must hold. Only equations that contain a function of t (x(t) = a*t^2/2) hold for every t and may
// be differentiated; an equation between plain symbols (y = F0*t, y a symbol) is one value,
// and differentiating it would "derive" 0 = F0. Such equations are used as they are.
#include "derivations/rules/dispatch.hpp"
#include "derivations/rules/follows.hpp"

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
  // A name defined through t (`p = (m0 + k*t)*u  by definition`, `H(t) = ...`) is a function
  // of t: every use of it in the claim is its definition, so the claim's own derivative
  // carries the reference (its equation is an identity once the name is resolved).
  std::string through_t;
  for (const auto& a : rule.refs) {
    if (a.kind != RuleArg::Kind::Label) continue;
    const Step& r = c.ref_step(a);
    if (r.rule.name == "definition" && introduces_name(r) && c.conv(r.claim.sides[1]).has(t))
      through_t += std::string(through_t.empty() ? "" : "; ") + to_text(r.claim.sides[0]) + " is a function of " +
                   c.text(t) + " by its definition " + r.label;
  }
  if (eqs.empty() && !through_t.empty()) {
    std::vector<ex> sd = c.sides(claim);
    if (sd.size() < 2) c.fail(c.s.claim_pos, "the claim of 'by differentiate' must be an equation");
    Verdict v = links_follow(c, sd, originals, "differentiate");
    v.detail += (v.detail.empty() ? "" : "; ") + through_t;
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
  {
    std::vector<ex> as = c.sides(claim_of(c.ref_step(rule.refs[0])));
    if (as.size() >= 2) derived = c.text(as[0].diff(ts)) + " = " + c.text(as[1].diff(ts));
  }
  c.res.derived = derived;
  eqs.insert(eqs.end(), originals.begin(), originals.end());
  std::vector<ex> sd = c.sides(claim);
  if (sd.size() < 2) c.fail(c.s.claim_pos, "the claim of 'by differentiate' must be an equation");
  return links_follow(c, sd, eqs, "differentiate");
}

}  // namespace dc::rules
