// `by given` and `by definition`: premises. Nothing is derived; the step is checked only for
// declared symbols and dimensions (check.cpp), and its side conditions only warn.
#include "derivations/rules/dispatch.hpp"

#include "derivations/syntax/expr.hpp"
#include "derivations/steps/follows.hpp"
#include "derivations/rules/in_domain.hpp"
#include "derivations/symbolic/inspect.hpp"
#include "derivations/symbolic/printer.hpp"

#include <optional>

namespace dc::rules {

Verdict given(StepContext&, const Relation&) { return proved("given", "premise taken from the source"); }

// `T = E - m*c^2 = (gamma - 1)*m*c^2  by definition`: the first link defines T (definition_of);
// every further link is a claim about the definition, checked as an identity -- a definition
// must not make a false equation citable.
Verdict definition(StepContext& c, const Relation& claim) {
  std::optional<SideCondition> domain_note;
  // A name declared with a domain (`symbol Q : positive`) must get a value in it: Q = -a would
  // be a premise that contradicts the declaration (and makes Q = -a < 0 citable).
  if (claim.sides[0].kind == NodeKind::Symbol)
    if (const SymbolInfo* info = c.d.symbols.find(claim.sides[0].text);
        info && !info->defined_by_step && !info->is_function && !info->domain.unrestricted()) {
      const ex value = c.conv(claim.sides[1]);
      // A value through a declared function (`R = x(T)`) takes whatever the file's premises
      // say of that function, which this premise-free check does not know: random function
      // values are no counterexample. The requirement is then a side condition.
      if (detail::has_abstract_application(value)) {
        SideCondition sc;
        sc.what = print_text(value, c.d.symbols) + " is " + info->domain.to_string();
        sc.reason = "declared domain of " + info->name;
        sc.status = SideCondition::Status::Unknown;
        sc.evidence = "depends on a declared function";
        domain_note = sc;
      } else {
        Verdict in = value_in_domain(value, info->domain, c.d.symbols, c.opt);
        if (in.kind == VerdictKind::Refuted) {
          in.detail = "the value defined for " + info->name + " must be " + info->domain.to_string() + ": " + in.detail;
          return in;
        }
        if (in.kind == VerdictKind::Undecided) {   // k = n/2 for an integer k: said, not hidden
          SideCondition sc;
          sc.what = print_text(value, c.d.symbols) + " is " + info->domain.to_string();
          sc.reason = "declared domain of " + info->name;
          sc.status = SideCondition::Status::Unknown;
          sc.evidence = in.reason;
          domain_note = sc;
        }
      }
    }
  auto with_note = [&](Verdict v) {
    if (domain_note) v.side_conditions.push_back(*domain_note);
    return v;
  };
  if (claim.sides.size() <= 2) return with_note(proved("definition", "introduces " + to_text(claim.sides[0])));
  std::vector<ex> links;
  for (std::size_t i = 1; i < claim.sides.size(); ++i) links.push_back(c.conv(claim.sides[i]));
  Verdict v = links_follow(c, links, {}, "identity");
  v.method = prefix_method("definition of " + to_text(claim.sides[0]) + ", further links", v.method);
  return with_note(v);
}

}  // namespace dc::rules
