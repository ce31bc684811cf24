// `by given` and `by definition`: premises. Nothing is derived; the step is checked only for
// declared symbols and dimensions (check.cpp), and its side conditions only warn.
#include "derivations/rules/dispatch.hpp"

#include "derivations/core/expr.hpp"

namespace dc::rules {

Verdict given(StepContext&, const Relation&) { return proved("given", "premise taken from the source"); }

Verdict definition(StepContext&, const Relation& claim) {
  return proved("definition", "introduces " + to_text(claim.sides[0]));
}

}  // namespace dc::rules
