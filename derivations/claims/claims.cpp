#include "derivations/claims/claims.hpp"
#include "derivations/calculus/install.hpp"

#include <chrono>
#include <functional>

#include "derivations/syntax/io.hpp"
#include "derivations/calculus/big_o.hpp"
#include "derivations/claims/internal/bank_units.hpp"
#include "derivations/claims/internal/claim_steps.hpp"
#include "derivations/report/report.hpp"
#include "derivations/decide/satisfiable.hpp"

namespace dc {

namespace {

using GiNaC::ex;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
bool ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool ident_char(char c) { return ident_start(c) || (c >= '0' && c <= '9') || c == '_'; }

SourcePos advance(const SourcePos& o, std::size_t offset) {
  SourcePos p = o;
  p.col += static_cast<int>(offset);
  return p;
}

void trim(const std::string& t, std::size_t& b, std::size_t& e) {
  while (b < e && is_space(t[b])) ++b;
  while (e > b && is_space(t[e - 1])) --e;
}

// Attach the offending text so errors quote it with a caret.
InputError quoted(const InputError& e, const std::string& text) {
  if (!e.line_text().empty()) return e;
  return e.with_line_text(text);
}

}  // namespace

std::vector<AssumptionItem> parse_assumptions(const std::string& text, const SourcePos& origin) {
  std::vector<AssumptionItem> out;
  auto fail = [&](std::size_t at, const std::string& msg, int len = 1) {
    throw InputError(advance(origin, at), msg, len, text);
  };
  // split at top-level commas ([0, 1] and (0, pi) contain commas)
  std::vector<std::pair<std::size_t, std::size_t>> items;
  // An unbalanced bracket is an error at the bracket: dropping the item (`x in [0,1`) would
  // check the claim on a wider domain than the author meant.
  std::vector<std::size_t> open;
  std::size_t from = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    char c = i < text.size() ? text[i] : ',';
    if (c == '(' || c == '[') open.push_back(i);
    else if (c == ')' || c == ']') {
      if (open.empty()) fail(i, std::string("unmatched '") + c + "' in the assumptions");
      open.pop_back();
    }
    if (i == text.size() && !open.empty())
      fail(open.back(), std::string("unclosed '") + text[open.back()] + "' in the assumptions (e.g. 'e in [0, 1]')");
    if (c == ',' && open.empty()) {
      std::size_t b = from, e = i;
      trim(text, b, e);
      if (b < e) items.push_back({b, e});
      else if (i < text.size() || !items.empty()) fail(b, "expected an assumption (e.g. 'm1 > 0', 'v1 real', 'e in [0,1]')");
      from = i + 1;
    }
  }
  for (auto [b, e] : items) {
    std::string item = text.substr(b, e - b);
    // a relation?
    std::size_t op_at = std::string::npos, op_len = 0;
    Constraint::Op op = Constraint::Op::Gt;
    int d = 0;
    for (std::size_t i = 0; i < item.size(); ++i) {
      char c = item[i];
      if (c == '(') ++d;
      else if (c == ')') --d;
      if (d != 0) continue;
      char n = i + 1 < item.size() ? item[i + 1] : '\0';
      std::size_t len = 0;
      Constraint::Op o = Constraint::Op::Gt;
      if (c == '<' && n == '=') len = 2, o = Constraint::Op::Le;
      else if (c == '>' && n == '=') len = 2, o = Constraint::Op::Ge;
      else if (c == '!' && n == '=') len = 2, o = Constraint::Op::Ne;
      else if (c == '<') len = 1, o = Constraint::Op::Lt;
      else if (c == '>') len = 1, o = Constraint::Op::Gt;
      else if (c == '=') fail(b + i, "'=' is not an assumption; expected <, <=, >, >=, != or a domain ('x real', 'x in [0,1]')");
      if (len) {
        if (op_at != std::string::npos) fail(b + i, "expected one comparison per assumption; separate them with ','", static_cast<int>(len));
        op_at = i;
        op_len = len;
        op = o;
        i += len - 1;
      }
    }
    AssumptionItem a;
    a.pos = advance(origin, b);
    a.text = item;
    if (op_at != std::string::npos) {
      std::size_t lb = 0, le = op_at, rb = op_at + op_len, re = item.size();
      trim(item, lb, le);
      trim(item, rb, re);
      if (lb >= le) fail(b + op_at, std::string("expected an expression before '") + op_text(op) + "'");
      if (rb >= re) fail(b + op_at, std::string("expected an expression after '") + op_text(op) + "'");
      try {
        a.lhs = parse_expression(std::string_view(item).substr(lb, le - lb), advance(origin, b + lb));
        a.rhs = parse_expression(std::string_view(item).substr(rb, re - rb), advance(origin, b + rb));
      } catch (const InputError& err) {
        throw quoted(err, text);
      }
      a.op = op;
      bool zero = a.rhs.kind == NodeKind::Number && a.rhs.text == "0";
      if (a.lhs.kind == NodeKind::Symbol && zero && op != Constraint::Op::Ne && op != Constraint::Op::Le) {
        a.name = a.lhs.text;
        if (is_reserved_name(a.name))
          fail(b + lb, "'" + a.name + "' is a predefined constant, not a symbol: it has no domain to assume",
               static_cast<int>(a.name.size()));
        a.domain = op == Constraint::Op::Gt ? Domain::positive()
                   : op == Constraint::Op::Ge ? Domain::nonnegative()
                                              : Domain::negative();
      } else {
        a.is_constraint = true;
      }
      out.push_back(std::move(a));
      continue;
    }
    // NAME DOMAIN
    std::size_t i = 0;
    if (!ident_start(item[0])) fail(b, "expected a symbol name at the start of the assumption '" + item + "'");
    while (i < item.size() && ident_char(item[i])) ++i;
    a.name = item.substr(0, i);
    if (is_reserved_name(a.name))
      fail(b, "'" + a.name + "' is a predefined constant, not a symbol: it has no domain to assume",
           static_cast<int>(a.name.size()));
    std::size_t db = i, de = item.size();
    trim(item, db, de);
    if (db >= de)
      fail(b + i, "expected a domain after '" + a.name + "': real, positive, nonnegative, negative or 'in [a, b]'");
    try {
      a.domain = parse_domain(item.substr(db, de - db), advance(origin, b + db));
    } catch (const InputError& err) {
      throw quoted(err, text);
    }
    out.push_back(std::move(a));
  }
  return out;
}

SymbolTable claim_table(const std::vector<const Node*>& exprs, const std::map<std::string, DomainAt>& domains,
                        const std::vector<AssumptionItem>& items, const SourcePos& assume_pos,
                        const std::vector<std::pair<std::string, std::string>>& functions) {
  SymbolTable table;
  std::vector<std::string> order;
  auto add = [&](const std::string& name) {
    if (std::find(order.begin(), order.end(), name) == order.end()) order.push_back(name);
  };
  auto collect = [&](const Node& n) {
    std::vector<const Node*> ids;
    collect_identifiers(n, ids);
    for (const Node* id : ids)
      if (id->kind == NodeKind::Symbol && !is_reserved_name(id->text)) add(id->text);
  };
  for (const Node* e : exprs) collect(*e);
  for (const auto& it : items)
    if (it.is_constraint) {
      collect(it.lhs);
      collect(it.rhs);
    }
  for (const auto& [name, d] : domains) add(name);
  for (const auto& name : order) {
    SymbolInfo info;
    info.name = name;
    auto it = domains.find(name);
    if (it != domains.end()) {
      info.domain = it->second.domain;
      info.pos = it->second.pos;
    }
    table.declare(std::move(info));
  }
  for (const auto& [name, param] : functions) {
    SymbolInfo info;
    info.name = name;
    info.is_function = true;
    info.params = {param};
    info.pos = assume_pos;
    table.declare(std::move(info));
  }
  for (const auto& it : items) {
    if (!it.is_constraint) continue;
    Constraint c;
    c.lhs = to_ginac(it.lhs, table);
    c.rhs = to_ginac(it.rhs, table);
    c.op = it.op;
    c.text = it.text;
    c.pos = it.pos;
    require_possible_assumption(c, static_cast<int>(it.text.size()));
    table.add_constraint(std::move(c));
  }
  Satisfiability sat = decide_satisfiable(table);
  if (sat.status != Satisfiability::Status::Satisfiable) throw InputError(assume_pos, unsatisfiable_message(sat));
  return table;
}

namespace {

// `n integer, n > 0` (in either order): the integers of one and the sign or interval of the
// other, `positive integer`. Returns false (nothing changed) when neither is plain `integer`.
bool merge_integer(Domain& into, const Domain& other) {
  const bool plain_into = into.kind == Domain::Kind::Real && into.integer;
  const bool plain_other = other.kind == Domain::Kind::Real && other.integer;
  if (!plain_into && !plain_other) return false;
  Domain merged = plain_into ? other : into;
  merged.integer = true;
  into = merged;
  return true;
}

std::map<std::string, DomainAt> domain_map(const std::vector<AssumptionItem>& items, const std::string& text) {
  std::map<std::string, DomainAt> out;
  for (const auto& it : items) {
    if (it.is_constraint) continue;
    auto prev = out.find(it.name);
    if (prev != out.end()) {
      if (prev->second.domain.to_string() == it.domain.to_string()) continue;
      if (merge_integer(prev->second.domain, it.domain)) {
        if (prev->second.domain.empty())
          throw InputError(it.pos, "the assumptions for '" + it.name + "' leave no integer: " +
                                       prev->second.domain.to_string(), static_cast<int>(it.text.size()), text);
        continue;
      }
      throw InputError(it.pos,
                       "conflicting assumptions for '" + it.name + "': " + prev->second.domain.to_string() + " and " +
                           it.domain.to_string(),
                       static_cast<int>(it.text.size()), text);
    }
    out[it.name] = {it.domain, it.pos};
  }
  return out;
}

}  // namespace

Verdict check_equal(const std::string& lhs, const std::string& rhs, const std::string& assume,
                    const ProveOptions& opt) {
  calculus::install();
  SourcePos lo{"<lhs>", 1, 1}, ro{"<rhs>", 1, 1}, ao{"<assume>", 1, 1};
  Node l, r;
  try {
    l = parse_expression(lhs, lo);
  } catch (const InputError& e) {
    throw quoted(e, lhs);
  }
  try {
    r = parse_expression(rhs, ro);
  } catch (const InputError& e) {
    throw quoted(e, rhs);
  }
  std::vector<AssumptionItem> items = parse_assumptions(assume, ao);
  auto domains = domain_map(items, assume);
  SymbolTable table;
  try {
    table = claim_table({&l, &r}, domains, items, ao);
  } catch (const InputError& e) {
    throw quoted(e, e.pos().file == "<lhs>" ? lhs : e.pos().file == "<rhs>" ? rhs : assume);
  }
  try {
    return check_equal_in(table, l, r, opt);
  } catch (const InputError& e) {
    throw quoted(e, e.pos().file == "<lhs>" ? lhs : e.pos().file == "<rhs>" ? rhs : assume);
  }
}

Verdict check_equal_in(const SymbolTable& table, const Node& l, const Node& r, const ProveOptions& opt) {
  calculus::install();
  // The claim is the step `lhs = rhs` (claim_steps.hpp), checked by the rule's code.
  const Derivation d = claims::equal_derivation("<equal>", table, l, r);
  const StepResult res = claims::check_last_step(d, opt);
  if (res.errors.empty()) return res.verdict;
  // The step could not be checked. A side that does not convert is reported at that side, as
  // its conversion reports it (a limit(...) without a value leaves the claim undecided).
  if (!claims::contains_integral(l) && !claims::contains_integral(r)) try {
      for (const Node* side : {&l, &r}) (void)to_ginac(*side, table);
    } catch (const UndecidedLimit& e) {
      Verdict v;
      v.kind = VerdictKind::Undecided;
      v.method = "limit";
      v.reason = e.what();
      return v;
    }
  throw res.errors.front();
}

// --- the claim bank ----------------------------------------------------------------------

namespace {

struct LineError {
  std::string message;
};

// The file name given to positions inside a claim's "assume" field.
const char* const kAssumeField = "<assume field>";

class ClaimLine {
 public:
  ClaimLine(const nlohmann::json& j, int line_no, const std::string& file, const ProveOptions& opt)
      : j_(j), line_(line_no), file_(file), opt_(opt) {}

  // The dimensional evidence of the line's "units" (bank_units.hpp), once run() has read it.
  const std::optional<std::string>& dimensions() const { return dimensions_; }

  Verdict run(const std::string& kind) {
    std::vector<std::string> fields{"lhs", "rhs"};
    if (kind == "limit" || kind == "antiderivative" || kind == "series_first_order" || kind == "series" ||
        kind == "solves_ode")
      fields.push_back("var");
    if (kind == "solves_ode") fields.push_back("solution");
    std::map<std::string, Node> nodes;
    for (const auto& f : fields) nodes[f] = expr(f);
    if (kind == "limit" || kind == "series_first_order" || kind == "series") point_node_ = point();
    // symbols: identifiers of all expressions; y, yp, ypp for ODEs
    std::map<std::string, DomainAt> domains = assumptions();
    std::vector<AssumptionItem> items = assume_items(domains);
    std::vector<const Node*> exprs;
    for (auto& [k, n] : nodes) (void)k, exprs.push_back(&n);
    if (big_o_) exprs.push_back(&*big_o_);
    if (point_node_ && !point_infinite_) exprs.push_back(&*point_node_);
    std::vector<Node> initial_nodes;
    if (kind == "solves_ode") initial_nodes = initial_values();
    for (const auto& n : initial_nodes) exprs.push_back(&n);
    auto table_of = [&](const std::vector<const Node*>& of,
                        const std::vector<std::pair<std::string, std::string>>& functions) {
      try {
        return claim_table(of, domains, items, SourcePos{file_, line_, 1}, functions);
      } catch (const InputError& e) {
        if (e.pos().file == kAssumeField)
          throw LineError{"in field 'assume' (column " + std::to_string(e.pos().col) + "): " + e.message()};
        throw LineError{"in 'assumptions': " + e.message()};
      }
    };
    table_ = table_of(exprs, {});
    try {
      const claims::BankUnits units = claims::read_units(j_);
      if (kind == "antiderivative")
        dimensions_ = claims::dimension_evidence(units, table_, nodes.at("rhs"), "rhs", nodes.at("lhs"),
                                                 "lhs times " + to_text(nodes.at("var")), &nodes.at("var"));
      else if (kind != "solves_ode" && rhs_word_.empty())
        dimensions_ = claims::dimension_evidence(units, table_, nodes.at("lhs"), "lhs", nodes.at("rhs"), "rhs");
    } catch (const std::invalid_argument& e) {
      throw LineError{e.what()};
    }
    auto conv = [&](const std::string& f) -> ex {
      try {
        return to_ginac(nodes.at(f), table_);
      } catch (const InputError& e) {
        throw LineError{"in field '" + f + "' (column " + std::to_string(e.pos().col) + "): " + e.message()};
      }
      // an UndecidedLimit (a limit that does not exist or is infinite, an integral without a
      // value) is no bad input: run()'s caller makes the claim undecided with the reason
    };
    // From here on the fields are only validated as before (their errors keep their texts);
    // the claim itself is the one-step derivation of claim_steps.hpp, checked by the rule.
    if (kind == "equal") {
      const Node& l = nodes.at("lhs");
      const Node& r = nodes.at("rhs");
      const Derivation d = claims::equal_derivation(file_, table_, l, r);
      const StepResult res = claims::check_last_step(d, opt_);
      if (res.errors.empty()) return res.verdict;
      if (claims::contains_integral(l) || claims::contains_integral(r))
        throw LineError{"in the integral: " + res.errors.front().message()};
      // a side that does not convert is reported at its field (a limit(...) without a value
      // leaves the claim undecided)
      conv("lhs");
      conv("rhs");
      throw LineError{res.errors.front().message()};
    }
    conv("lhs");
    conv("rhs");
    ex var = conv("var");
    if (!GiNaC::is_a<GiNaC::symbol>(var)) throw LineError{"field 'var' must be a symbol name"};
    const GiNaC::symbol& x = GiNaC::ex_to<GiNaC::symbol>(var);
    if (kind == "antiderivative")
      return checked(claims::antiderivative_derivation(file_, table_, nodes.at("lhs"), nodes.at("rhs"), nodes.at("var")));
    if (kind == "limit") {
      if (!point_infinite_) to_ginac(*point_node_, table_);
      const int dir = limit_direction();
      Node rhs = rhs_word_.empty() ? nodes.at("rhs") : parse_field("rhs", rhs_word_);
      return checked(claims::limit_derivation(file_, table_, nodes.at("lhs"), rhs, approach(nodes.at("var"), dir)));
    }
    if (kind == "series") {
      // lhs - rhs = O((var - point)^order) as var -> point (from "dir")
      ex p = point_infinite_ ? ex(0) : to_ginac(*point_node_, table_);
      if (j_.contains("order") && !j_.at("order").is_number_integer())
        throw LineError{"field 'order' must be an integer (lhs - rhs = O((var - point)^order))"};
      if (!j_.contains("order") && !big_o_)
        throw LineError{"a series claim needs an integer field 'order' (lhs - rhs = O((var - point)^order)) or an "
                        "order term in the rhs ('x - x^3/6 + O(x^5)')"};
      long long order = j_.contains("order") ? j_.at("order").get<long long>() : 0;
      if (big_o_) {
        int from_term = order_of_big_o(x, p);
        if (j_.contains("order") && from_term != order)
          throw LineError{"field 'order' is " + std::to_string(order) + " but the rhs ends in O(" + to_text(*big_o_) +
                          "), order " + std::to_string(from_term)};
        order = from_term;
      }
      if (order < -1000 || order > 1000) throw LineError{"field 'order' must be between -1000 and 1000"};
      int dir = limit_direction();
      if (point_infinite_ && dir != 0) throw LineError{"field 'dir' goes with a finite point"};
      return checked(claims::series_derivation(file_, table_, nodes.at("lhs"), nodes.at("rhs"),
                                               approach(nodes.at("var"), dir), static_cast<int>(order), big_o_));
    }
    if (kind == "series_first_order") {
      // lhs = rhs + O((var - point)^2): the rule's first-order form, from the side `dir` names
      if (!point_infinite_) to_ginac(*point_node_, table_);
      const int dir = limit_direction();
      if (big_o_) {
        ex p = point_infinite_ ? ex(0) : to_ginac(*point_node_, table_);
        if (!point_infinite_ && order_of_big_o(x, p) != 2)
          throw LineError{"a first-order claim ends in O((var - point)^2), got O(" + to_text(*big_o_) + ")"};
      }
      return checked(claims::series_derivation(file_, table_, nodes.at("lhs"), nodes.at("rhs"),
                                               approach(nodes.at("var"), dir),
                                               big_o_ && !point_infinite_ ? std::optional<int>(2) : std::nullopt, big_o_));
    }
    // solves_ode: the ODE lhs = rhs in y, yp, ypp; the claimed solution; initial values.
    ex sol = conv("solution");
    for (const char* name : claims::kOdeNames)
      if (const SymbolInfo* info = table_.find(name); info && sol.has(info->sym))
        throw LineError{std::string("the solution must not contain '") + name + "'"};
    // The derivation's table declares y as a function of var (`function y(t)`), in place of the
    // symbols y, yp, ypp: the ODE's sides are written with y(t) and its derivatives.
    std::vector<Node> ode{claims::ode_form(nodes.at("lhs"), nodes.at("var")),
                          claims::ode_form(nodes.at("rhs"), nodes.at("var"))};
    std::vector<const Node*> ode_exprs{&ode[0], &ode[1], &nodes.at("solution"), &nodes.at("var")};
    for (const auto& n : initial_nodes) ode_exprs.push_back(&n);
    const SymbolTable ode_table = table_of(ode_exprs, {{claims::kOdeNames[0], x.get_name()}});
    std::vector<claims::InitialValue> initial;
    for (std::size_t i = 0; i < initial_nodes.size() / 2; ++i)
      initial.push_back({initial_nodes[2 * i], initial_nodes[2 * i + 1], initial_orders_[i]});
    return checked(claims::ode_derivation(file_, ode_table, nodes.at("lhs"), nodes.at("rhs"), nodes.at("var"),
                                          nodes.at("solution"), initial));
  }

 private:
  std::optional<std::string> dimensions_;
  const nlohmann::json& j_;
  int line_;
  std::string file_;
  const ProveOptions& opt_;
  SymbolTable table_;
  std::optional<Node> point_node_;
  std::optional<Node> big_o_;   // series: the argument of an O(...) term taken off the rhs
  int point_infinite_ = 0;
  std::string rhs_word_;          // limit: "rhs" is oo, -oo or undefined (the limit rule's limit values)
  std::vector<int> initial_orders_;

  // The claim's step checked by its rule (check_step): its verdict, or the first error of a
  // step that could not be checked as an error of the line.
  Verdict checked(const Derivation& d) {
    StepResult res = claims::check_last_step(d, opt_);
    if (!res.errors.empty()) throw LineError{res.errors.front().message()};
    return res.verdict;
  }

  claims::Approach approach(const Node& var, int dir) {
    claims::Approach a;
    a.var = var;
    a.point = point_infinite_ ? parse_field("point", point_infinite_ > 0 ? "oo" : "-oo") : *point_node_;
    a.dir = dir;
    return a;
  }

  std::string text_field(const std::string& f, const nlohmann::json& j) {
    if (!j.contains(f)) throw LineError{"missing field '" + f + "'"};
    const auto& v = j.at(f);
    if (v.is_string()) return v.get<std::string>();
    if (v.is_number()) return v.dump();
    throw LineError{"field '" + f + "' must be a string"};
  }

  Node parse_field(const std::string& f, const std::string& text) {
    try {
      return parse_expression(text, SourcePos{file_, line_, 1});
    } catch (const InputError& e) {
      throw LineError{"in field '" + f + "' (column " + std::to_string(e.pos().col) + "): " + e.message()};
    }
  }

  Node expr(const std::string& f) {
    std::string t = text_field(f, j_);
    if (f == "rhs" && j_.value("kind", "") == "limit") {
      if (t == "oo" || t == "+oo" || t == "-oo" || t == "undefined") {
        rhs_word_ = t == "+oo" ? "oo" : t;
        return parse_field(f, "0");
      }
    }
    Node n = parse_field(f, t);
    if (f == "rhs" && (j_.value("kind", "") == "series" || j_.value("kind", "") == "series_first_order"))
      n = strip_big_o(n);
    return n;
  }

  // series: a right-hand side may end in its order term, `x - x^3/6 + O(x^5)`, as other systems
  // print it; the term is taken off and gives the order (checked against "order" if given).
  Node strip_big_o(const Node& n) {
    Node rest, arg;
    if (!split_order_term(n, rest, arg)) return n;
    big_o_ = arg;
    return rest;
  }

  // The order N of an O(...) term: O((x - p)^N), O(x^N) at p = 0, O(x^-N) at infinity.
  int order_of_big_o(const GiNaC::symbol& x, const ex& p) {
    std::string why;
    std::optional<int> n = order_of_term(to_ginac(*big_o_, table_), x, p, point_infinite_, &why);
    if (!n) throw LineError{why + ", got O(" + to_text(*big_o_) + ")"};
    return *n;
  }

  // limit: "dir": "+" (from above), "-" (from below); absent or "+-": two-sided.
  int limit_direction() {
    if (!j_.contains("dir")) return 0;
    std::string t = text_field("dir", j_);
    if (t == "+") return 1;
    if (t == "-") return -1;
    if (t == "+-" || t.empty()) return 0;
    throw LineError{"field 'dir' must be \"+\" (from above), \"-\" (from below) or \"+-\" (two-sided), got '" + t +
                    "'"};
  }

  std::optional<Node> point() {
    std::string t = text_field("point", j_);
    if (t == "oo" || t == "+oo") { point_infinite_ = 1; return parse_field("point", "0"); }
    if (t == "-oo") { point_infinite_ = -1; return parse_field("point", "0"); }
    return parse_field("point", t);
  }

  std::map<std::string, DomainAt> assumptions() {
    std::map<std::string, DomainAt> out;
    if (!j_.contains("assumptions")) return out;
    const auto& a = j_.at("assumptions");
    if (!a.is_object()) throw LineError{"field 'assumptions' must be an object {\"name\": \"domain\"}"};
    for (auto it = a.begin(); it != a.end(); ++it) {
      if (!it.value().is_string()) throw LineError{"assumption '" + it.key() + "' must be a string domain"};
      bool ok = !it.key().empty() && ident_start(it.key()[0]);
      for (char c : it.key()) ok = ok && ident_char(c);
      if (!ok || is_reserved_name(it.key())) throw LineError{"assumption key '" + it.key() + "' is not a symbol name"};
      try {
        out[it.key()] = {parse_domain(it.value().get<std::string>(), SourcePos{file_, line_, 1}), {file_, line_, 1}};
      } catch (const InputError& e) {
        throw LineError{"in assumption '" + it.key() + "': " + e.message()};
      }
    }
    return out;
  }

  // The optional field "assume": an assumption list as for `equal --assume` (domains such as
  // "x > 0", "e in [0, 1]" and relations such as "x > 1000000", "v1 > v2"). Its domains join
  // those of "assumptions" (a symbol given two different domains is an error); positions in its
  // errors are columns inside the field.
  std::vector<AssumptionItem> assume_items(std::map<std::string, DomainAt>& domains) {
    if (!j_.contains("assume")) return {};
    if (!j_.at("assume").is_string()) throw LineError{"field 'assume' must be a string such as \"x > 0, v1 > v2\""};
    std::string text = j_.at("assume").get<std::string>();
    std::vector<AssumptionItem> items;
    try {
      items = parse_assumptions(text, SourcePos{kAssumeField, line_, 1});
    } catch (const InputError& e) {
      throw LineError{"in field 'assume' (column " + std::to_string(e.pos().col) + "): " + e.message()};
    }
    for (const auto& it : items) {
      if (it.is_constraint) continue;
      auto prev = domains.find(it.name);
      if (prev != domains.end() && prev->second.domain.to_string() != it.domain.to_string() &&
          merge_integer(prev->second.domain, it.domain)) {
        if (prev->second.domain.empty())
          throw LineError{"in field 'assume' (column " + std::to_string(it.pos.col) + "): the assumptions for '" +
                          it.name + "' leave no integer: " + prev->second.domain.to_string()};
        continue;
      }
      if (prev != domains.end() && prev->second.domain.to_string() != it.domain.to_string())
        throw LineError{"in field 'assume' (column " + std::to_string(it.pos.col) + "): conflicting assumptions for '" +
                        it.name + "': " + prev->second.domain.to_string() + " and " + it.domain.to_string()};
      domains[it.name] = {it.domain, it.pos};
    }
    return items;
  }

  std::vector<Node> initial_values() {
    std::vector<Node> out;
    if (!j_.contains("initial")) return out;
    const auto& a = j_.at("initial");
    if (!a.is_array()) throw LineError{"field 'initial' must be a list of {\"at\", \"order\", \"value\"}"};
    for (const auto& c : a) {
      if (!c.is_object()) throw LineError{"each initial condition must be an object {\"at\", \"order\", \"value\"}"};
      int order = 0;
      if (c.contains("order")) {
        if (!c.at("order").is_number_integer() || c.at("order").get<int>() < 0 || c.at("order").get<int>() > 1)
          throw LineError{"'order' of an initial condition must be 0 or 1"};
        order = c.at("order").get<int>();
      }
      initial_orders_.push_back(order);
      out.push_back(parse_field("initial.at", text_field("at", c)));
      out.push_back(parse_field("initial.value", text_field("value", c)));
    }
    return out;
  }
};

}  // namespace

nlohmann::ordered_json claim_line_error(int line_no, const std::string& file, const std::string& message,
                                        const nlohmann::json* id) {
  nlohmann::ordered_json out;
  if (id) out["id"] = *id;
  out["line"] = line_no;
  out["verdict"] = "error";
  out["error"] = file + ":" + std::to_string(line_no) + ": error: " + message;
  return out;
}

nlohmann::ordered_json claim_line_undecided(const std::string& line, int line_no, const std::string& method,
                                            const std::string& reason) {
  nlohmann::ordered_json out;
  // Only the id and the kind are read back from the line (it was valid enough to be tried).
  nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
  if (j.is_object() && j.contains("id")) out["id"] = j.at("id");
  out["line"] = line_no;
  if (j.is_object() && j.contains("kind") && j.at("kind").is_string()) out["kind"] = j.at("kind");
  Verdict v;
  v.kind = VerdictKind::Undecided;
  v.method = method;
  v.reason = reason;
  nlohmann::ordered_json vj = verdict_json(v);
  for (auto& [k, val] : vj.items()) out[k] = val;
  return out;
}

namespace {

// The line with every byte that is not valid UTF-8 replaced by U+FFFD.
std::string replace_invalid_utf8(std::string_view s) {
  std::string out;
  while (!s.empty()) {
    std::size_t bad = invalid_utf8_at(s);
    if (bad == std::string_view::npos) {
      out += s;
      break;
    }
    out += s.substr(0, bad);
    out += "\xEF\xBF\xBD";
    s.remove_prefix(bad + 1);
  }
  return out;
}

char hex_digit(int v) { return static_cast<char>(v < 10 ? '0' + v : 'A' + v - 10); }

}  // namespace

nlohmann::ordered_json check_claim_line(const std::string& line, int line_no, const std::string& file,
                                        const ProveOptions& opt) {
  calculus::install();
  nlohmann::ordered_json out;
  auto t0 = std::chrono::steady_clock::now();
  nlohmann::json j;
  auto error = [&](const std::string& msg) {
    out["line"] = line_no;
    out["verdict"] = "error";
    out["error"] = file + ":" + std::to_string(line_no) + ": error: " + msg;
    return out;
  };
  // JSON is UTF-8: a line that is not is an error (named by its id when the rest of the line
  // still reads as a claim), and the other lines go on.
  if (std::size_t bad = invalid_utf8_at(line); bad != std::string::npos) {
    unsigned char b = static_cast<unsigned char>(line[bad]);
    std::string msg = "invalid UTF-8 at column " + std::to_string(bad + 1) + " (byte 0x" + hex_digit(b >> 4) +
                      hex_digit(b & 15) + "); a claim bank must be UTF-8 text";
    nlohmann::json guess = nlohmann::json::parse(replace_invalid_utf8(line), nullptr, false);
    if (guess.is_object() && guess.contains("id")) return claim_line_error(line_no, file, msg, &guess.at("id"));
    return claim_line_error(line_no, file, msg);
  }
  try {
    j = nlohmann::json::parse(line);
  } catch (const nlohmann::json::exception& e) {
    std::string what = e.what();
    // "[json.exception.parse_error.101] parse error at line 1, column 5: ..." -> keep the part
    // after the library's tag
    auto p = what.find("] ");
    return error("malformed JSON: " + (p == std::string::npos ? what : what.substr(p + 2)));
  }
  if (!j.is_object()) return error("expected a JSON object per line");
  if (j.contains("id")) out["id"] = j.at("id");
  out["line"] = line_no;
  if (!j.contains("kind"))
    return error("missing field 'kind' (one of equal, limit, series, antiderivative, series_first_order, solves_ode)");
  if (!j.at("kind").is_string())
    return error("field 'kind' must be a string (one of equal, limit, series, antiderivative, series_first_order, solves_ode)");
  std::string kind = j.at("kind").get<std::string>();
  static const std::vector<std::string> kinds{"equal", "limit", "series", "antiderivative", "series_first_order",
                                              "solves_ode"};
  if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end())
    return error("unknown kind '" + kind + "'; expected one of equal, limit, series, antiderivative, series_first_order, solves_ode");
  out["kind"] = kind;
  Verdict v;
  std::optional<std::string> dimensions;
  try {
    ClaimLine c(j, line_no, file, opt);
    try {
      v = c.run(kind);
    } catch (...) {
      dimensions = c.dimensions();
      throw;
    }
    dimensions = c.dimensions();
  } catch (const LineError& e) {
    return error(e.message);
  } catch (const InputError& e) {
    return error(e.message());
  } catch (const UndecidedLimit& e) {
    // a well-formed line whose limit or integral has no usable value (it does not exist, is
    // infinite, or no method evaluates it): undecided with that reason
    v = Verdict{};
    v.kind = VerdictKind::Undecided;
    v.method = "limit";
    v.reason = e.what();
  } catch (const std::exception& e) {
    // The line is well formed (its errors are LineError / InputError above): a library failure
    // inside the computation leaves the claim undecided, with what failed, not an input error.
    v = Verdict{};
    v.kind = VerdictKind::Undecided;
    v.method = "internal";
    v.reason = std::string("a symbolic computation failed: ") + e.what();
  }
  // a dimension mismatch is the first evidence (the verdict stays the rule's)
  if (dimensions) v.detail = *dimensions + (v.detail.empty() ? "" : "; " + v.detail);
  nlohmann::ordered_json vj = verdict_json(v);
  for (auto& [k, val] : vj.items()) out[k] = val;
  if (dimensions) out["dimensions"] = *dimensions;
  out["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace dc
