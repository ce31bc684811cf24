// check_step and check_derivation (check.hpp): around the rule (dispatch.cpp), each step is
// also checked for dimensions, side conditions of its claim, an erratum's printed claim and a
// stable form's equality with the form it replaces.
#include "derivations/rules/check.hpp"

#include <algorithm>
#include <chrono>
#include <functional>

#include "derivations/decide/common_domain.hpp"
#include "derivations/steps/context.hpp"
#include "derivations/rules/dispatch.hpp"
#include "derivations/rules/in_domain.hpp"
#include "derivations/rules/plus_minus.hpp"
#include "derivations/symbolic/vectors.hpp"

namespace dc {

namespace {

using rules::positioned;
using rules::with_line;

// Dimension of every side; a mismatch is an error at the claim with both dimensions.
void check_dimensions(const Derivation& d, const Step& s, const Relation& claim, StepResult& res) {
  std::vector<Dimension> dims;
  std::vector<const Node*> nodes;
  for (const auto& side : claim.sides) {
    if (limit_value_side(s, side, d.symbols)) continue;   // oo, -oo, undefined
    // A literal 0 has every dimension (`m_p*v_p - m_c*v_c = 0`).
    if (is_literal_zero(side)) continue;
    nodes.push_back(&side);
    try {
      dims.push_back(dimension_of(side, d.symbols));
    } catch (const InputError& e) {
      res.errors.push_back(with_line(d, e));
      return;
    }
  }
  if (dims.empty()) return;
  for (std::size_t i = 1; i < dims.size(); ++i) {
    if (dims[i] != dims[0]) {
      const Node& n = *nodes[i];
      res.errors.push_back(positioned(
          d, n.pos,
          "dimension mismatch: '" + to_text(*nodes[0]) + "' has dimension " + dims[0].to_string() + " but '" +
              to_text(n) + "' has dimension " + dims[i].to_string(),
          n.length));
      return;
    }
  }
  res.dimension = dims[0].to_string();
}

// The printed claim of an erratum step: an undefined symbol is reported at its position; a
// well-formed but wrong printed claim is reported with its refutation.
void check_erratum(const Derivation& d, const Step& s, const ProveOptions& opt, StepResult& res) {
  if (auto err = erratum_error(d, s)) {
    res.errors.push_back(*err);
    res.erratum_reported = true;
    return;
  }
  StepResult printed;
  printed.step = &s;
  Verdict pv = rules::run_rule(d, s, s.claim, opt, printed);
  if (pv.kind == VerdictKind::Refuted || !printed.errors.empty()) {
    std::string why = !printed.errors.empty() ? printed.errors[0].message()
                                              : "refuted" + (pv.detail.empty() ? std::string() : " (" + pv.detail + ")");
    res.errors.push_back(positioned(d, s.claim_pos, "the printed claim is wrong: " + why + "; erratum: " + s.erratum->why,
                                    static_cast<int>(std::max<std::size_t>(1, s.claim_text.size()))));
    res.erratum_reported = true;
  } else {
    res.errors.push_back(positioned(d, s.erratum->pos,
                                    "an erratum is declared but the printed claim is not refuted (" +
                                        std::string(to_string(pv.kind)) + "); remove the erratum or fix the claim",
                                    7));
  }
}

bool has_calculus(const Node& n) {
  if (n.kind == NodeKind::Call && (n.text == "integral" || n.text == "diff" || n.text == "limit" || n.text == "O" ||
                                    n.text == "eval_between"))
    return true;
  for (const auto& a : n.args)
    if (has_calculus(a)) return true;
  return false;
}

// Side conditions of the claim's sides (not of what an integral's or a limit's bound variable
// needs). `written` receives each side as written (its parts and conditions) when every side is
// an expression without calculus (no integral, derivative, limit or order term), else stays empty.
void add_claim_side_conditions(const Derivation& d, const Step& s, const Relation& claim, StepResult& res,
                               std::vector<WrittenSide>& written) {
  try {
    const bool asymptotic = (s.rule.name == "limit" || s.rule.name == "series") && s.rule.var;
    bool plain = !asymptotic && !s.names_result;
    for (std::size_t si = 0; si < claim.sides.size(); ++si) {
      const Node& side = claim.sides[si];
      if (limit_value_side(s, side, d.symbols)) {
        plain = false;
        continue;
      }
      Node n = resolve_definitions(d, side);
      plain = plain && !has_calculus(n);
      // A limit or series claim is about x near the point only (`x*log(x) = 0  by limit x -> 0+`,
      // `log(sin(x)) = log(x) - x^2/6  by series x -> 0+ to order 4`): the conditions of parts
      // that involve x are not claims about x's whole domain (the limit engine decides where the
      // expressions are real near the point); the conditions of parts free of x are.
      WrittenSide w;
      w.conditions = side_conditions_of_tree_parts(n, d.symbols, asymptotic ? s.rule.var->label : std::string(), w.parts);
      if (plain) w.value = to_ginac(n, d.symbols);
      for (auto& sc : w.conditions) {
        bool dup = false;
        for (const auto& o : res.verdict.side_conditions) dup = dup || o.what == sc.what;
        if (!dup) res.verdict.side_conditions.push_back(sc);
      }
      written.push_back(std::move(w));
    }
    if (!plain) written.clear();
  } catch (const std::exception&) {
    // conversion problems were reported by the rule already
    written.clear();
  }
}

// A stable form must equal the form it replaces.
void check_stable_form(const Derivation& d, const Step& s, const ProveOptions& opt, StepResult& res) {
  const Step* other = d.find(*s.stable_of);
  try {
    auto a = claim_sides(d, s);
    auto b = claim_sides(d, *other);
    Verdict v = prove_equal(a.back(), b.back(), d.symbols, opt);
    if (!v.holds())
      res.errors.push_back(positioned(d, s.pos,
                                      "the stable form is not equal to '" + *s.stable_of + "' (" +
                                          std::string(to_string(v.kind)) + (v.detail.empty() ? "" : ": " + v.detail) + ")",
                                      static_cast<int>(s.label.size())));
  } catch (const std::exception& e) {
    res.errors.push_back(positioned(d, s.pos, "the stable form cannot be compared with '" + *s.stable_of + "'",
                                    static_cast<int>(s.label.size())));
  }
}

}  // namespace

namespace {
StepResult check_one_sign(const Derivation& d, const Step& s, const ProveOptions& opt);
}  // namespace

// A vector claim: one check per component (symbolic/vectors.hpp), each by the step's rule on
// the component's equation; the step holds when every component does, and a component that
// does not speaks for the step, named in the method and the derived line.
namespace {
StepResult check_components(const Derivation& d, const Step& s, const ProveOptions& opt, int k) {
  auto worse = [](const StepResult& r) { return rules::severity(r.verdict.kind); };
  StepResult out;
  std::vector<InputError> errors;
  double seconds = 0;
  for (int i = 1; i <= k; ++i) {
    Step c = s;
    c.claim = vector_component(s.claim, d.symbols, i);
    if (c.erratum) c.erratum->corrected = vector_component(s.erratum->corrected, d.symbols, i);
    StepResult r = check_step(d, c, opt);
    r.step = &s;
    seconds += r.seconds;
    for (const auto& e : r.errors) {
      bool seen = false;
      for (const auto& f : errors) seen = seen || (f.message() == e.message() && f.pos().line == e.pos().line);
      if (!seen) errors.push_back(e);
    }
    const std::string text = to_text(c.erratum ? c.erratum->corrected : c.claim);
    const std::string which = "component " + std::to_string(i) + (text.size() <= 60 ? " (" + text + ")" : "");
    if (!r.verdict.holds()) {
      r.verdict.method = which + ": " + r.verdict.method;
      r.derived = r.derived.empty() ? which : which + ": " + r.derived;
    }
    if (i == 1 || worse(r) > worse(out)) out = std::move(r);
  }
  if (out.verdict.holds()) out.verdict.method = "each component: " + out.verdict.method;
  out.errors = std::move(errors);
  out.seconds = seconds;
  return out;
}
}  // namespace

StepResult check_step(const Derivation& d, const Step& s, const ProveOptions& opt) {
  int components = 0;
  try {
    components = vector_shape(s.erratum ? s.erratum->corrected : s.claim, d.symbols);
  } catch (const InputError&) {
    // reported where the claim is converted
  }
  if (components) return check_components(d, s, opt, components);
  if (plus_minus_sign() == 0 && rules::mentions_plus_minus(d, s)) {
    auto t0 = std::chrono::steady_clock::now();
    StepResult r = rules::check_both_signs(d, s, opt, check_one_sign);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
  }
  return check_one_sign(d, s, opt);
}

namespace {
StepResult check_one_sign(const Derivation& d, const Step& s, const ProveOptions& opt) {
  auto t0 = std::chrono::steady_clock::now();
  StepResult res;
  res.step = &s;
  const Relation& claim = s.erratum ? s.erratum->corrected : s.claim;
  if (s.erratum) check_erratum(d, s, opt, res);
  check_dimensions(d, s, claim, res);
  res.verdict = rules::run_rule(d, s, claim, opt, res);
  std::vector<WrittenSide> written;
  add_claim_side_conditions(d, s, claim, res, written);
  // A claim must hold on the whole declared domain (premises only warn); where every side is
  // undefined is not a counterexample (decide/common_domain.hpp).
  if (s.rule.name != "given" && s.rule.name != "definition") {
    if (written.size() >= 2) require_defined_on_common_domain(res.verdict, written, d.symbols);
    else require_defined_on_domain(res.verdict);
  }
  if (s.first_side_fresh && res.verdict.kind == VerdictKind::Refuted && claim.sides.size() >= 2) {
    // Most likely the author meant to define the name; say how (docs/format.md, "Chains and names").
    const std::string name = to_text(claim.sides[0]);
    res.verdict.detail += std::string(res.verdict.detail.empty() ? "" : "; ") + "'" + name +
                          "' appears in no earlier step, so nothing determines it: only a definition introduces a name " +
                          "(write '" + name + " = " + to_text(claim.sides[1]) +
                          "  by definition' as a step of its own and derive the rest from it)";
  }
  // An ODE solution proved by residual and initial values holds only up to a singularity.
  const std::size_t first = s.names_result ? 1 : 0;   // `W = integral(...) = G` names the result
  const bool integral_claim = claim.sides.size() > first && claim.sides[first].kind == NodeKind::Call &&
                              claim.sides[first].text == "integral";
  if ((s.rule.name == "solves_ode" || (s.rule.name == "integrate" && !integral_claim)) && s.rule.var)
    require_solution_without_singularities(res.verdict, s.rule.var->label);
  if (s.stable_of) check_stable_form(d, s, opt, res);
  // `M = integral(...) = G` naming a quantity declared `positive`: G must be positive too
  if (s.names_result && claim.sides[0].kind == NodeKind::Symbol)
    if (const SymbolInfo* info = d.symbols.find(claim.sides[0].text);
        info && !info->domain.unrestricted() && res.verdict.holds()) {
      try {
        Verdict in = rules::value_in_domain(claim_sides(d, s).back(), info->domain, d.symbols, opt);
        if (!in.holds() || in.kind == VerdictKind::HoldsNumerically) {
          const bool refuted = in.kind == VerdictKind::Refuted;
          const std::string why = "the value named " + info->name + " must be " + info->domain.to_string() + ": " +
                                  (in.detail.empty() ? in.reason : in.detail);
          if (in.holds()) {   // holds numerically: so does the step
            if (res.verdict.kind == VerdictKind::Proved) {
              res.verdict.kind = VerdictKind::HoldsNumerically;
              res.verdict.points = in.points;
              res.verdict.digits = in.digits;
              res.verdict.false_accept = in.false_accept;
            }
            res.verdict.method = rules::prefix_method(res.verdict.method, in.method);
          } else {
            res.verdict.kind = refuted ? VerdictKind::Refuted : VerdictKind::Undecided;
            res.verdict.method = rules::prefix_method(res.verdict.method, in.method);
            if (refuted) res.verdict.detail = why, res.verdict.point = in.point;
            else res.verdict.reason = why;
          }
        }
      } catch (const std::exception&) {
        res.verdict.kind = VerdictKind::Undecided;
        res.verdict.reason = "the value named " + info->name + " could not be compared with its declared domain";
      }
    }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}
}  // namespace

int CheckSummary::exit_code(bool strict) const {
  if (input_errors > 0) return kExitInputError;
  if (refuted > 0 || errors > 0) return kExitRefuted;
  if (undecided > 0) return kExitUndecided;
  if (strict && errata > 0) return kExitRefuted;
  return kExitOk;
}

void CheckSummary::add(StepResult r) {
  const Step& s = *r.step;
  std::size_t own_errors = r.errors.size() - (r.erratum_reported ? 1 : 0);
  if (r.erratum_reported) ++errata;
  // a definition written as a chain (`T = E1 = E2`) also claims E1 = E2: not a premise
  // (a document step says itself whether the search took it as a given)
  if (!s.document_row) r.premise = s.rule.name == "given" || (s.rule.name == "definition" && s.claim.sides.size() <= 2);
  if (r.input_error) ++input_errors;
  if (own_errors > 0) ++errors;
  else if (r.premise && r.verdict.holds()) ++premises;
  else switch (r.verdict.kind) {
      case VerdictKind::Proved: ++proved; break;
      case VerdictKind::HoldsNumerically: ++holds_numerically; break;
      case VerdictKind::Refuted: ++refuted; break;
      case VerdictKind::Undecided: ++undecided; break;
    }
  results.push_back(std::move(r));
}

CheckSummary check_derivation(const Derivation& d, const ProveOptions& opt) {
  CheckSummary sum;
  for (const auto& s : d.steps) sum.add(check_step(d, s, opt));
  return sum;
}

}  // namespace dc
