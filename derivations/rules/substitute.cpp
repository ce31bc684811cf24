// `by substitute S... into C [with x = value]`: the claim must follow from C with the
// substitutions applied and from the substitutions themselves taken as equations. (The claim
// may still mention a substituted name, T = 2*pi/omega, or a defined name whose definition
// brings one in; a counterexample must then respect omega = sqrt(k/m) too.)
#include <algorithm>

#include "derivations/symbolic/functions.hpp"
#include "derivations/symbolic/vectors.hpp"
#include "derivations/rules/dispatch.hpp"
#include "derivations/steps/follows.hpp"

namespace dc::rules {

Verdict substitute(StepContext& c, const Relation& claim) {
  const RuleSpec& rule = c.rule();
  std::vector<Eq> extra;   // references that are not `x = value`: equations only (added below)
  std::vector<std::string> labels;
  auto subs = c.substitutions(rule.refs, &extra, &labels);
  auto w = c.substitutions(rule.with, nullptr, &labels);
  subs.insert(subs.end(), w.begin(), w.end());

  // C with the substitutions applied: C' (a vector C: each of its components)
  const Step& into = c.ref_step(rule.into[0]);
  const Relation& into_claim = claim_of(into);
  const int components = vector_shape(into_claim, c.d.symbols);
  std::vector<std::vector<ex>> parts;
  for (int k = components ? 1 : 0; k <= components; ++k)
    parts.push_back(c.sides(components ? vector_component(into_claim, c.d.symbols, k) : into_claim));
  std::vector<std::string> applied;   // the substitutions C' rests on
  for (auto& part : parts)
    for (auto& e : part) {
      std::vector<bool> used;
      e = apply_subs(e, subs, &used);
      for (std::size_t i = 0; i < used.size(); ++i)
        if (used[i] && std::find(applied.begin(), applied.end(), labels[i]) == applied.end()) applied.push_back(labels[i]);
    }
  const std::vector<ex>& cs = parts.front();

  // The equations: C' and every reference and substitution
  std::vector<Eq> eqs;
  for (const auto& part : parts)
    for (std::size_t i = 0; i + 1 < part.size(); ++i) {
      Eq q{part[i] - part[i + 1], ex(), into.label, applied};
      if (i == 0 && (GiNaC::is_a<GiNaC::symbol>(part[0]) || pool_function_index(part[0]) >= 0)) q.hint = part[0];
      eqs.push_back(q);
    }
  for (const auto* group : {&rule.refs, &rule.with})
    for (const auto& a : *group) {
      auto e = c.equations(a);
      eqs.insert(eqs.end(), e.begin(), e.end());
    }
  for (const auto& part : parts) {
    const std::string text = part.size() >= 2 ? c.text(part.front()) + " = " + c.text(part.back())
                                              : part.empty() ? std::string() : c.text(part.front());
    c.res.derived += (c.res.derived.empty() ? "" : "; ") + text;
  }

  std::vector<ex> sd = c.sides(claim);
  add_path_differentials(c, sd, eqs);
  if (cs.size() < 2) {
    // substituting into an expression: the claim must be that expression
    if (sd.size() != 1) c.fail(rule.into[0].pos, "'" + into.label + "' is an expression; the claim must be one too");
    Verdict v = follows(c, sd[0], cs[0], eqs);
    v.method = prefix_method("substitute", v.method);
    return v;
  }
  if (sd.size() < 2) c.fail(c.s.claim_pos, "expected an equation as the claim of 'by substitute'");
  Verdict v = links_follow(c, sd, eqs, "substitute");
  // Substituting into C can leave an identity (C itself substituted into C). When the claim
  // does not follow, say so, rather than show a line that reads as evidence against the claim.
  if (!v.holds()) try {
      if (GiNaC::normal(cs.front() - cs.back()).is_zero())
        c.res.derived += ", an identity: nothing is derived from '" + into.label + "' by this substitution";
    } catch (const std::exception&) {
    }
  return v;
}

}  // namespace dc::rules
