// `by rewrite [refs] [with x = value, ...]` (also written simplify, expand, factor, algebra):
// every link of the claim follows from the references, with the substitutions applied to the
// claim and to the references. Without references the claim must be an identity. An
// expression step (no `=`) has nothing to compare; its side conditions are still checked.
#include "derivations/rules/dispatch.hpp"
#include "derivations/steps/follows.hpp"

namespace dc::rules {

Verdict rewrite(StepContext& c, const Relation& claim) {
  std::vector<ex> sd = c.sides(claim);
  std::vector<std::string> labels;
  auto subs = c.substitutions(c.rule().with, nullptr, &labels);
  for (auto& e : sd) e = apply_subs(e, subs);
  if (sd.size() < 2) {
    // An expression step: nothing to compare; its side conditions are still checked.
    return proved("expression", "an expression (no equation to check)");
  }
  std::vector<Eq> eqs = c.all_equations(c.rule().refs);
  for (auto& q : eqs) apply_to(q, subs, labels);
  add_path_differentials(c, sd, eqs);
  return links_follow(c, sd, eqs, c.rule().refs.empty() ? "identity" : "rewrite");
}

}  // namespace dc::rules
