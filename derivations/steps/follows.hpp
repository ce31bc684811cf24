// "The claim follows from equations" (derivations/steps/, shared by the rules): the shared tool of the
// rules. The equations are reduced (elimination.hpp; references that contradict each other
// are an input error), both sides of the claim are reduced with the eliminations, and
// prove_equal decides. A refutation stands only when its point satisfies the references
// (counterexample.hpp).
#pragma once
#include <string>
#include <vector>

#include "derivations/steps/context.hpp"
#include "derivations/steps/elimination.hpp"

namespace dc::rules {

// Part of the reason of a proof that holds on one component of the references' solutions only
// (follows.cpp): the document search retries such a set without a slip among its rows.
inline constexpr const char* kOneComponent = "one component of their solutions";

// Does a = b follow from the equations? When a refutation's point fails because of one
// elimination (it puts F0 = y/t outside F0's domain, or gives sin(theta) a value theta does not
// have), the reduction is redone without that choice: any valid reduction proves, and any
// certified point refutes.
Verdict follows(StepContext& c, const ex& a, const ex& b, const std::vector<Eq>& eqs0,
                const std::vector<ex>& preferred = {});

// Every link of a chain a = b = c follows (each with `follows`), the method prefixed by the
// rule's.
Verdict links_follow(StepContext& c, const std::vector<ex>& sd, const std::vector<Eq>& eqs,
                     const std::string& rule_method, const std::vector<ex>& preferred = {});

// References whose equations reduce to a nonzero constant (a = 1 and a = 2 leave -1 = 0) have
// no common solution, and anything would follow from them: throws StepError (an input error
// naming them), never a premise of a proof. (Only for equations of references, never for a
// claim substituted back, which is simply refuted.)
void reject_contradictions(StepContext& c, const Reduction& red, const std::vector<Eq>& eqs);

// Does e contain an application y(s) (or a derivative of one) of a declared function at s? An
// equation with one holds for every value of s (y(t) = F0*t), so it may be used at other
// values of s. An equation between plain symbols (y = F0*t with y a symbol) is one value:
// instantiating it at two points would give y = F0*t1 and y = 0, from which anything follows.
bool has_application_at(const ex& e, const ex& s);

// "reference 'a1'" / "references 'a1' and 'a2'" / "references 'e1', 'e2' and 'e3'", in the
// order the rule lists them.
std::string reference_names(const std::vector<int>& sources, const std::vector<Eq>& eqs);

}  // namespace dc::rules
