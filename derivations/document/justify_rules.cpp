// The rules other than rewrite that the justification search tries (search.hpp): the limit a
// row takes or the regime an approximate row holds in, solving for the subject of a row, and
// agreement to first order in the small quantities the text neglects.
#include <algorithm>
#include <functional>
#include <map>

#include "derivations/calculus/big_o.hpp"
#include "derivations/document/search.hpp"

namespace dc::document_detail {

// The rows a rule may start from: the nearest and the most relevant rows in force, each once.
std::vector<std::string> Search::source_rows() const {
  std::vector<std::string> out;
  auto add = [&](const std::string& l) {
    if (std::find(out.begin(), out.end(), l) == out.end() && usable_ref(l)) out.push_back(l);
  };
  for (const auto& l : row_.cited) add(l);
  for (std::size_t i = 0; i < 4 && i < row_.nearby.size(); ++i) add(row_.nearby[i]);
  for (const auto& l : most_relevant()) add(l);
  return out;
}

// The locals as `with x = value` substitutions: those whose first side is a name and that do
// not mention `skip` (a condition on the limit variable cannot hold along the limit).
std::vector<RuleArg> Search::local_substitutions(const std::vector<std::string>& labels, const std::string& skip) const {
  std::vector<RuleArg> out;
  for (const auto& label : labels) {
    const Step* st = d_.find(label);
    if (!st || st->claim.sides.size() < 2 || st->claim.sides.front().kind != NodeKind::Symbol) continue;
    std::set<std::string> names;
    for (const auto& side : st->claim.sides) names_of(side, names);
    if (!skip.empty() && names.count(skip)) continue;
    RuleArg a;
    a.kind = RuleArg::Kind::Equation;
    a.label = label;
    a.equation.sides = {st->claim.sides.front(), st->claim.sides.back()};
    a.pos = s_.claim_pos;
    out.push_back(std::move(a));
  }
  return out;
}

// `v'_1 = \lim_{m_2\to\infty} …` after `v'_1 = f(m_2)`: the limit of that row's expression,
// with the conditions in force (those on the limit variable dropped). An approximate row
// under a condition `x \approx 0` (or `= 0`): the limit x -> 0 of a row with the same subject.
std::optional<StepResult> Search::by_limit() {
  struct Regime { Node var, point; };
  std::vector<Regime> regimes;
  for (const auto& side : s_.claim.sides)
    walk_nodes(side, [&](const Node& n) {
      if (n.kind == NodeKind::Call && n.text == "limit" && n.args.size() == 3 && n.args[1].kind == NodeKind::Symbol)
        regimes.push_back({n.args[1], n.args[2]});
    });
  if (row_.relation == "approx")
    for (const auto& label : row_.locals) {
      const Step* st = d_.find(label);
      if (!st || st->claim.sides.size() < 2 || st->claim.sides.front().kind != NodeKind::Symbol) continue;
      const Node& last = st->claim.sides.back();
      if ((last.kind == NodeKind::Number && last.text == "0") || (last.kind == NodeKind::Symbol && last.text == "oo"))
        regimes.push_back({st->claim.sides.front(), last});
    }
  if (regimes.empty()) return std::nullopt;
  const std::string subject = set_name(s_);
  if (subject.empty()) return std::nullopt;
  for (const auto& g : regimes)
    for (const auto& label : source_rows()) {
      const Step* st = d_.find(label);
      if (!st || set_name(*st) != subject || st->claim.sides.size() != 2) continue;
      for (const auto* conds : {&row_.locals, &row_.fresh}) {
        RuleSpec rule;
        rule.name = rule.written_name = "limit";
        rule.var = node_arg(g.var, RuleArg::Kind::Symbol);
        rule.point = node_arg(g.point, RuleArg::Kind::Value);
        rule.into.push_back(label_arg(label));
        rule.with = local_substitutions(*conds, g.var.text);
        StepResult r = attempt_rule(rule);
        if (usable(r) && r.verdict.holds() && !rests_on_a_slip({label})) {
          std::vector<std::string> used{label};
          for (const auto& w : rule.with) used.push_back(w.label);
          return found(r, "limit " + to_text(g.var) + " -> " + to_text(g.point), used);
        }
      }
    }
  return std::nullopt;
}

// `theta = \arccos(…)` from rows that give cos(theta): solved for the subject, the names of
// the rows that the claim does not mention eliminated.
std::optional<StepResult> Search::by_solve(Refutations& refutations) {
  if (row_.relation != "=") return std::nullopt;
  const Node& subject = s_.claim.sides.front();
  if (subject.kind != NodeKind::Symbol) return std::nullopt;
  int tries = 0;
  bool refuted_once = false;
  for (const auto& refs : candidate_sets()) {
    std::vector<std::string> rows;
    std::set<std::string> theirs;
    for (const auto& label : refs) {
      const Step* st = d_.find(label);
      if (!st || !st->document_row || st->document_row->relation == "inline") continue;
      rows.push_back(label);
      for (const auto& side : st->claim.sides) names_of(side, theirs);
    }
    if (rows.empty() || !theirs.count(subject.text)) continue;
    if (++tries > 6) break;
    StepResult r = attempt_rule(solve_for_subject(refs));
    if (usable(r) && r.verdict.holds() && !rests_on_a_slip(refs)) {
      std::string what = "solve for " + subject.text;
      return found(r, what, refs);
    }
    // (`t_{1/2} = \tau/\ln 2` against `e^{-t_{1/2}/\tau} = 1/2`: no elimination undoes the
    // exponential, the claim substituted back does)
    if (usable(r) && substituted_back_refutes(r) && !refuted_once && rows_speak_of_claim(refs)) {
      refuted_once = true;
      // widened here by the rows that set its names, and solved again (the widening of the
      // refutations after the search eliminates, which does not undo the exponential either)
      std::vector<std::string> wider = refs;
      for (const auto& l : unset_setters(refs)) wider.push_back(l);
      if (wider.size() > refs.size() && wider.size() <= kMaxWidened && !late()) {
        StepResult w = attempt_rule(solve_for_subject(wider));
        if (usable(w) && substituted_back_refutes(w)) {
          refutations.push_back({w, wider, true});
          continue;
        }
      }
      refutations.push_back({r, refs, true});
    }
  }
  return std::nullopt;
}

// A refutation by `solve` that the rows themselves give: the claim substituted back fails
// them. (Not one from the sign of the root, `the claimed root must be positive like t`: that
// is the reading with every name positive speaking, t = (m_0 - m_r)/\mu at m_r > m_0.)
bool Search::substituted_back_refutes(const StepResult& r) {
  return r.verdict.kind == VerdictKind::Refuted && r.verdict.method.rfind("claim substituted back", 0) == 0;
}

RuleSpec Search::solve_for_subject(const std::vector<std::string>& refs) const {
  std::set<std::string> skip, names;
  for (const auto& side : s_.claim.sides) names_of(side, skip);
  for (const auto& label : row_.locals)
    if (const Step* st = d_.find(label)) skip.insert(set_name(*st));
  for (const auto& label : refs)
    if (const Step* st = d_.find(label); st && st->document_row && st->document_row->relation != "inline")
      for (const auto& side : st->claim.sides) names_of(side, names);
  return solve_spec(refs, s_.claim.sides.front(), names, skip);
}

// `by solve REFS for x, y…`: the subject, then each declared plain name of `names` not in `skip`
// (what the rows determine beside it).
RuleSpec Search::solve_spec(const std::vector<std::string>& refs, const Node& subject,
                            const std::set<std::string>& names, const std::set<std::string>& skip) const {
  RuleSpec rule;
  rule.name = rule.written_name = "solve";
  for (const auto& label : refs) rule.refs.push_back(label_arg(label));
  rule.unknowns.push_back(node_arg(subject, RuleArg::Kind::Symbol));
  for (const auto& n : names) {
    const SymbolInfo* info = d_.symbols.find(n);
    if (skip.count(n) || !info || info->is_function) continue;
    Node x;
    x.kind = NodeKind::Symbol;
    x.text = n;
    x.pos = s_.claim_pos;
    rule.unknowns.push_back(node_arg(x, RuleArg::Kind::Symbol));
  }
  return rule;
}

// `… = m_r\Delta v - u_e\Delta m` "where the higher-order term was neglected": the two sides
// differ by terms of second order in the small quantities (the names the text writes with
// \Delta or \delta), each scaled by one eps -> 0. Only when the text says so; never refutes.
std::optional<StepResult> Search::by_first_order() {
  static const char* const kWords[] = {"neglect", "higher-order", "higher order", "first order", "first-order",
                                       "second order", "second-order", "small"};
  bool said = false;
  for (const char* w : kWords) said = said || row_.hint.find(w) != std::string::npos;
  if (!said || s_.claim.sides.size() != 2) return std::nullopt;
  std::set<std::string> mine;
  for (const auto& side : s_.claim.sides) names_of(side, mine);
  std::vector<GiNaC::ex> smalls;
  std::vector<std::string> small_names;
  for (const auto& n : mine)
    if (n.rfind("Delta_", 0) == 0 || n.rfind("delta_", 0) == 0)
      if (const SymbolInfo* info = d_.symbols.find(n); info && !info->is_function) {
        smalls.push_back(info->sym);
        small_names.push_back(n);
      }
  if (smalls.empty()) return std::nullopt;
  try {
    const GiNaC::ex diff = to_ginac(s_.claim.sides[0], d_.symbols) - to_ginac(s_.claim.sides[1], d_.symbols);
    Verdict v = second_order_in_smalls(diff, smalls, d_.symbols);
    if (v.kind != VerdictKind::Proved) return std::nullopt;
    StepResult res;
    res.step = &s_;
    res.verdict = proved("first order (" + join(small_names) + " small, as the text says; each scaled by eps)",
                         "the sides differ by O(eps^2): " + v.method);
    return found(res, "first_order " + join(small_names), {});
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::optional<StepResult> Search::by_rates() {
  static const char* const kWords[] = {"derivative", "rate", "lim", "per unit time", "divid", "differentiat"};
  bool said = false;
  for (const char* w : kWords) said = said || row_.hint.find(w) != std::string::npos;
  if (!said) return std::nullopt;
  // the variable of the claim's derivatives (t in dv/dt), and its functions by base name
  std::string var;
  std::map<std::string, std::string> function_of;   // base name -> function id (v -> v__of_t)
  for (const auto& side : s_.claim.sides)
    walk_nodes(side, [&](const Node& n) {
      if (n.kind == NodeKind::Call && n.text == "diff" && n.args.size() == 2 && n.args[0].kind == NodeKind::Call &&
          n.args[0].args.size() == 1 && n.args[0].args[0].kind == NodeKind::Symbol && n.args[1].kind == NodeKind::Symbol) {
        const std::string& id = n.args[0].text;
        const std::size_t of = id.find("__of_");
        if (of == std::string::npos) return;
        var = n.args[1].text;
        function_of[id.substr(0, of)] = id;
      }
    });
  if (var.empty()) return std::nullopt;
  for (const auto& label : source_rows()) {
    if (late()) break;
    const Step* st = d_.find(label);
    if (!st || st->claim.sides.size() != 2) continue;
    // the increments of the row: each a Delta_ name whose quantity is a function of var here
    std::set<std::string> names;
    for (const auto& side : st->claim.sides) names_of(side, names);
    std::map<std::string, Node> rate;   // Delta_x -> dx/dt (Delta_t -> 1)
    bool ok = true;
    for (const auto& n : names) {
      if (n.rfind("Delta_", 0) != 0) continue;
      const std::string base = n.substr(6);
      Node r;
      if (base == var) {
        r.kind = NodeKind::Number;
        r.text = "1";
      } else if (auto f = function_of.find(base); f != function_of.end()) {
        Node t;
        t.kind = NodeKind::Symbol;
        t.text = var;
        Node fx;
        fx.kind = NodeKind::Call;
        fx.text = f->second;
        fx.args = {t};
        r.kind = NodeKind::Call;
        r.text = "diff";
        r.args = {fx, t};
      } else {
        ok = false;   // an increment of a quantity the claim does not differentiate
        break;
      }
      rate[n] = r;
    }
    if (!ok || rate.empty()) continue;
    // linear and homogeneous in the increments, each factor free of them
    try {
      const GiNaC::ex e = (to_ginac(st->claim.sides[0], d_.symbols) - to_ginac(st->claim.sides[1], d_.symbols)).expand();
      GiNaC::exmap zero;
      std::vector<GiNaC::ex> incs;
      for (const auto& [n, r] : rate) {
        const SymbolInfo* info = d_.symbols.find(n);
        if (!info) throw std::runtime_error("undeclared");
        zero[info->sym] = 0;
        incs.push_back(info->sym);
      }
      if (!e.subs(zero).expand().is_zero()) continue;
      bool linear = true;
      for (const auto& x : incs) {
        if (e.degree(x) != 1) linear = false;
        const GiNaC::ex c = e.coeff(x, 1);
        for (const auto& y : incs) linear = linear && !c.has(y);
      }
      if (!linear) continue;
    } catch (const std::exception&) {
      continue;
    }
    Relation rates;
    for (const auto& side : st->claim.sides) {
      Node copy = side;
      replace_names(copy, rate);
      rates.sides.push_back(std::move(copy));
    }
    RuleSpec rule;
    rule.name = rule.written_name = "rewrite";
    RuleArg a;
    a.kind = RuleArg::Kind::Equation;
    a.equation = rates;
    a.pos = s_.claim_pos;
    rule.refs.push_back(std::move(a));
    for (const auto& l : row_.locals) rule.refs.push_back(label_arg(l));
    for (const auto& l : row_.where) rule.refs.push_back(label_arg(l));
    StepResult r = attempt_rule(std::move(rule));
    if (!usable(r) || !r.verdict.holds()) continue;
    r.verdict.method = "rates of " + label + " (each increment over " + var + " divided by it, in the limit): " + r.verdict.method;
    r.found_line.clear();   // a .dc rule line does not state it
    return found(r, "rates", {label});
  }
  return std::nullopt;
}

// The rows an equation of a solution or a derivative may come from: the usual sources, and
// every row of the two displays before this one (the case of an equation may have ended in the
// words between, "which is integrated"; it is used with the conditions it was written under).
std::vector<std::string> Search::equation_rows() const {
  std::vector<std::string> out = source_rows();
  for (const auto& st : d_.steps) {
    if (&st == &s_) break;
    if (st.document_row && st.document_row->relation != "inline" && st.document_row->display < row_.display &&
        st.document_row->display + 2 >= row_.display && usable_ref(st.label) &&
        std::find(out.begin(), out.end(), st.label) == out.end())
      out.push_back(st.label);
  }
  return out;
}

std::optional<StepResult> Search::by_integration() {
  static const char* const kWords[] = {"integrat", "solution", "solving"};
  bool said = false;
  for (const char* w : kWords) said = said || row_.hint.find(w) != std::string::npos;
  if (!said || s_.claim.sides.size() != 2 || s_.claim.sides[0].kind != NodeKind::Symbol) return std::nullopt;
  const std::string subject = s_.claim.sides[0].text;
  // the constants of integration: names no earlier row mentions, none of them a function
  for (const auto& n : new_names_)
    if (const SymbolInfo* info = d_.symbols.find(n); !info || info->is_function) return std::nullopt;
  const std::vector<std::string> sources = equation_rows();
  std::optional<StepResult> refuted;
  std::vector<std::string> refuted_rows;
  std::string refuted_method;
  for (const auto& label : sources) {
    if (late()) break;
    const Step* st = d_.find(label);
    if (!st || st->claim.sides.size() != 2) continue;
    // the equation's variable and its functions, by base name; it must differentiate the subject
    std::string var;
    std::map<std::string, Node> fn;
    bool rate = false;
    for (const auto& side : st->claim.sides)
      walk_nodes(side, [&](const Node& n) {
        if (n.kind == NodeKind::Call && n.text == "diff" && !n.args.empty() && n.args[0].kind == NodeKind::Call &&
            n.args[0].text.rfind(subject + "__of_", 0) == 0)
          rate = true;
        if (n.kind != NodeKind::Call || n.args.size() != 1 || n.args[0].kind != NodeKind::Symbol) return;
        const std::size_t of = n.text.find("__of_");
        if (of == std::string::npos || n.text.substr(of + 5) != n.args[0].text) return;
        var = n.args[0].text;
        fn[n.text.substr(0, of)] = n;
      });
    if (!rate || var.empty() || !fn.count(subject)) continue;
    std::vector<std::string> constants;
    for (const auto& n : new_names_)
      if (!fn.count(n)) constants.push_back(n);
    if (constants.empty()) continue;   // nothing in the row for the starting value to fix
    // the row's value of the subject, its other names read as the equation reads them
    Node value = s_.claim.sides[1];
    replace_names(value, fn);
    // the equation with the subject's function replaced by that value: an identity when the
    // row solves it
    const std::string id = fn.at(subject).text;
    Relation solved = st->claim;
    for (auto& side : solved.sides) replace_calls(side, id, value);
    RuleSpec rule;
    rule.name = rule.written_name = "rewrite";
    std::vector<std::string> used{label};
    if (st->document_row)
      for (const auto& l : st->document_row->locals) used.push_back(l);   // the equation's own case
    for (const auto& l : row_.locals) used.push_back(l);
    for (const auto& l : row_.where) used.push_back(l);
    for (const auto& l : used)
      if (l != label) rule.refs.push_back(label_arg(l));
    StepResult r = attempt_rule(std::move(rule), &solved);
    const std::string what = "solving " + label + " (" + id + " replaced by the row's value)";
    if (usable(r) && r.verdict.holds()) {
      r.verdict.method = what + ": it holds, " + join(constants) +
                         (constants.size() == 1 ? " the constant" : " the constants") + " of integration: " +
                         r.verdict.method;
      r.found_line.clear();   // a .dc rule line does not state it
      return found(r, "integrate", used);
    }
    if (usable(r) && r.verdict.kind == VerdictKind::Refuted && !refuted) {
      // no value of the constants makes the row solve the equation. A refutation when every
      // other name of the row is one of the equation's (so what varies with the variable is
      // what the equation lets vary) and a counterexample holds with every quantity positive
      std::set<std::string> theirs, mine;
      for (const auto& side : st->claim.sides) names_of(side, theirs);
      for (const auto& side : s_.claim.sides) names_of(side, mine);
      bool alike = true;
      for (const auto& n : mine)
        alike = alike && (theirs.count(n) || fn.count(n) || n == var ||
                          std::find(constants.begin(), constants.end(), n) != constants.end());
      std::vector<std::string> others(used.begin() + 1, used.end());
      StepResult pos = attempt_positive(others, &solved);
      if (alike && usable(pos) && pos.verdict.kind == VerdictKind::Refuted) {
        refuted = pos;
        refuted_rows = used;
        refuted_method = what + ": it fails, whatever " + join(constants) + " is";
      }
    }
  }
  if (refuted) {
    refuted->verdict.method = refuted_method + ": " + refuted->verdict.method;
    refuted->found_line.clear();
    return found(*refuted, "integrate", refuted_rows);
  }
  return std::nullopt;
}

std::optional<StepResult> Search::by_differentiation() {
  static const char* const kWords[] = {"differentiat", "derivative"};
  bool said = false;
  for (const char* w : kWords) said = said || row_.hint.find(w) != std::string::npos;
  if (!said || s_.claim.sides.size() != 2) return std::nullopt;
  // the functions the row differentiates: base name -> its application (v_y -> v_y__of_t(t))
  std::map<std::string, Node> fn;
  std::string var;
  for (const auto& side : s_.claim.sides)
    walk_nodes(side, [&](const Node& n) {
      if (n.kind != NodeKind::Call || n.text != "diff" || n.args.size() < 2 || n.args[0].kind != NodeKind::Call ||
          n.args[0].args.size() != 1 || n.args[0].args[0].kind != NodeKind::Symbol)
        return;
      const std::string& id = n.args[0].text;
      const std::size_t of = id.find("__of_");
      if (of == std::string::npos || id.substr(of + 5) != n.args[0].args[0].text) return;
      var = n.args[0].args[0].text;
      fn[id.substr(0, of)] = n.args[0];
    });
  if (fn.empty()) return std::nullopt;
  const std::vector<std::string> sources = equation_rows();
  std::optional<StepResult> refuted;
  std::vector<std::string> refuted_rows;
  std::string refuted_method;
  for (const auto& label : sources) {
    if (late()) break;
    const Step* st = d_.find(label);
    if (!st || st->claim.sides.size() < 2 || st->claim.sides[0].kind != NodeKind::Symbol) continue;
    const auto f = fn.find(st->claim.sides[0].text);
    if (f == fn.end()) continue;
    // the row with the function replaced by that row's value (its other names as the row reads them)
    Node value = st->claim.sides.back();
    replace_names(value, fn);
    Relation claim = s_.claim;
    for (auto& side : claim.sides) replace_calls(side, f->second.text, value);
    RuleSpec rule;
    rule.name = rule.written_name = "rewrite";
    std::vector<std::string> used{label};
    for (const auto& l : row_.locals) used.push_back(l);
    for (const auto& l : row_.where) used.push_back(l);
    for (const auto& l : used)
      if (l != label) rule.refs.push_back(label_arg(l));
    StepResult r = attempt_rule(std::move(rule), &claim);
    const std::string what = "differentiating " + label + " (" + f->second.text + " replaced by its value there)";
    if (usable(r) && r.verdict.holds()) {
      r.verdict.method = what + ": " + r.verdict.method;
      r.found_line.clear();   // a .dc rule line does not state it
      return found(r, "differentiate", used);
    }
    if (usable(r) && r.verdict.kind == VerdictKind::Refuted && !refuted) {
      std::set<std::string> theirs, mine;
      for (const auto& side : st->claim.sides) names_of(side, theirs);
      for (const auto& side : s_.claim.sides) names_of(side, mine);
      bool alike = true;
      for (const auto& n : mine) {
        const std::size_t of = n.find("__of_");
        alike = alike && (theirs.count(n) || n == var || (of != std::string::npos && fn.count(n.substr(0, of))));
      }
      std::vector<std::string> others(used.begin() + 1, used.end());
      StepResult pos = alike ? attempt_positive(others, &claim) : StepResult{};
      if (alike && usable(pos) && pos.verdict.kind == VerdictKind::Refuted) {
        refuted = pos;
        refuted_rows = used;
        refuted_method = what + ": the sides differ";
      }
    }
  }
  if (refuted) {
    refuted->verdict.method = refuted_method + ": " + refuted->verdict.method;
    refuted->found_line.clear();
    return found(*refuted, "differentiate", refuted_rows);
  }
  return std::nullopt;
}

}  // namespace dc::document_detail
