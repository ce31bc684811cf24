// The .dc reader's declarations (DcReader, internal/dc_reader.hpp; docs/format.md): the
// `symbol` / `function` and `assume` statements, and the names that steps introduce (`by
// definition`), with the check that definitions form no cycle.
#include <functional>
#include <map>
#include <set>

#include "derivations/reader/internal/dc_reader.hpp"
#include "derivations/decide/satisfiable.hpp"
#include "derivations/syntax/units.hpp"

namespace dc::reader_detail {

// --- symbol / function -------------------------------------------------------------------

// The parameters of a declared function, after its '(' up to and past the ')'.
std::vector<std::string> DcReader::parameters(const Span& s, std::size_t& p, const std::string& owner) {
  std::vector<std::string> params;
  for (;;) {
    skip_ws(s, p);
    SourcePos ap = s.at(p);
    std::string a = identifier(s, p, "an argument name (a declared symbol)");
    const SymbolInfo* info = d_.symbols.find(a);
    if (!info || info->is_function || info->vector_dim)
      fail(ap, "the argument '" + a + "' of '" + owner + "' must be a declared symbol (declare it first with 'symbol " + a +
                   " : real [s]')",
           static_cast<int>(a.size()));
    params.push_back(a);
    skip_ws(s, p);
    if (p < s.text.size() && s.text[p] == ',') { ++p; continue; }
    if (p < s.text.size() && s.text[p] == ')') { ++p; break; }
    fail(s.at(p), "expected ',' or ')' in the argument list of '" + owner + "'");
  }
  return params;
}

void DcReader::symbol_statement(const Span& s, bool is_function) {
  std::size_t p = 0;
  struct NameAt { std::string name; SourcePos pos; };
  std::vector<NameAt> names;
  std::vector<std::string> params;
  const char* kind = is_function ? "function" : "symbol";
  if (is_function) {
    skip_ws(s, p);
    SourcePos np = s.at(p);
    names.push_back({identifier(s, p, "a function name, e.g. 'function v(t) : real [m/s]'"), np});
    skip_ws(s, p);
    if (p >= s.text.size() || s.text[p] != '(')
      fail(s.at(p), "expected '(' and the argument of function '" + names[0].name + "', e.g. 'function v(t)'");
    ++p;
    params = parameters(s, p, names[0].name);
  } else {
    for (;;) {
      skip_ws(s, p);
      SourcePos np = s.at(p);
      names.push_back({identifier(s, p, "a symbol name, e.g. 'symbol m1, m2 : positive [kg]'"), np});
      skip_ws(s, p);
      if (p < s.text.size() && s.text[p] == ',') { ++p; continue; }
      break;
    }
  }
  for (const auto& n : names) {
    if (n.name == "deg")
      fail(n.pos, std::string("'deg' is predefined as pi/180 (degrees: 30*deg, or 30°) and cannot be declared as a ") + kind +
                      "; choose another name", 3);
    if (is_reserved_name(n.name) || contains(kRuleKeywords, n.name) || n.name == "by")
      fail(n.pos, "'" + n.name + "' is a reserved name and cannot be declared as a " + kind,
           static_cast<int>(n.name.size()));
  }
  skip_ws(s, p);
  if (p >= s.text.size() || s.text[p] != ':')
    fail(s.at(p), std::string("expected ':' and a domain after the ") + kind +
                      " names, e.g. ': positive [kg]'");
  ++p;
  skip_ws(s, p);
  // domain: a word, or 'in' followed by an interval [a, b] / (a, b) / half-open
  std::size_t db = p;
  std::size_t we;
  std::string dw = word_at(s.text, p, &we);
  // "integer in [1, 10]": the interval follows the word integer
  if (dw == "integer") {
    std::size_t q = we, qe;
    while (q < s.text.size() && is_space(s.text[q])) ++q;
    if (word_at(s.text, q, &qe) == "in") dw = "in", we = qe;
  }
  std::size_t de;
  if (dw == "in") {
    std::size_t q = we;
    while (q < s.text.size() && is_space(s.text[q])) ++q;
    if (q >= s.text.size() || (s.text[q] != '[' && s.text[q] != '('))
      fail(s.at(q), "expected an interval after 'in', e.g. 'in [0, 1]' or 'in (0, pi)'");
    // the bracket that closes the interval, past the parentheses of its bounds (`10^(-40)`)
    std::size_t close = std::string::npos;
    for (std::size_t i = q + 1, depth = 0; i < s.text.size() && close == std::string::npos; ++i) {
      const char c = s.text[i];
      if (c == '(') ++depth;
      else if (c == ']' || (c == ')' && depth == 0)) close = i;
      else if (c == ')') --depth;
    }
    if (close == std::string::npos) fail(s.at(q), "expected ']' or ')' to close the interval");
    de = close + 1;
  } else if (dw.empty()) {
    fail(s.at(p), "expected a domain: real, positive, nonnegative, negative, integer, or an interval 'in [a, b]'");
  } else {
    de = we;
    // "positive integer": a sign word and the word integer
    std::size_t q = de, qe;
    while (q < s.text.size() && is_space(s.text[q])) ++q;
    if (dw != "integer" && word_at(s.text, q, &qe) == "integer") de = qe;
  }
  std::string dtext = s.text.substr(db, de - db);
  Domain domain = parse_domain(dtext, s.at(db));
  p = de;
  skip_ws(s, p);
  if (p >= s.text.size() || s.text[p] != '[')
    fail(s.at(p), "expected the dimension in brackets after the domain, e.g. [kg], [m/s], [1]");
  std::size_t close = s.text.find(']', p);
  if (close == std::string::npos) fail(s.at(p), "expected ']' to close the dimension");
  Node unit = expression(s, p + 1, close, "a dimension inside '[ ]', e.g. [kg*m/s^2] or [1]");
  Dimension dim = parse_dimension(unit);
  p = close + 1;
  std::vector<std::string> tex;
  skip_ws(s, p);
  if (p < s.text.size()) {
    std::size_t te;
    std::string tw = word_at(s.text, p, &te);
    if (tw != "tex") fail(s.at(p), "unexpected text '" + excerpt(s, p) + "'; expected 'tex \"...\"' or the end of the statement");
    SourcePos texpos = s.at(p);
    p = te;
    for (;;) {
      tex.push_back(string_literal(s, p, "a quoted TeX name, e.g. tex \"v'_1\""));
      skip_ws(s, p);
      if (p < s.text.size() && s.text[p] == ',') { ++p; continue; }
      break;
    }
    expect_end(s, p);
    if (tex.size() != names.size())
      fail(texpos, "expected " + std::to_string(names.size()) + " TeX name" + (names.size() == 1 ? "" : "s") +
                       " (one per declared name), found " + std::to_string(tex.size()), 3);
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    SymbolInfo info;
    info.name = names[i].name;
    info.tex = tex.empty() ? std::string() : tex[i];
    info.domain = domain;
    info.dimension = dim;
    info.has_dimension = true;
    if (unit_as_written(unit)) info.unit = to_text(unit);
    info.pos = names[i].pos;
    info.is_function = is_function;
    info.params = params;
    d_.symbols.declare(std::move(info));
  }
}

// --- assume ------------------------------------------------------------------------------

void DcReader::assume_statement(const Span& s, const SourcePos& at) {
  if (!first_assume_) first_assume_ = at;
  // split at top-level comparison operators
  struct Op { std::size_t at, len; Constraint::Op op; };
  std::vector<Op> ops;
  int depth = 0;
  for (std::size_t i = 0; i < s.text.size(); ++i) {
    char c = s.text[i];
    if (c == '(') ++depth;
    else if (c == ')') --depth;
    if (depth != 0) continue;
    char n = i + 1 < s.text.size() ? s.text[i + 1] : '\0';
    if (c == '<' && n == '=') ops.push_back({i, 2, Constraint::Op::Le}), ++i;
    else if (c == '>' && n == '=') ops.push_back({i, 2, Constraint::Op::Ge}), ++i;
    else if (c == '!' && n == '=') ops.push_back({i, 2, Constraint::Op::Ne}), ++i;
    else if (c == '<') ops.push_back({i, 1, Constraint::Op::Lt});
    else if (c == '>') ops.push_back({i, 1, Constraint::Op::Gt});
    else if (c == '=') fail(s.at(i), "'=' is not an assumption; expected one of <, <=, >, >=, != (e.g. 'assume v1 > v2')");
  }
  if (ops.empty()) {
    std::size_t b = 0;
    skip_ws(s, b);
    fail(s.at(b), "expected a relation with <, <=, >, >= or != (e.g. 'assume v1 > v2')");
  }
  std::vector<Node> sides;
  std::size_t from = 0;
  for (const auto& o : ops) {
    sides.push_back(expression(s, from, o.at, "an expression before '" + s.text.substr(o.at, o.len) + "'"));
    from = o.at + o.len;
  }
  sides.push_back(expression(s, from, s.text.size(), "an expression after '" +
                                                          s.text.substr(ops.back().at, ops.back().len) + "'"));
  std::vector<GiNaC::ex> ex;
  for (const auto& n : sides) ex.push_back(converted(n));
  warn_assumption_dimensions(sides);
  std::size_t b = 0, e = s.text.size();
  trim_range(s.text, b, e);
  for (std::size_t i = 0; i < ops.size(); ++i) {
    Constraint c;
    c.lhs = ex[i];
    c.rhs = ex[i + 1];
    c.op = ops[i].op;
    c.text = to_text(sides[i]) + " " + s.text.substr(ops[i].at, ops[i].len) + " " + to_text(sides[i + 1]);
    c.pos = sides[i].pos;
    // underline from the left side to the end of the right side (on one line)
    const Node& r = sides[i + 1];
    int length = r.pos.line == c.pos.line ? r.pos.col + r.length - c.pos.col : static_cast<int>(c.text.size());
    try {
      require_possible_assumption(c, length);
    } catch (const InputError& e) {
      fail(e.pos(), e.message(), e.length());
    }
    d_.symbols.add_constraint(std::move(c));
  }
}

// An assumption compares quantities of one dimension (`m*b^2 <= g*M*L` does not): a mismatch
// is a positioned warning at the side that differs from the first; the assumption still
// applies as written. A literal 0 has every dimension.
void DcReader::warn_assumption_dimensions(const std::vector<Node>& sides) {
  const Node* first = nullptr;
  Dimension first_dim;
  for (const Node& side : sides) {
    if (is_literal_zero(side)) continue;
    Dimension dim;
    try {
      dim = dimension_of(side, d_.symbols);
    } catch (const InputError&) {
      return;   // a dimension error inside a side is reported where the side is used
    }
    if (!first) {
      first = &side;
      first_dim = dim;
    } else if (dim != first_dim) {
      d_.diagnostics.push_back(InputError::warning(
          side.pos,
          "the assumption compares '" + to_text(*first) + "' (dimension " + first_dim.to_string() + ") with '" +
              to_text(side) + "' (dimension " + dim.to_string() + "); it still applies as written",
          side.length, d_.source.line(side.pos.line)));
      return;
    }
  }
}

void DcReader::check_assumptions() {
  Satisfiability sat = decide_satisfiable(d_.symbols);
  if (sat.status == Satisfiability::Status::Satisfiable) return;
  SourcePos p = first_assume_ ? *first_assume_ : SourcePos{file(), 1, 1};
  std::string why = unsatisfiable_message(sat);
  if (sat.status == Satisfiability::Status::Unsatisfiable) why += "; nothing may be derived from a contradiction";
  fail(p, why, 6);
}

// --- names defined by steps --------------------------------------------------------------

void DcReader::introduce_definition(Step& step) {
  const Relation& r = step.claim;
  if (r.sides.size() < 2)
    fail(step.claim_pos, "a definition must be 'NEW = expression' (or 'NEW(t) = expression')");
  const Node& lhs = r.sides[0];
  std::string name;
  std::vector<std::string> params;
  if (lhs.kind == NodeKind::Symbol) {
    name = lhs.text;
  } else if (lhs.kind == NodeKind::Call && !is_builtin_function(lhs.text)) {
    name = lhs.text;
    for (const auto& a : lhs.args) {
      if (a.kind != NodeKind::Symbol || !d_.symbols.find(a.text) || d_.symbols.find(a.text)->is_function)
        fail(a.pos, "the arguments of a defined function must be declared symbols, e.g. 'p(t) = m*v(t)'", a.length);
      params.push_back(a.text);
    }
  } else {
    fail(lhs.pos, "a definition must start with the new name: 'NEW = expression' (found '" + to_text(lhs) + "')",
         lhs.length);
  }
  if (is_reserved_name(name)) fail(lhs.pos, "'" + name + "' is a reserved name and cannot be defined", lhs.length);
  // `T = E1 = E2`: the first link defines T (definition_of); the others are checked claims
  const Node& rhs = r.sides[1];
  std::vector<const Node*> ids;
  for (std::size_t i = 1; i < r.sides.size(); ++i) collect_identifiers(r.sides[i], ids);
  for (const Node* id : ids)
    if (id->text == name) fail(id->pos, "the definition of '" + name + "' refers to itself", id->length);
  check_definition_cycle(name, rhs);
  // Defined earlier by another definition step?
  for (const auto& s : d_.steps)
    if (s.rule.name == "definition" && !s.claim.sides.empty() &&
        (s.claim.sides[0].kind == NodeKind::Symbol || s.claim.sides[0].kind == NodeKind::Call) &&
        s.claim.sides[0].text == name)
      fail(lhs.pos, "'" + name + "' is already defined by step '" + s.label + "' at " + std::to_string(s.pos.line) + ":" +
                        std::to_string(s.pos.col),
           lhs.length);
  if (d_.symbols.find(name)) {
    // Declared with `symbol`: the definition gives its value; the declaration's dimension
    // is checked like every step's.
    const SymbolInfo* info = d_.symbols.find(name);
    if (!step.tex.empty())
      fail(step.tex_pos, "'" + name + "' is declared with 'symbol' (at " + std::to_string(info->pos.line) +
                             "); give its TeX name there", 3);
    if (info->is_function != !params.empty())
      fail(lhs.pos, "'" + name + "' is declared as a " + (info->is_function ? "function" : "symbol") +
                        " but defined as a " + (params.empty() ? "symbol" : "function"),
           lhs.length);
    return;
  }
  // New symbol: dimension of the right-hand side, domain real unless evidently positive.
  SymbolInfo info;
  info.name = name;
  info.pos = lhs.pos;
  info.defined_by_step = true;
  info.tex = step.tex;   // empty: the default from the name (SymbolTable::declare)
  info.is_function = !params.empty();
  info.params = params;
  if (!params.empty()) {
    // the parameters must exist; the body is validated below
  }
  info.dimension = dimension_of(rhs, d_.symbols);
  info.has_dimension = true;
  try {
    GiNaC::ex v = to_ginac(rhs, d_.symbols);
    if (params.empty() && v.info(GiNaC::info_flags::positive)) info.domain = Domain::positive();
  } catch (const UndecidedLimit&) {
    // a limit the engine cannot decide: no domain is inferred; uses of the name are undecided
  }
  d_.symbols.declare(std::move(info));
}

// A symbol declared with `symbol` may be defined after a definition that uses it, so
// definitions can form a cycle (u = v + 1, then v = u - 1), which no expansion ends. Refuse
// the definition that closes one, naming the whole cycle.
void DcReader::check_definition_cycle(const std::string& name, const Node& rhs) {
  std::map<std::string, const Step*> by_name;
  for (const auto& s : d_.steps)
    if (s.rule.name == "definition" && s.claim.sides.size() >= 2 &&
        (s.claim.sides[0].kind == NodeKind::Symbol || s.claim.sides[0].kind == NodeKind::Call))
      by_name.emplace(s.claim.sides[0].text, &s);
  // Depth-first search from the names the new body uses; path holds the chain so far.
  std::set<std::string> done;
  std::vector<const Step*> path;
  std::function<bool(const std::string&)> leads_back = [&](const std::string& n) -> bool {
    if (n == name) return true;
    auto it = by_name.find(n);
    if (it == by_name.end() || !done.insert(n).second) return false;
    path.push_back(it->second);
    std::vector<const Node*> ids;
    collect_identifiers(it->second->claim.sides[1], ids);
    for (const Node* id : ids)
      if (leads_back(id->text)) return true;
    path.pop_back();
    return false;
  };
  std::vector<const Node*> ids;
  collect_identifiers(rhs, ids);
  for (const Node* id : ids) {
    path.clear();
    if (!leads_back(id->text)) continue;
    std::string chain = name, where;
    for (const Step* s : path) {
      chain += " -> " + s->claim.sides[0].text;
      where += std::string(where.empty() ? "" : ", ") + "'" + s->claim.sides[0].text +
               (where.empty() ? "' is defined by step '" : "' by step '") + s->label +
               "' at " + std::to_string(s->pos.line) + ":" + std::to_string(s->pos.col);
    }
    chain += " -> " + name;
    fail(id->pos, "circular definition: " + chain + " (" + where + "); a definition may not depend on itself",
         id->length);
  }
}

}  // namespace dc::reader_detail
