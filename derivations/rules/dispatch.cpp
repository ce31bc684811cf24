// Rule name -> rule function, and the one place where a rule's failure becomes a verdict.
#include "derivations/rules/dispatch.hpp"

#include <string>
#include <utility>

#include "derivations/symbolic/symbols.hpp"

namespace dc::rules {

namespace {

// The canonical names of docs/format.md, "Rules" (the parser maps simplify, expand, factor
// and algebra to rewrite).
constexpr std::pair<const char*, Rule> kRules[] = {
    {"given", given},
    {"definition", definition},
    {"rewrite", rewrite},
    {"substitute", substitute},
    {"solve", solve},
    {"limit", limit},
    {"series", series},
    {"first_order", first_order},
    {"differentiate", differentiate},
    {"integrate", integrate},
    {"solves_ode", solves_ode},
    {"stationary", stationary},
    {"maximum", stationary},
    {"minimum", stationary},
    {"instance", instance},
    {"coefficients", coefficients},
};

Verdict dispatch(StepContext& c, const Relation& claim) {
  const std::string& name = c.rule().name;
  for (const auto& [rule_name, rule] : kRules)
    if (name == rule_name) return rule(c, claim);
  c.fail(c.rule().pos, "unknown rule '" + name + "'");
}

}  // namespace

Verdict run_rule(const Derivation& d, const Step& s, const Relation& claim, const ProveOptions& opt,
                 StepResult& res) {
  try {
    StepContext c(d, s, opt, res);
    return dispatch(c, claim);
  } catch (const StepError& e) {
    res.errors.push_back(e.error);
    if (e.input) res.input_error = true;
    return undecided(s.rule.name, "the step could not be checked: " + e.error.message());
  } catch (const InputError& e) {
    res.errors.push_back(with_line(d, e));
    return undecided(s.rule.name, "the step could not be checked: " + e.message());
  } catch (const UndecidedLimit& e) {
    return undecided("limit", e.what());
  } catch (const std::exception& e) {
    // GiNaC arithmetic errors (division by zero in a substitution, pole in a series, ...):
    // the rule could not carry out its derivation; never shown with GiNaC internals.
    std::string what = e.what();
    if (what.find("division by zero") != std::string::npos) what = "division by zero while deriving";
    else what = "the symbolic computation failed";
    return undecided(s.rule.name, what);
  }
}

}  // namespace dc::rules
