// `by given` and `by definition`: premises. Nothing is derived; the step is checked only for
// declared symbols and dimensions (check.cpp), and its side conditions only warn.
#include "derivations/rules/dispatch.hpp"

#include "derivations/core/expr.hpp"
#include "derivations/rules/follows.hpp"

namespace dc::rules {

Verdict given(StepContext&, const Relation&) { return proved("given", "premise taken from the source"); }

// `T = E - m*c^2 = (gamma - 1)*m*c^2  by definition`: the first link defines T (definition_of);
// every further link is a claim about the definition, checked as an identity -- a definition
// must not make a false equation citable.
Verdict definition(StepContext& c, const Relation& claim) {
  if (claim.sides.size() <= 2) return proved("definition", "introduces " + to_text(claim.sides[0]));
  std::vector<ex> links;
  for (std::size_t i = 1; i < claim.sides.size(); ++i) links.push_back(c.conv(claim.sides[i]));
  Verdict v = links_follow(c, links, {}, "identity");
  v.method = prefix_method("definition of " + to_text(claim.sides[0]) + ", further links", v.method);
  return v;
}

}  // namespace dc::rules
