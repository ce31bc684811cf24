// Claims as one-step derivations (internal/claim_steps.hpp): the steps a .dc author would write,
// built as the reader (derivations/reader/dc_steps.cpp) builds them.
#include "derivations/claims/internal/claim_steps.hpp"

#include <algorithm>
#include <utility>

namespace dc::claims {

namespace {

Node call_node(const std::string& name, std::vector<Node> args, const SourcePos& pos) {
  Node n;
  n.kind = NodeKind::Call;
  n.text = name;
  n.args = std::move(args);
  n.pos = pos;
  n.length = static_cast<int>(name.size());
  return n;
}

Node number_node(const std::string& text, const SourcePos& pos) {
  Node n;
  n.kind = NodeKind::Number;
  n.text = text;
  n.pos = pos;
  n.length = static_cast<int>(text.size());
  return n;
}

RuleArg symbol_arg(const Node& var) {
  RuleArg a;
  a.kind = RuleArg::Kind::Symbol;
  a.label = var.text;
  a.value = var;
  a.pos = var.pos;
  a.length = std::max(1, var.length);
  return a;
}

RuleArg value_arg(const Node& v) {
  RuleArg a;
  a.kind = RuleArg::Kind::Value;
  a.label = to_text(v);
  a.value = v;
  a.pos = v.pos;
  a.length = std::max(1, v.length);
  return a;
}

RuleSpec rule_named(const std::string& name, const std::string& args, const SourcePos& pos) {
  RuleSpec r;
  r.name = name;
  r.written_name = name;
  r.text = "by " + name + (args.empty() ? "" : " " + args);
  r.pos = pos;
  return r;
}

Step make_step(const std::string& label, std::vector<Node> sides, RuleSpec rule) {
  Step s;
  s.label = label;
  s.claim.sides = std::move(sides);
  s.claim_text = to_text(s.claim);
  s.pos = s.claim.sides[0].pos;
  s.claim_pos = s.claim.sides[0].pos;
  s.rule = std::move(rule);
  return s;
}

Derivation one_step(const std::string& file, const SymbolTable& table, std::vector<Step> steps) {
  Derivation d;
  d.source.name = file;
  d.symbols = table;
  d.steps = std::move(steps);
  d.index();
  return d;
}

// `x -> 0+`, `x -> oo`
std::string approach_text(const Approach& a) {
  return to_text(a.var) + " -> " + to_text(a.point) + (a.dir > 0 ? "+" : a.dir < 0 ? "-" : "");
}

void set_approach(RuleSpec& r, const Approach& a) {
  r.var = symbol_arg(a.var);
  r.point = value_arg(a.point);
  r.dir = a.dir;
}

}  // namespace

Node ode_form(const Node& n, const Node& var) {
  if (n.kind == NodeKind::Symbol) {
    const SourcePos& p = n.pos;
    Node y = call_node(kOdeNames[0], {var}, p);
    if (n.text == kOdeNames[0]) return y;
    if (n.text == kOdeNames[1]) return call_node("diff", {y, var}, p);
    if (n.text == kOdeNames[2]) return call_node("diff", {y, var, number_node("2", p)}, p);
    return n;
  }
  Node out = n;
  for (auto& a : out.args) a = ode_form(a, var);
  return out;
}

bool contains_integral(const Node& n) {
  if (n.kind == NodeKind::Call && n.text == "integral") return true;
  return std::any_of(n.args.begin(), n.args.end(), [](const Node& a) { return contains_integral(a); });
}

Derivation equal_derivation(const std::string& file, const SymbolTable& table, const Node& lhs, const Node& rhs) {
  // An equation with an integral is what `by integrate` checks (by every method of
  // integral_equal.hpp, also for an integral inside a larger expression); `by rewrite` would
  // only evaluate integrals inside expressions.
  const bool integral = contains_integral(lhs) || contains_integral(rhs);
  RuleSpec r = rule_named(integral ? "integrate" : "rewrite", "", lhs.pos);
  return one_step(file, table, {make_step("claim", {lhs, rhs}, std::move(r))});
}

Derivation limit_derivation(const std::string& file, const SymbolTable& table, const Node& lhs, const Node& rhs,
                            const Approach& a) {
  RuleSpec r = rule_named("limit", approach_text(a), lhs.pos);
  set_approach(r, a);
  return one_step(file, table, {make_step("claim", {lhs, rhs}, std::move(r))});
}

Derivation series_derivation(const std::string& file, const SymbolTable& table, const Node& lhs, const Node& rhs,
                             const Approach& a, std::optional<int> order, const std::optional<Node>& order_term) {
  RuleSpec r =
      rule_named("series", approach_text(a) + (order ? " to order " + std::to_string(*order) : ""), lhs.pos);
  set_approach(r, a);
  r.order = order;
  Step s = make_step("claim", {lhs, rhs}, std::move(r));
  s.order_term = order_term;
  return one_step(file, table, {std::move(s)});
}

Derivation antiderivative_derivation(const std::string& file, const SymbolTable& table, const Node& f, const Node& G,
                                     const Node& var) {
  Node integral = call_node("integral", {f, var}, f.pos);
  RuleSpec r = rule_named("integrate", "", f.pos);
  return one_step(file, table, {make_step("claim", {integral, G}, std::move(r))});
}

Derivation ode_derivation(const std::string& file, const SymbolTable& table, const Node& ode_lhs, const Node& ode_rhs,
                          const Node& var, const Node& solution, const std::vector<InitialValue>& initial) {
  Step ode = make_step("ode", {ode_form(ode_lhs, var), ode_form(ode_rhs, var)}, rule_named("given", "", ode_lhs.pos));
  // `with y(a) = v, y'(b) = w`
  std::vector<RuleArg> with;
  std::string with_text;
  for (const auto& iv : initial) {
    RuleArg w;
    w.kind = RuleArg::Kind::Equation;
    w.prime_order = iv.order;
    w.equation.sides = {call_node(kOdeNames[0], {iv.at}, iv.at.pos), iv.value};
    w.label = std::string(kOdeNames[0]) + std::string(static_cast<std::size_t>(iv.order), '\'') + "(" +
              to_text(iv.at) + ") = " + to_text(iv.value);
    w.pos = iv.at.pos;
    w.length = std::max(1, iv.at.length);
    with_text += (with_text.empty() ? " with " : ", ") + w.label;
    with.push_back(std::move(w));
  }
  RuleSpec r = rule_named("solves_ode", "ode wrt " + var.text + with_text, solution.pos);
  RuleArg ref;
  ref.kind = RuleArg::Kind::Label;
  ref.label = ode.label;
  ref.pos = ode_lhs.pos;
  ref.length = static_cast<int>(ode.label.size());
  r.refs.push_back(std::move(ref));
  r.var = symbol_arg(var);
  r.with = std::move(with);
  Step claim = make_step("claim", {call_node(kOdeNames[0], {var}, solution.pos), solution}, std::move(r));
  return one_step(file, table, {std::move(ode), std::move(claim)});
}

StepResult check_last_step(const Derivation& d, const ProveOptions& opt) {
  return check_step(d, d.steps.back(), opt);
}

}  // namespace dc::claims
