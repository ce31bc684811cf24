// The .dc reader's steps (DcReader, internal/dc_reader.hpp; docs/format.md): a step's claim
// and attribute lines (by, note, erratum, stable, hide), a `by series` claim's order term, and
// the rule line `by NAME ...` with its arguments.
#include <algorithm>
#include <map>
#include <set>

#include "derivations/reader/internal/dc_reader.hpp"
#include "derivations/calculus/big_o.hpp"
#include "derivations/symbolic/vectors.hpp"

namespace dc::reader_detail {

// --- steps -------------------------------------------------------------------------------

void DcReader::step_statement(const Statement& st, const DcReader::Header& h) {
  // (the vector functions came later than the labels authors use: `norm:` stays a label)
  const bool vector_word = h.label == "dot" || h.label == "cross" || h.label == "norm" || h.label == "vec";
  if (contains(kRuleKeywords, h.label) || contains(kAttributeKeywords, h.label) ||
      (is_reserved_name(h.label) && !vector_word))
    fail(h.label_pos, "'" + h.label + "' is a reserved word and cannot be a step label",
         static_cast<int>(h.label.size()));
  if (auto it = defined_.find(h.label); it != defined_.end()) {
    const Step& prev = d_.steps[it->second];
    fail(h.label_pos, "duplicate label '" + h.label + "' (first defined at " + std::to_string(prev.pos.line) + ":" +
                          std::to_string(prev.pos.col) + ")",
         static_cast<int>(h.label.size()));
  }
  current_label_ = h.label;
  // Parts: the claim, then attribute lines (by/note/erratum/stable), each with continuations.
  struct Part { std::string kw; Span span; SourcePos kw_pos; };
  std::vector<Part> parts;
  parts.push_back({"", {}, h.label_pos});
  parts.back().span.append_line(file(), st.first_line, st.lines[0].second, h.claim_from);
  for (std::size_t i = 1; i < st.lines.size(); ++i) {
    const std::string& l = st.lines[i].second;
    std::size_t b = l.find_first_not_of(" \t");
    std::size_t we;
    std::string w = word_at(l, b, &we);
    if (contains(kAttributeKeywords, w) && (we >= l.size() || !is_ident_char(l[we]))) {
      Part part{w, {}, {file(), st.lines[i].first, static_cast<int>(b) + 1}};
      part.span.append_line(file(), st.lines[i].first, l, we);
      parts.push_back(std::move(part));
    } else {
      parts.back().span.append_line(file(), st.lines[i].first, l, 0);
    }
  }
  Step step;
  step.label = h.label;
  step.tag = h.tag;
  step.pos = h.label_pos;
  const Span& claim = parts[0].span;
  std::size_t cb = 0, ce = claim.text.size();
  trim_range(claim.text, cb, ce);
  if (cb >= ce) fail(claim.at(cb), "expected a claim after '" + h.label + ":' (an equation 'a = b' or an expression)");
  step.claim_pos = claim.at(cb);
  step.claim = relation(claim, cb, ce, "a claim");
  step.claim_text = normalise_ws(claim.text.substr(cb, ce - cb));
  bool have_rule = false;
  for (std::size_t i = 1; i < parts.size(); ++i) {
    const Part& part = parts[i];
    if (part.kw == "by") {
      if (have_rule) fail(part.kw_pos, "a step has exactly one 'by' line; found a second one", 2);
      step.rule = rule_line(part.span, part.kw_pos);
      have_rule = true;
    } else if (part.kw == "hide") {
      expect_end(part.span, 0);
      step.hidden = true;
    } else if (part.kw == "tex") {
      if (!step.tex.empty()) fail(part.kw_pos, "a step has at most one 'tex'", 3);
      std::size_t p = 0;
      step.tex_pos = part.kw_pos;
      step.tex = string_literal(part.span, p, "a quoted TeX name for the name this step introduces, e.g. tex \"\\omega_n\"");
      expect_end(part.span, p);
      if (step.tex.find_first_not_of(' ') == std::string::npos) fail(part.kw_pos, "empty 'tex': write the TeX name between the quotes", 3);
    } else if (part.kw == "note") {
      std::size_t p = 0;
      step.notes.push_back(string_literal(part.span, p, "a quoted note, e.g. note \"...\""));
      expect_end(part.span, p);
    } else if (part.kw == "erratum") {
      if (step.erratum) fail(part.kw_pos, "a step has at most one 'erratum'", 7);
      std::size_t p = 0;
      Erratum er;
      er.pos = part.kw_pos;
      er.why = string_literal(part.span, p, "a quoted reason, e.g. erratum \"v_e is never defined\" : corrected claim");
      skip_ws(part.span, p);
      if (p >= part.span.text.size() || part.span.text[p] != ':')
        fail(part.span.at(p), "expected ':' and the corrected claim after the erratum's reason");
      ++p;
      std::size_t e = part.span.text.size();
      trim_range(part.span.text, p, e);
      er.corrected = relation(part.span, p, e, "the corrected claim after ':'");
      er.corrected_text = normalise_ws(part.span.text.substr(p, e - p));
      step.erratum = std::move(er);
    } else {  // stable
      std::size_t p = 0;
      SourcePos lp = part.span.at([&] { std::size_t q = 0; skip_ws(part.span, q); return q; }());
      std::string label = identifier(part.span, p, "the label of the step this one is a stable form of");
      check_ref(label, lp);
      step.stable_of = label;
      step.stable_regime = string_literal(part.span, p, "a quoted regime, e.g. stable v_naive \"burn fraction < 1e-3\"");
      expect_end(part.span, p);
    }
  }
  if (!have_rule)
    fail(h.label_pos, "step '" + h.label + "' has no rule: expected an indented line 'by RULE ...' (rules: " +
                          join(kRuleNames, ", ") + ")",
         static_cast<int>(h.label.size()));

  if (step.rule.name == "series") order_term(step);
  // Symbols: a definition introduces its left-hand side; so does a named result whose name
  // was never declared (`W = integral(F, x, 0, L) = F0*L/2  by integrate`).
  const bool introduces = step.rule.name == "definition" ||
                          (names_operation_result(step) && step.claim.sides[0].kind == NodeKind::Symbol &&
                           !d_.symbols.find(step.claim.sides[0].text));
  if (!step.tex.empty() && !introduces)
    fail(step.tex_pos, "'tex' gives the TeX name of the name a step introduces; step '" + step.label +
                           "' introduces none (a definition or a named result does; a declared symbol takes its "
                           "'tex' on its 'symbol' line)", 3);
  if (introduces) introduce_definition(step);
  // Undefined symbols (and other conversion errors) in the claim; for an erratum step the
  // printed claim's error is kept for the report, the corrected claim must be valid.
  (void)vector_shape(step.erratum ? step.erratum->corrected : step.claim, d_.symbols);   // sides of one shape
  if (step.erratum) {
    for (const auto& side : step.erratum->corrected.sides) validate(side);
  } else {
    for (const auto& side : step.claim.sides)
      if (!limit_value_side(step, side, d_.symbols)) validate_side(side);
  }
  step.names_result = names_new_quantity(step);
  if (step.rule.name == "given") note_bound_names(step);
  step.first_side_fresh = !step.names_result && step.rule.name != "given" && step.rule.name != "definition" &&
                          step.claim.sides.size() >= 2 && !step.erratum &&
                          (step.claim.sides[0].kind == NodeKind::Symbol || step.claim.sides[0].kind == NodeKind::Call) &&
                          d_.symbols.find(step.claim.sides[0].text) && !used_names_.count(step.claim.sides[0].text);
  if (step.names_result) named_results_[step.claim.sides[0].text] = d_.steps.size();
  auto note_names = [&](const Relation& r) {
    for (const auto& side : r.sides) {
      std::vector<const Node*> ids;
      collect_identifiers(side, ids);
      for (const Node* id : ids) used_names_.insert(id->text);
    }
  };
  note_names(step.claim);
  if (step.erratum) note_names(step.erratum->corrected);
  for (const auto& w : step.rule.with) note_names(w.equation);
  defined_[step.label] = d_.steps.size();
  d_.steps.push_back(std::move(step));
}

// `by series x -> p [to order N]` with a claim whose last side ends in `+ O(gauge)`: the term
// gives the order (and must agree with `to order N` when both are written).
void DcReader::order_term(Step& step) {
  Node& last = step.claim.sides.back();
  Node rest, arg;
  if (step.claim.sides.size() < 2 || !split_order_term(last, rest, arg)) return;
  const RuleSpec& r = step.rule;
  if (!r.var || !r.point) return;   // the rule's own checks report the missing point
  validate(arg);
  const GiNaC::ex g = to_ginac(arg, d_.symbols);
  const GiNaC::ex x = to_ginac(r.var->value, d_.symbols);
  if (!GiNaC::is_a<GiNaC::symbol>(x)) return;
  const Node& pt = r.point->value;
  const bool oo = pt.kind == NodeKind::Symbol && pt.text == "oo";
  const bool minus_oo = pt.kind == NodeKind::Neg && pt.args[0].kind == NodeKind::Symbol && pt.args[0].text == "oo";
  const int inf = oo ? 1 : minus_oo ? -1 : 0;
  const GiNaC::ex p = inf ? GiNaC::ex(0) : to_ginac(pt, d_.symbols);
  std::string why;
  std::optional<int> n = order_of_term(g, GiNaC::ex_to<GiNaC::symbol>(x), p, inf, &why);
  if (!n) fail(arg.pos, why + ", got O(" + to_text(arg) + ")", arg.length);
  if (r.order && *r.order != *n)
    fail(arg.pos, "the claim ends in O(" + to_text(arg) + "), order " + std::to_string(*n) + ", but the rule says 'to order " +
                      std::to_string(*r.order) + "'",
         arg.length);
  step.rule.order = *n;
  step.order_term = arg;
  last = rest;
}

namespace {

// An operation whose result a step may name: an integral, a derivative, a limit, or a declared
// function evaluated (`x(T)`, the range as the position at the time of flight).
bool is_operation(const Node& n, const SymbolTable& symbols) {
  if (n.kind != NodeKind::Call) return false;
  if (n.text == "integral" || n.text == "diff" || n.text == "limit") return true;
  const SymbolInfo* f = is_builtin_function(n.text) ? nullptr : symbols.find(n.text);
  return f && f->is_function;
}

bool has_operation(const Node& n, const SymbolTable& symbols) {
  if (is_operation(n, symbols)) return true;
  for (const auto& a : n.args)
    if (has_operation(a, symbols)) return true;
  return false;
}

// One operation, scaled: OP, -OP, OP*c, c*OP, OP/c with c free of operations
// (`integral(x*lambda(x), x, 0, L)/M`). Not a sum: `I_G + m*d^2` is a result to derive.
bool scaled_operation(const Node& n, const SymbolTable& symbols) {
  if (is_operation(n, symbols)) return true;
  if (n.kind == NodeKind::Neg) return scaled_operation(n.args[0], symbols);
  if (n.kind == NodeKind::Mul)
    return (scaled_operation(n.args[0], symbols) && !has_operation(n.args[1], symbols)) ||
           (scaled_operation(n.args[1], symbols) && !has_operation(n.args[0], symbols));
  if (n.kind == NodeKind::Div) return scaled_operation(n.args[0], symbols) && !has_operation(n.args[1], symbols);
  return false;
}

}  // namespace

// The shape of a named result (Step::names_result): a chain `NAME = OP(...) = ...` of at least
// three sides whose first link is one operation, an integral, a derivative, a limit or a
// declared function's value, possibly scaled (`U = -integral(...)`, `R = x(T)`,
// `x_cm = integral(x*lambda(x), x, 0, L)/M`), under a rule other than given/definition. Only
// an operation's result can be named:
// `K = a*b + a*b = 2*a*b  by rewrite` is a claim about K like any other, so a wrong first link
// is refuted instead of silently defining K.
bool DcReader::names_operation_result(const Step& step) const {
  if (step.rule.name == "given" || step.rule.name == "definition" || step.erratum) return false;
  if (step.claim.sides.size() < 3) return false;
  const Node& n = step.claim.sides[0];
  if (n.kind != NodeKind::Symbol && n.kind != NodeKind::Call) return false;
  return scaled_operation(step.claim.sides[1], d_.symbols);
}

// A premise that mentions a name bound by an earlier named result speaks of that value: a
// general law written later with the same letters (`I_O = I_G + m*d^2` after the rod's
// `I_G = integral(...) = m*L^2/12`) silently becomes a statement about the rod. Say so at the
// name, once per name and step (a note: the premise may mean exactly that).
void DcReader::note_bound_names(Step& step) const {
  std::set<std::string> seen;
  for (const auto& side : step.claim.sides) {
    std::vector<const Node*> ids;
    collect_identifiers(side, ids);
    for (const Node* id : ids) {
      auto it = named_results_.find(id->text);
      if (it == named_results_.end() || !seen.insert(id->text).second) continue;
      const Step& by = d_.steps[it->second];
      step.diagnostics.push_back(InputError::note(
          id->pos,
          "'" + id->text + "' here is the value that step '" + by.label + "' (line " + std::to_string(by.pos.line) +
              ") named, " + to_text(by.claim.sides[1]) + "; this premise is a statement about that value (use another " +
              "name for another quantity)",
          id->length, d_.source.line(id->pos.line)));
    }
  }
}

// See Step::names_result.
bool DcReader::names_new_quantity(const Step& step) const {
  if (!names_operation_result(step)) return false;
  const Node& n = step.claim.sides[0];
  if (used_names_.count(n.text)) return false;
  const SymbolInfo* info = d_.symbols.find(n.text);
  if (!info) return false;
  // A quantity named in an assumption cannot be named (`assume W < E` would say nothing of
  // the value). A declared domain can: the step then also claims that the value lies in it
  // (check.cpp), so `symbol W : positive` and `W = -1 = -1` stay refuted.
  for (const auto& c : d_.symbols.constraints())
    if (c.lhs.has(info->sym) || c.rhs.has(info->sym)) return false;
  if (n.kind == NodeKind::Symbol) return !info->is_function;
  if (!info->domain.unrestricted()) return false;
  if (n.kind != NodeKind::Call || !info->is_function || n.args.size() != info->params.size()) return false;
  for (std::size_t i = 0; i < n.args.size(); ++i)
    if (n.args[i].kind != NodeKind::Symbol || n.args[i].text != info->params[i]) return false;
  return true;
}

// integral(...) cannot be converted to GiNaC; validate its parts instead.
void DcReader::validate_side(const Node& n) {
  if (n.kind == NodeKind::Call && n.text == "integral") {
    for (std::size_t i = 0; i < n.args.size(); ++i) {
      // a limit of integration may be oo or -oo
      const Node& a = n.args[i];
      const Node& v = a.kind == NodeKind::Neg ? a.args[0] : a;
      if (i >= 2 && v.kind == NodeKind::Symbol && v.text == "oo") continue;
      validate_side(a);
    }
    return;
  }
  if (contains_integral(n)) {
    for (const auto& a : n.args) validate_side(a);
    return;
  }
  validate(n);
}

bool DcReader::contains_integral(const Node& n) {
  if (n.kind == NodeKind::Call && n.text == "integral") return true;
  for (const auto& a : n.args)
    if (contains_integral(a)) return true;
  return false;
}

std::string DcReader::normalise_ws(const std::string& t) {
  std::string out;
  bool space = false;
  for (char c : t) {
    if (is_space(c) || c == '\n') { space = true; continue; }
    if (space && !out.empty()) out += ' ';
    space = false;
    out += c;
  }
  return out;
}

// --- the rule line -----------------------------------------------------------------------

void DcReader::check_ref(const std::string& label, const SourcePos& p) {
  if (defined_.count(label)) return;
  if (label == current_label_)
    fail(p, "step '" + label + "' refers to itself; a step may only use earlier steps",
         static_cast<int>(label.size()));
  auto it = all_labels_.find(label);
  if (it != all_labels_.end())
    fail(p, "step '" + label + "' is defined later (at " + std::to_string(it->second.line) + ":" +
                std::to_string(it->second.col) + "); a step may only use earlier steps",
         static_cast<int>(label.size()));
  std::vector<std::string> earlier;
  for (const auto& st : d_.steps) earlier.push_back(st.label);
  fail(p, "unknown label '" + label + "'" + did_you_mean(label, earlier) + "; expected the label of an earlier step",
       static_cast<int>(label.size()));
}

RuleSpec DcReader::rule_of(const Derivation& d, std::size_t index, const std::string& text, const SourcePos& pos) {
  DcReader r(d.source);
  r.d_.symbols = d.symbols;
  for (std::size_t i = 0; i < index && i < d.steps.size(); ++i) {
    r.defined_[d.steps[i].label] = r.d_.steps.size();
    r.d_.steps.push_back(d.steps[i]);
  }
  for (const auto& st : d.steps) r.all_labels_.emplace(st.label, st.pos);
  if (index < d.steps.size()) r.current_label_ = d.steps[index].label;
  Span s;
  s.text = text;
  for (std::size_t i = 0; i < text.size(); ++i) s.pos.push_back(SourcePos{pos.file, pos.line, pos.col + static_cast<int>(i)});
  s.end = SourcePos{pos.file, pos.line, pos.col + static_cast<int>(text.size())};
  return r.rule_line(s, pos);
}

RuleSpec DcReader::rule_line(const Span& s, const SourcePos& by_pos) {
  RuleSpec spec;
  spec.pos = by_pos;
  std::size_t p = 0;
  skip_ws(s, p);
  SourcePos name_pos = s.at(p);
  std::string all_rules = join(kRuleNames, ", ") + " (aliases of rewrite: " + join(kRewriteAliases, ", ") + ")";
  if (p >= s.text.size() || !is_ident_start(s.text[p]))
    fail(name_pos, "expected a rule name after 'by'; known rules: " + all_rules);
  std::string name = identifier(s, p, "a rule name");
  spec.written_name = name;
  rule_name_ = name;
  if (contains(kRuleNames, name)) spec.name = name;
  else if (contains(kRewriteAliases, name)) spec.name = "rewrite";
  else {
    std::vector<std::string> names = kRuleNames;
    names.insert(names.end(), kRewriteAliases.begin(), kRewriteAliases.end());
    fail(name_pos, "unknown rule '" + name + "'" + did_you_mean(name, names) + "; known rules: " + all_rules,
         static_cast<int>(name.size()));
  }
  {
    std::size_t b = 0, e = s.text.size();
    trim_range(s.text, b, e);
    spec.text = "by " + normalise_ws(s.text.substr(b, e - b));
  }
  // Split the arguments at top-level keywords and '->'.
  struct Group { std::string kw; SourcePos kw_pos; std::size_t b, e; };
  std::vector<Group> groups{{"", name_pos, p, s.text.size()}};
  int depth = 0;
  for (std::size_t i = p; i < s.text.size(); ++i) {
    char c = s.text[i];
    if (c == '(' || c == '[') { ++depth; continue; }
    if (c == ')' || c == ']') { --depth; continue; }
    if (depth != 0) continue;
    if (c == '-' && i + 1 < s.text.size() && s.text[i + 1] == '>') {
      groups.back().e = i;
      groups.push_back({"->", s.at(i), i + 2, s.text.size()});
      ++i;
      continue;
    }
    if (is_ident_start(c) && (i == 0 || !is_ident_char(s.text[i - 1]))) {
      std::size_t we;
      std::string w = word_at(s.text, i, &we);
      // `to order N` belongs to `by series` only (elsewhere `to` may be a symbol's name).
      if (contains(kRuleKeywords, w) || (w == "to" && spec.name == "series")) {
        groups.back().e = i;
        groups.push_back({w, s.at(i), we, s.text.size()});
      }
      i = we - 1;
    }
  }
  std::set<std::string> seen;
  for (const auto& g : groups) {
    if (!g.kw.empty() && !seen.insert(g.kw).second)
      fail(g.kw_pos, "'" + g.kw + "' appears twice in the rule line", static_cast<int>(g.kw.size()));
  }
  // Which keywords each rule takes.
  const std::string& r = spec.name;
  std::vector<std::string> allowed;
  if (r == "rewrite") allowed = {"with"};
  else if (r == "substitute") allowed = {"into", "with"};
  else if (r == "solve" || r == "coefficients") allowed = {"for"};
  else if (r == "limit") allowed = {"->", "of", "with"};
  else if (r == "series") allowed = {"->", "of", "with", "to"};
  else if (r == "first_order") allowed = {"of"};
  else if (r == "differentiate") allowed = {"wrt"};
  else if (r == "integrate") allowed = {"wrt", "from", "with"};
  else if (r == "solves_ode") allowed = {"wrt", "with"};
  else if (r == "stationary" || r == "maximum" || r == "minimum") allowed = {"of", "wrt"};
  else if (r == "instance") allowed = {"of", "with"};
  for (const auto& g : groups)
    if (!g.kw.empty() && !contains(allowed, g.kw))
      fail(g.kw_pos, "unexpected '" + g.kw + "' in 'by " + name + "'" + usage(r), static_cast<int>(g.kw.size()));
  auto group = [&](const std::string& kw) -> const Group* {
    for (const auto& g : groups)
      if (g.kw == kw) return &g;
    return nullptr;
  };
  auto require = [&](const std::string& kw) -> const Group& {
    const Group* g = group(kw);
    if (!g) fail(s.end, "expected '" + kw + "' in 'by " + name + "'" + usage(r));
    return *g;
  };
  const Group& pre = groups[0];
  auto pre_items = items(s, pre);
  if (r == "given" || r == "definition") {
    if (!pre_items.empty())
      fail(s.at(pre_items[0].first), "'by " + name + "' takes no arguments" + usage(r));
  } else if (r == "rewrite") {
    for (auto& it : pre_items) spec.refs.push_back(ref_or_equation(s, it.first, it.second));
  } else if (r == "substitute") {
    if (pre_items.empty()) fail(s.at(nonspace(s, pre.b)), "expected the substitutions (labels or 'x = value')" + usage(r));
    for (auto& it : pre_items) spec.refs.push_back(ref_or_equation(s, it.first, it.second));
    spec.into = labels(s, require("into"), "the label of the step to substitute into", 1);
  } else if (r == "solve" || r == "coefficients") {
    if (pre_items.empty())
      fail(s.at(nonspace(s, pre.b)),
           std::string(r == "solve" ? "expected the labels of the equations to solve" : "expected the label of the identity") +
               usage(r));
    for (auto& it : pre_items) spec.refs.push_back(label_arg(s, it.first, it.second));
    const Group& g = require("for");
    for (auto& it : items(s, g)) {
      RuleArg u = symbol_or_value(s, it.first, it.second);
      const SymbolInfo* v = u.kind == RuleArg::Kind::Symbol ? d_.symbols.find(u.label) : nullptr;
      if (!v || !v->vector_dim || v->is_function) {
        spec.unknowns.push_back(std::move(u));
        continue;
      }
      for (const auto& component : v->components) {   // a vector unknown: its components
        RuleArg cu = u;
        cu.label = component;
        cu.value = parse_expression(component, u.pos);
        spec.unknowns.push_back(std::move(cu));
      }
    }
    if (spec.unknowns.empty())
      fail(s.at(nonspace(s, g.b)),
           std::string(r == "solve" ? "expected the unknowns after 'for'" : "expected the variables after 'for'") + usage(r));
  } else if (r == "limit" || r == "series") {
    if (pre_items.size() != 1) fail(s.at(nonspace(s, pre.b)), "expected one variable before '->'" + usage(r));
    spec.var = symbol_arg(s, pre_items[0].first, pre_items[0].second);
    const Group& g = require("->");
    auto pit = items(s, g);
    if (pit.size() != 1) fail(s.at(nonspace(s, g.b)), "expected one point after '->' (a value, oo or -oo)" + usage(r));
    // A one-sided approach: `-> 0+` (from above), `-> a-` (from below).
    std::size_t pe = pit[0].second;
    if (pe > pit[0].first + 1 && (s.text[pe - 1] == '+' || s.text[pe - 1] == '-')) {
      spec.dir = s.text[pe - 1] == '+' ? 1 : -1;
      --pe;
      std::size_t pb = pit[0].first;
      trim_range(s.text, pb, pe);
    }
    spec.point = value_arg(s, pit[0].first, pe);
    if (spec.dir != 0 && (spec.point->value.kind == NodeKind::Symbol || spec.point->value.kind == NodeKind::Neg)) {
      const Node& v = spec.point->value.kind == NodeKind::Neg ? spec.point->value.args[0] : spec.point->value;
      if (v.kind == NodeKind::Symbol && v.text == "oo")
        fail(s.at(pe), "a direction ('+' or '-') goes with a finite point; 'oo' and '-oo' are approached from one side already",
             1);
    }
    // `to order N` (series): the claim holds up to O((x - p)^N).
    if (const Group* to = group("to")) {
      std::size_t b = to->b, e = to->e;
      trim_range(s.text, b, e);
      std::size_t we = b;
      std::string w = b < e && is_ident_start(s.text[b]) ? word_at(s.text, b, &we) : std::string();
      if (w != "order") fail(s.at(b), "expected 'order N' after 'to' (the claim holds up to O((x - point)^N))" + usage(r));
      std::size_t nb = we, ne = e;
      trim_range(s.text, nb, ne);
      std::string num = s.text.substr(nb, ne - nb);
      bool neg = !num.empty() && num[0] == '-';
      std::string digits = neg ? num.substr(1) : num;
      if (digits.empty() || digits.size() > 4 || digits.find_first_not_of("0123456789") != std::string::npos)
        fail(s.at(nb), "expected an integer order between -1000 and 1000 after 'to order'" + usage(r),
             std::max(1, static_cast<int>(ne - nb)));
      int n = std::stoi(digits) * (neg ? -1 : 1);
      if (n < -1000 || n > 1000)
        fail(s.at(nb), "expected an integer order between -1000 and 1000 after 'to order'" + usage(r),
             static_cast<int>(ne - nb));
      spec.order = n;
    }
    // `of A`: the expression of step A (its last side); without it, the claim's own first side.
    if (group("of")) spec.into = labels(s, *group("of"), "the label of the step to take the " + r + " of", 1);
  } else if (r == "first_order") {
    if (pre_items.empty()) fail(s.at(nonspace(s, pre.b)), "expected the small quantities" + usage(r));
    // a small quantity is a symbol or a declared function (theta, or theta(t) as written):
    // a small function is small with all its derivatives
    for (auto& it : pre_items) {
      const RuleArg a = spanned(s, it.first, it.second);
      const SymbolInfo* info = d_.symbols.find(a.label);
      if (plain_identifier(s, it.first, it.second) && info && info->is_function) {
        RuleArg f = a;
        f.kind = RuleArg::Kind::Symbol;
        // the name as written, for printers (the rule finds its applications itself)
        f.value.kind = NodeKind::Symbol;
        f.value.text = a.label;
        f.value.pos = a.pos;
        f.value.length = a.length;
        spec.smalls.push_back(f);
      } else if (plain_identifier(s, it.first, it.second)) {
        spec.smalls.push_back(symbol_arg(s, it.first, it.second));
      } else {
        spec.smalls.push_back(value_arg(s, it.first, it.second));
      }
    }
    spec.into = labels(s, require("of"), "the label of the step to expand", 1);
  } else if (r == "stationary" || r == "maximum" || r == "minimum") {
    // `of A` (a step: its last side) or `of EXPR`; `wrt x` may be left out when the claim is `x = p`
    if (!pre_items.empty()) fail(s.at(pre_items[0].first), "expected 'of' before the quantity" + usage(r));
    const Group& g = require("of");
    auto oit = items(s, g);
    if (oit.size() != 1) fail(s.at(nonspace(s, g.b)), "expected one step label or expression after 'of'" + usage(r));
    if (plain_identifier(s, oit[0].first, oit[0].second) &&
        defined_.count(s.text.substr(oit[0].first, oit[0].second - oit[0].first)))
      spec.into.push_back(label_arg(s, oit[0].first, oit[0].second));
    else
      spec.into.push_back(value_arg(s, oit[0].first, oit[0].second));
    if (const Group* w = group("wrt")) {
      auto wit = items(s, *w);
      if (wit.size() != 1) fail(s.at(nonspace(s, w->b)), "expected one variable after 'wrt'" + usage(r));
      spec.var = symbol_arg(s, wit[0].first, wit[0].second);
    }
  } else if (r == "instance") {
    // `by instance of LAW [with x = value, ...]` (or `by instance LAW ...`)
    const Group* g = group("of");
    if (g && !pre_items.empty()) fail(s.at(pre_items[0].first), "expected only 'of LAW'" + usage(r));
    if (g) spec.into = labels(s, *g, "the label of the law", 1);
    else if (pre_items.size() == 1) spec.into.push_back(label_arg(s, pre_items[0].first, pre_items[0].second));
    else fail(s.at(nonspace(s, pre.b)), "expected the label of the law after 'of'" + usage(r));
  } else if (r == "differentiate" || r == "integrate" || r == "solves_ode") {
    // differentiate and integrate may work on the claim's own diff(...) / integral(...)
    if (pre_items.empty() && r == "solves_ode")
      fail(s.at(nonspace(s, pre.b)), "expected the label of the equation" + usage(r));
    for (auto& it : pre_items) spec.refs.push_back(label_arg(s, it.first, it.second));
    // without a cited equation, differentiate and integrate read the variable from the claim's
    // own diff(f, x) / integral(f, x, a, b), so 'wrt' may be left out; so does integrating a
    // differential equation from its start, `by integrate A with v = v0, x = x0`
    const Group* g = group("wrt");
    const bool differential_form = r == "integrate" && group("with") && !group("from");
    if (!g && ((pre_items.empty() && r != "solves_ode") || differential_form)) {
    } else {
      if (!g) g = &require("wrt");
      auto wit = items(s, *g);
      if (wit.size() != 1) fail(s.at(nonspace(s, g->b)), "expected one variable after 'wrt'" + usage(r));
      spec.var = symbol_arg(s, wit[0].first, wit[0].second);
    }
    if (r == "integrate") {
      // `from T0` is needed by the ODE form only (an integral(f, x, a, b) claim has its limits).
      if (const Group* f = group("from")) {
        auto fit = items(s, *f);
        if (fit.size() != 1) fail(s.at(nonspace(s, f->b)), "expected one lower limit after 'from'" + usage(r));
        spec.point = value_arg(s, fit[0].first, fit[0].second);
      }
    }
  }
  if (const Group* g = group("with")) {
    auto wit = items(s, *g);
    if (wit.empty()) fail(s.at(nonspace(s, g->b)), "expected 'x = value' after 'with'");
    for (auto& it : wit) {
      RuleArg a = ref_or_equation(s, it.first, it.second);
      if (a.kind != RuleArg::Kind::Equation)
        fail(a.pos, "expected 'x = value' after 'with', found '" + a.label + "'", a.length);
      spec.with.push_back(std::move(a));
    }
  }
  return spec;
}

std::string DcReader::usage(const std::string& r) {
  if (r == "given" || r == "definition") return "";
  static const std::map<std::string, std::string> u = {
      {"rewrite", "by rewrite [A, B, ...] [with x = value, ...]"},
      {"substitute", "by substitute S1, S2, ... into C"},
      {"solve", "by solve A, B, ... for x, y, ..."},
      {"limit", "by limit x -> POINT[+|-] [of A] [with y = value, ...]"},
      {"series", "by series x -> POINT[+|-] [to order N] [of A]"},
      {"first_order", "by first_order d1, d2 of A"},
      {"differentiate", "by differentiate [A, ...] wrt t"},
      {"integrate", "by integrate A wrt t from T0 [with y(T0) = value, ...]' or 'by integrate [A, ...] wrt x' for a claim "
                    "'integral(f, x, a, b) = G' or 'by integrate A with x = x0, t = t0, ...' for a differential equation A"},
      {"solves_ode", "by solves_ode A wrt t [with y(T0) = value, ...]"},
      {"stationary", "by stationary of A wrt x' (A a step or an expression) with the claim 'x = point"},
      {"maximum", "by maximum of A wrt x' (A a step or an expression) with the claim 'x = point"},
      {"minimum", "by minimum of A wrt x' (A a step or an expression) with the claim 'x = point"},
      {"instance", "by instance of LAW [with x = value, ...]"},
      {"coefficients", "by coefficients A [, B, ...] for x, t, ...' (A holds for every x, t, ...)"}};
  auto it = u.find(r);
  return it == u.end() ? "" : "; usage: '" + it->second + "'";
}

// Top-level comma-separated items of a group: (begin, end) offsets, trimmed.
std::vector<std::pair<std::size_t, std::size_t>> DcReader::items(const Span& s, const auto& g) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  int depth = 0;
  std::size_t from = g.b;
  auto push = [&](std::size_t b, std::size_t e) {
    trim_range(s.text, b, e);
    if (b < e) out.push_back({b, e});
    else if (!out.empty() || e < g.e) fail(s.at(b), "expected an argument between the commas");
  };
  for (std::size_t i = g.b; i < g.e; ++i) {
    char c = s.text[i];
    if (c == '(' || c == '[') ++depth;   // (a vector literal [a, b, c] is one argument)
    else if (c == ')' || c == ']') --depth;
    else if (c == ',' && depth == 0) {
      push(from, i);
      from = i + 1;
    }
  }
  std::size_t b = from, e = g.e;
  trim_range(s.text, b, e);
  if (b < e) out.push_back({b, e});
  else if (!out.empty()) fail(s.at(b), "expected an argument after ','");
  return out;
}

bool DcReader::plain_identifier(const Span& s, std::size_t b, std::size_t e) const {
  if (b >= e || !is_ident_start(s.text[b])) return false;
  for (std::size_t i = b; i < e; ++i)
    if (!is_ident_char(s.text[i])) return false;
  return true;
}

// An argument over s.text[b, e): its position, length and text.
RuleArg DcReader::spanned(const Span& s, std::size_t b, std::size_t e) {
  RuleArg a;
  a.pos = s.at(b);
  a.length = static_cast<int>(e - b);
  a.label = s.text.substr(b, e - b);
  return a;
}

RuleArg DcReader::label_arg(const Span& s, std::size_t b, std::size_t e) {
  RuleArg a = spanned(s, b, e);
  if (!plain_identifier(s, b, e)) fail(a.pos, "expected a step label, found '" + a.label + "'", a.length);
  a.kind = RuleArg::Kind::Label;
  check_ref(a.label, a.pos);
  return a;
}

std::vector<RuleArg> DcReader::labels(const Span& s, const auto& g, const std::string& what, std::size_t count) {
  auto it = items(s, g);
  if (it.size() != count) fail(s.at(nonspace(s, g.b)), "expected " + what + " after '" + g.kw + "'");
  std::vector<RuleArg> out;
  for (auto& i : it) out.push_back(label_arg(s, i.first, i.second));
  return out;
}

RuleArg DcReader::ref_or_equation(const Span& s, std::size_t b, std::size_t e) {
  if (plain_identifier(s, b, e)) return label_arg(s, b, e);
  RuleArg a = spanned(s, b, e);
  // `y'(T0) = v0`, `y''(T0) = a0`: an initial value of a derivative. The primes are read
  // here and blanked (`y (T0)` is the same call), so positions stay exact.
  std::size_t q = b;
  while (q < e && is_ident_char(s.text[q])) ++q;
  std::size_t primes = q;
  while (primes < e && s.text[primes] == '\'') ++primes;
  if (q > b && is_ident_start(s.text[b]) && primes > q) {
    std::size_t after = primes;
    while (after < e && is_space(s.text[after])) ++after;
    if (after >= e || s.text[after] != '(')
      fail(s.at(primes), "expected '(' after the primes: a derivative's initial value is written y'(T0) = value");
    if (rule_name_ != "solves_ode")
      fail(a.pos, "an initial value of a derivative (y'(T0) = value) belongs to 'by solves_ode A wrt t with ...'",
           a.length);
    Span blanked = s;
    for (std::size_t i = q; i < primes; ++i) blanked.text[i] = ' ';
    a.prime_order = static_cast<int>(primes - q);
    Relation rel = relation(blanked, b, e, "an initial value y'(T0) = value");
    if (rel.sides.size() != 2)
      fail(a.pos, "expected an initial value 'y'(T0) = value', found '" + a.label + "'", a.length);
    for (const auto& side : rel.sides) validate(side);
    a.kind = RuleArg::Kind::Equation;
    a.equation = std::move(rel);
    return a;
  }
  Relation rel = relation(s, b, e, "a label or 'x = value'");
  if (rel.sides.size() != 2)
    fail(a.pos, "expected a label or an equation 'x = value', found '" + a.label + "'", a.length);
  (void)vector_shape(rel, d_.symbols);
  for (const auto& side : rel.sides) validate(side);
  a.kind = RuleArg::Kind::Equation;
  a.equation = std::move(rel);
  return a;
}

RuleArg DcReader::symbol_arg(const Span& s, std::size_t b, std::size_t e) {
  RuleArg a = spanned(s, b, e);
  if (!plain_identifier(s, b, e)) fail(a.pos, "expected a symbol name, found '" + a.label + "'", a.length);
  const SymbolInfo* info = d_.symbols.find(a.label);
  if (!info || info->is_function)
  {
    std::vector<std::string> names;
    for (const auto& sym : d_.symbols.all())
      if (!sym.is_function && !sym.is_differential) names.push_back(sym.name);
    fail(a.pos, "undefined symbol '" + a.label + "'" + did_you_mean(a.label, names) + ": declare it with 'symbol " +
                    a.label + " ...'",
         a.length);
  }
  a.kind = RuleArg::Kind::Symbol;
  a.value = parse_expression(a.label, a.pos);
  return a;
}

RuleArg DcReader::value_arg(const Span& s, std::size_t b, std::size_t e) {
  RuleArg a = spanned(s, b, e);
  a.kind = RuleArg::Kind::Value;
  a.value = expression(s, b, e, "a value");
  bool infinite = (a.value.kind == NodeKind::Symbol && a.value.text == "oo") ||
                  (a.value.kind == NodeKind::Neg && a.value.args[0].kind == NodeKind::Symbol &&
                   a.value.args[0].text == "oo");
  if (!infinite) validate(a.value);
  return a;
}

RuleArg DcReader::symbol_or_value(const Span& s, std::size_t b, std::size_t e) {
  if (plain_identifier(s, b, e)) return symbol_arg(s, b, e);
  RuleArg a = value_arg(s, b, e);
  return a;
}

}  // namespace dc::reader_detail
