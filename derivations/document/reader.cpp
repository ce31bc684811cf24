// A LaTeX or Markdown document -> Derivation (document.hpp). The split into displays and rows
// is syntax/document.cpp, the TeX of each row syntax/tex_math.cpp; this file decides what the
// rows mean together: which names are functions of a variable, which are vectors, which
// inline givens are in force for a display, which rows a step may cite.
#include <algorithm>
#include <cctype>

#include "derivations/calculus/install.hpp"
#include "derivations/document/reader.hpp"
#include "derivations/symbolic/vectors.hpp"
#include "derivations/syntax/io.hpp"

namespace dc {
namespace document_detail {

std::string relation_word(TexRel r) {
  switch (r) {
    case TexRel::Eq: return "=";
    case TexRel::Approx: return "approx";
    case TexRel::Lt: return "<";
    case TexRel::Le: return "<=";
    case TexRel::Gt: return ">";
    case TexRel::Ge: return ">=";
    case TexRel::Ne: return "!=";
    case TexRel::Gives: return "=";
  }
  return "=";
}

void walk(Node& n, const std::function<void(Node&)>& f) {
  f(n);
  for (auto& a : n.args) walk(a, f);
}
void walk(const Node& n, const std::function<void(const Node&)>& f) {
  f(n);
  for (const auto& a : n.args) walk(a, f);
}

// Names used as plain symbols (not calls, not reserved words).
void symbol_names(const Node& n, std::set<std::string>& out) {
  walk(n, [&](const Node& x) {
    if (x.kind == NodeKind::Symbol && !is_reserved_name(x.text)) out.insert(x.text);
  });
}

// How a side is built from vectors: 0 scalar, 1 linear in the vectors (each term one vector
// factor with scalar coefficients), -1 anything else (a product of vectors, a vector in a
// function, a denominator or a power, a sum of a vector and a scalar). A relation whose sides
// are all of degree 1 (or a literal 0) holds as vectors exactly when it holds for each
// component, and each component is the same scalar relation: it is checked as that.
int vector_degree(const Node& n, const std::set<std::string>& vectors) {
  switch (n.kind) {
    case NodeKind::Number: return 0;
    case NodeKind::Symbol: return vectors.count(n.text) ? 1 : 0;
    case NodeKind::Neg: return vector_degree(n.args[0], vectors);
    case NodeKind::Add:
    case NodeKind::Sub: {
      const int a = vector_degree(n.args[0], vectors), b = vector_degree(n.args[1], vectors);
      if (a < 0 || b < 0) return -1;
      return a == b ? a : -1;
    }
    case NodeKind::Mul: {
      const int a = vector_degree(n.args[0], vectors), b = vector_degree(n.args[1], vectors);
      if (a < 0 || b < 0 || a + b > 1) return -1;
      return a + b;
    }
    case NodeKind::Div: {
      const int a = vector_degree(n.args[0], vectors), b = vector_degree(n.args[1], vectors);
      return a < 0 || b != 0 ? -1 : a;
    }
    case NodeKind::Pow: {
      const int a = vector_degree(n.args[0], vectors), b = vector_degree(n.args[1], vectors);
      return a == 0 && b == 0 ? 0 : -1;
    }
    case NodeKind::Call: {
      // a vector function of a variable, p(t) written bold
      const std::size_t of = n.text.find("__of_");
      if (of != std::string::npos && vectors.count(n.text.substr(0, of))) return 1;
      // linear operators in their first argument: d/dt, an integral, a limit
      if ((n.text == "diff" || n.text == "integral" || n.text == "limit") && !n.args.empty()) {
        for (std::size_t i = 1; i < n.args.size(); ++i)
          if (vector_degree(n.args[i], vectors) != 0) return -1;
        return vector_degree(n.args[0], vectors);
      }
      for (const auto& a : n.args)
        if (vector_degree(a, vectors) != 0) return -1;
      return 0;
    }
  }
  return -1;
}

bool is_zero_literal(const Node& n) { return n.kind == NodeKind::Number && (n.text == "0" || n.text == "0.0"); }

Derivation DocumentReader::run() {
  calculus::install();
  d_.source = doc_.source;
  d_.title = title();
  for (const auto& w : doc_.warnings) d_.diagnostics.push_back(w);
  read_tex_macros(doc_.macro_text, ctx_);
  directives();
  if (d_.symbols.find("e")) ctx_.e_is_euler = false;
  parse_rows();
  inline_givens();
  mark_definitions();
  neglected_names();
  build_steps();
  declare_symbols();
  assumptions();
  authors_rules();
  if (d_.steps.empty())
    throw InputError({d_.source.name, 0, 0},
                     "no displayed relation to check (a document needs at least one displayed equation: "
                     "$$…$$, \\[…\\] or an equation/align environment)");
  d_.index();
  return std::move(d_);
}

std::string DocumentReader::title() const {
  std::string name = doc_.source.name;
  const std::size_t slash = name.find_last_of('/');
  if (slash != std::string::npos) name = name.substr(slash + 1);
  return name;
}

// `derivcheck: symbol …` / `function …` / `assume …` lines, read by the .dc reader; an error
// is reported at the directive's own position in the document.
void DocumentReader::directives() {
  if (doc_.directives.empty()) return;
  std::string text;
  bool exact_columns = true;
  for (const auto& dir : doc_.directives) {
    if (dir.text.rfind("assume", 0) == 0) {   // after the names are known (assumptions())
      assumes_.push_back(&dir);
      text += "\n";
      continue;
    }
    const std::string line = as_dc(dir);
    exact_columns = exact_columns && line == dir.text;
    text += line + "\n";
  }
  text += "dc_directives_end: 0 = 0\n  by rewrite\n";
  Derivation parsed;
  try {
    parsed = parse_derivation(SourceText{doc_.source.name, text});
  } catch (const InputError& e) {
    const int i = e.pos().line - 1;
    if (i >= 0 && i < static_cast<int>(doc_.directives.size())) {
      const SourcePos& o = doc_.directives[static_cast<std::size_t>(i)].origin;
      SourcePos p{doc_.source.name, o.line, o.col + (exact_columns ? std::max(0, e.pos().col - 1) : 0)};
      throw InputError(p, e.message() + " (in a derivcheck: directive)", e.length(), doc_.source.line(o.line));
    }
    throw InputError({doc_.source.name, 0, 0}, e.message() + " (in the derivcheck: directives)");
  }
  d_.symbols = parsed.symbols;
}

// A directive in the document's own notation, as a .dc line: names may be TeX (`\mu`,
// `v'_1`), the dimension may be left out (then the names are dimensionless, as every
// undeclared name of a document is), an assumption may be TeX (`\theta < \pi/2`).
std::string DocumentReader::as_dc(const DocDirective& dir) const {
  const std::string& t = dir.text;
  auto word_end = t.find_first_of(" \t");
  const std::string word = t.substr(0, word_end);
  if ((word == "symbol" || word == "function") && word_end != std::string::npos) {
    const std::size_t colon = t.find(':');
    if (colon == std::string::npos) return t;
    std::string names;
    std::size_t p = word_end;
    while (p < colon) {
      std::size_t comma = t.find(',', p);
      if (comma == std::string::npos || comma > colon) comma = colon;
      std::string name = t.substr(p, comma - p);
      const std::size_t b = name.find_first_not_of(" \t"), e = name.find_last_not_of(" \t");
      name = b == std::string::npos ? "" : name.substr(b, e - b + 1);
      if (!name.empty() && word == "symbol") {
        try {
          Node n = parse_tex_expression(name, dir.origin, ctx_);
          if (n.kind == NodeKind::Symbol) name = n.text;
        } catch (const InputError&) {
          // left as written: the .dc reader reports it
        }
      }
      names += (names.empty() ? "" : ", ") + name;
      p = comma + 1;
    }
    std::string rest = t.substr(colon);
    if (rest.find('[') == std::string::npos) {
      const std::size_t tex = rest.find(" tex ");
      rest.insert(tex == std::string::npos ? rest.size() : tex, " [1]");
    }
    return word + " " + names + " " + rest;
  }
  if (word == "assume" && word_end != std::string::npos) {
    try {
      TexRow row = parse_tex_row(std::string_view(t).substr(word_end), dir.origin, ctx_);
      if (row.chains.size() == 1 && row.chains[0].sides.size() == 2) {
        static const std::map<TexRel, std::string> ops = {
            {TexRel::Lt, "<"}, {TexRel::Le, "<="}, {TexRel::Gt, ">"}, {TexRel::Ge, ">="}, {TexRel::Ne, "!="}};
        auto op = ops.find(row.chains[0].rels[0]);
        if (op != ops.end())
          return "assume " + to_text(row.chains[0].sides[0]) + " " + op->second + " " +
                 to_text(row.chains[0].sides[1]);
      }
    } catch (const InputError&) {
    }
  }
  return t;
}

// `derivcheck: assume v_1 > v_2` (TeX or .dc notation), once every name is declared.
void DocumentReader::assumptions() {
  static const std::map<TexRel, Constraint::Op> ops = {{TexRel::Lt, Constraint::Op::Lt},
                                                       {TexRel::Le, Constraint::Op::Le},
                                                       {TexRel::Gt, Constraint::Op::Gt},
                                                       {TexRel::Ge, Constraint::Op::Ge},
                                                       {TexRel::Ne, Constraint::Op::Ne}};
  for (const DocDirective* dir : assumes_) {
    const std::string_view rel = std::string_view(dir->text).substr(6);
    SourcePos at = dir->origin;
    at.col += 6;
    TexRow row = parse_tex_row(rel, at, ctx_);
    if (row.chains.size() != 1 || row.chains[0].sides.size() != 2 || !ops.count(row.chains[0].rels[0]))
      throw InputError(dir->origin, "expected one relation <, <=, >, >= or != after 'assume'",
                       static_cast<int>(dir->text.size()), doc_.source.line(dir->origin.line));
    const TexChain& ch = row.chains[0];
    Constraint c;
    c.lhs = to_ginac(ch.sides[0], d_.symbols);
    c.rhs = to_ginac(ch.sides[1], d_.symbols);
    c.op = ops.at(ch.rels[0]);
    c.text = to_text(ch.sides[0]) + " " + op_text(c.op) + " " + to_text(ch.sides[1]);
    c.pos = dir->origin;
    d_.symbols.add_constraint(std::move(c));
  }
}

// Does any row use e as a plain symbol (a coefficient of restitution)? Then e^2 is its square.
bool DocumentReader::uses_symbol_e() const {
  bool found = false;
  for (const auto& r : rows_)
    for (const auto& ch : r.tex.chains)
      for (const auto& side : ch.sides)
        walk(side, [&](const Node& x) { found = found || (x.kind == NodeKind::Symbol && x.text == "e"); });
  return found;
}

void DocumentReader::parse_rows() {
  parse_all_rows();
  if (ctx_.e_is_euler && uses_symbol_e()) {
    ctx_.e_numeric_power_is_symbol = true;
    rows_.clear();
    parse_all_rows();
  }
  join_broken_sides();
  mark_functions_and_vectors();
}

// A row that begins with + or - after the alignment (`&\quad + c`) is the rest of the
// previous row's last side, broken over two rows: joined to it.
void DocumentReader::join_broken_sides() {
  std::vector<ReadRow> out;
  for (auto& r : rows_) {
    const bool broken = r.not_read.empty() && !r.tex.chains.empty() && r.tex.chains.front().continues_side;
    if (broken && !out.empty() && out.back().display == r.display && out.back().not_read.empty() &&
        !out.back().tex.chains.empty() && !out.back().tex.chains.back().sides.empty()) {
      TexChain& prev = out.back().tex.chains.back();
      TexChain& rest = r.tex.chains.front();
      Node sum;
      sum.kind = NodeKind::Add;
      sum.pos = prev.sides.back().pos;
      sum.op_pos = rest.sides.front().pos;
      sum.args = {prev.sides.back(), rest.sides.front()};
      prev.sides.back() = std::move(sum);
      for (std::size_t i = 1; i < rest.sides.size(); ++i) {
        prev.sides.push_back(rest.sides[i]);
        prev.rels.push_back(rest.rels[i - 1]);
        prev.rel_pos.push_back(rest.rel_pos[i - 1]);
      }
      for (std::size_t c = 1; c < r.tex.chains.size(); ++c) out.back().tex.chains.push_back(r.tex.chains[c]);
      if (out.back().tex.tag.empty()) out.back().tex.tag = r.tex.tag;
      if (out.back().tex.label.empty()) out.back().tex.label = r.tex.label;
      for (const auto& v : r.tex.vector_names) out.back().tex.vector_names.insert(v);
      for (const auto& v : r.vectors) out.back().vectors.insert(v);
      continue;
    }
    if (broken) {
      r.not_read = "the row continues a side, but no row before it in this display has one";
      r.not_read_pos = r.row->origin;
    }
    out.push_back(std::move(r));
  }
  rows_ = std::move(out);
}

void DocumentReader::parse_all_rows() {
  for (std::size_t k = 0; k < doc_.displays.size(); ++k) {
    for (const auto& row : doc_.displays[k].rows) {
      ReadRow r;
      r.row = &row;
      r.display = k;
      try {
        r.tex = parse_tex_row(row.text, row.origin, ctx_);
      } catch (const InputError& e) {
        r.not_read = e.message();
        r.not_read_pos = e.pos();
      }
      // a name written bold is another quantity than the same letter in italic, unless a
      // directive declares it a vector (`vector p : 3 [kg*m/s]`): then it is that vector
      std::set<std::string> undeclared;
      for (const auto& v : r.tex.vector_names) {
        const SymbolInfo* s = d_.symbols.find(v);
        if (s && s->vector_dim) continue;
        undeclared.insert(v);
        r.vectors.insert(v + "_vec");
      }
      for (auto& ch : r.tex.chains)
        for (auto& side : ch.sides) {
          if (!undeclared.empty()) rename_vectors(side, undeclared);
          if (undeclared.size() < r.tex.vector_names.size()) vector_products(side);
        }
      rows_.push_back(std::move(r));
    }
  }
}

// `W = \int_0^L F\,dx` where another row says `F = F_0 x^2/L^2`: the integrand varies with
// x through that row, and reading F as a constant would be wrong. Not read yet.
void DocumentReader::mark_integrands_through_definitions() {
  std::map<std::string, std::set<std::string>> defined;   // name -> names of its definition
  for (const auto& r : rows_)
    for (const auto& ch : r.tex.chains)
      if (ch.sides.size() >= 2 && !ch.continues && ch.sides[0].kind == NodeKind::Symbol)
        for (std::size_t i = 1; i < ch.sides.size(); ++i) symbol_names(ch.sides[i], defined[ch.sides[0].text]);
  for (auto& r : rows_) {
    if (!r.not_read.empty()) continue;
    for (const auto& ch : r.tex.chains)
      for (const auto& side : ch.sides)
        walk(side, [&](const Node& x) {
          if (!r.not_read.empty() || x.kind != NodeKind::Call || x.args.size() < 2) return;
          if (x.text != "integral") return;
          if (x.args[1].kind != NodeKind::Symbol) return;
          const std::string& var = x.args[1].text;
          std::set<std::string> inner;
          symbol_names(x.args[0], inner);
          for (const auto& n : inner) {
            auto it = defined.find(n);
            if (n != var && it != defined.end() && it->second.count(var)) {
              r.not_read = "'" + n + "' varies with " + var +
                           " through another row's equation; an integral of it is not read yet";
              r.not_read_pos = x.pos;
              return;
            }
          }
        });
  }
}

void DocumentReader::mark_functions_and_vectors() {
  mark_integrands_through_definitions();
  // A name differentiated on its own (dv/dt) is a function of that variable in its display.
  std::map<std::size_t, std::map<std::string, std::string>> functions;   // display -> name -> var
  std::set<std::string> plain;
  for (auto& r : rows_) {
    for (auto& ch : r.tex.chains)
      for (auto& side : ch.sides)
        walk(side, [&](const Node& x) {
          if (x.kind == NodeKind::Call && x.text == "diff" && x.args.size() >= 2 &&
              x.args[0].kind == NodeKind::Symbol && x.args[1].kind == NodeKind::Symbol)
            functions[r.display][x.args[0].text] = x.args[1].text;
        });
  }
  read_differentials(functions);
  // (known before the rows are read: `c(t_{1/2})` in one display is the c(t) of another)
  for (const auto& [k, names] : functions)
    for (const auto& [name, var] : names) function_vars_[function_id(name, var)] = var;
  for (auto& r : rows_) {
    for (auto& ch : r.tex.chains)
      for (auto& side : ch.sides)
        if (std::string why = read_values_at(side, functions[r.display]); !why.empty() && r.not_read.empty()) {
          r.not_read = why;
          r.not_read_pos = r.row->origin;
        }
    auto fit = functions.find(r.display);
    for (auto& ch : r.tex.chains)
      for (auto& side : ch.sides) {
        if (fit != functions.end()) to_functions(side, fit->second);
        symbol_names(side, plain);
      }
  }
  for (const auto& [k, names] : functions)
    for (const auto& [name, var] : names) function_vars_[function_id(name, var)] = var;
}

// `dv = -u_e\,dm_r/m_r - g\,dt` in a display whose other rows differentiate with respect to t:
// every term of each side holds exactly one differential, so the row divided by dt says
// dv/dt = -u_e (dm_r/dt)/m_r - g, and it is read as that (v, m_r functions of t there). A
// row whose terms do not each hold one differential, or a display without its variable, is
// not read.
void DocumentReader::read_differentials(std::map<std::size_t, std::map<std::string, std::string>>& functions) {
  // the degree in differentials of a side: 0 none, 1 one in every term, -1 anything else
  std::function<int(const Node&)> degree = [&](const Node& n) -> int {
    switch (n.kind) {
      case NodeKind::Call:
        if (n.text == "differential") return 1;
        for (const auto& a : n.args)
          if (degree(a) != 0) return -1;
        return 0;
      case NodeKind::Add:
      case NodeKind::Sub: {
        const int a = degree(n.args[0]), b = degree(n.args[1]);
        return a == b ? a : -1;
      }
      case NodeKind::Neg: return degree(n.args[0]);
      case NodeKind::Mul: {
        const int a = degree(n.args[0]), b = degree(n.args[1]);
        return a < 0 || b < 0 || a + b > 1 ? -1 : a + b;
      }
      case NodeKind::Div: {
        const int a = degree(n.args[0]), b = degree(n.args[1]);
        return a < 0 || b != 0 ? -1 : a;
      }
      case NodeKind::Pow: return degree(n.args[0]) == 0 && degree(n.args[1]) == 0 ? 0 : -1;
      default: {
        for (const auto& a : n.args)
          if (degree(a) != 0) return -1;
        return 0;
      }
    }
  };
  auto has_differential = [&](const Node& n) {
    bool found = false;
    walk(n, [&](const Node& x) { found = found || (x.kind == NodeKind::Call && x.text == "differential"); });
    return found;
  };
  for (auto& r : rows_) {
    if (!r.not_read.empty()) continue;
    bool any = false;
    for (const auto& ch : r.tex.chains)
      for (const auto& side : ch.sides) any = any || has_differential(side);
    if (!any) continue;
    const std::string not_read =
        "a differential (dv) outside a derivative or an integral is read only when every term of the row holds one "
        "and the display differentiates with respect to the variable (dv/dt)";
    std::set<std::string> vars;
    for (const auto& [name, var] : functions[r.display]) vars.insert(var);
    bool ok = vars.size() == 1;
    for (const auto& ch : r.tex.chains)
      for (const auto& side : ch.sides) ok = ok && (degree(side) == 1 || is_zero_literal(side));
    if (!ok) {
      r.not_read = not_read;
      r.not_read_pos = r.row->origin;
      continue;
    }
    const std::string var = *vars.begin();
    for (auto& ch : r.tex.chains)
      for (auto& side : ch.sides)
        walk(side, [&](Node& x) {
          if (x.kind != NodeKind::Call || x.text != "differential" || x.args.size() != 1) return;
          if (x.args[0].kind == NodeKind::Symbol && x.args[0].text == var) {
            x = Node{NodeKind::Number, "1", {}, x.pos};
            return;
          }
          if (x.args[0].kind == NodeKind::Symbol) functions[r.display][x.args[0].text] = var;
          Node v;
          v.kind = NodeKind::Symbol;
          v.text = var;
          v.pos = x.pos;
          x.text = "diff";
          x.args.push_back(v);
        });
  }
}

std::string DocumentReader::function_id(const std::string& name, const std::string& var) {
  return name + "__of_" + var;
}

// Every plain use of a function name becomes its application at the variable.
void DocumentReader::to_functions(Node& n, const std::map<std::string, std::string>& names) {
  walk(n, [&](Node& x) {
    if (x.kind != NodeKind::Symbol) return;
    auto it = names.find(x.text);
    if (it == names.end() || x.text == it->second) return;
    Node var;
    var.kind = NodeKind::Symbol;
    var.text = it->second;
    var.pos = x.pos;
    x.kind = NodeKind::Call;
    x.text = function_id(it->first, it->second);
    x.args = {var};
  });
}

void DocumentReader::build_steps() {
  auto& by_label = label_rows_;
  auto& by_tag = tag_rows_;
  struct Earlier {
    std::size_t section;
    std::string label;
    std::vector<std::string> conditions;
  };
  std::vector<Earlier> section_steps;   // in document order
  Node last_side;
  bool has_last_side = false;
  std::size_t last_display = static_cast<std::size_t>(-1);
  std::size_t last_section = static_cast<std::size_t>(-1);
  std::vector<std::string> conditions, own, fresh, where, earlier;
  std::vector<bool> pushed(inline_steps_.size(), false);
  for (auto& r : rows_) {
    const DocDisplay& disp = doc_.displays[r.display];
    const std::size_t section = static_cast<std::size_t>(disp.section);
    if (r.display != last_display) {
      // inline givens written before this display, and the "where" clause right after it
      // (pushed before its rows, which may use them)
      own.clear();
      where.clear();
      for (std::size_t i = 0; i < inline_steps_.size(); ++i) {
        const auto& is = inline_steps_[i];
        subject_of_[is.step.label] = is.subject;
        if (is.displays_before == r.display && is.section == section) own.push_back(is.step.label);
        if (is.displays_before == r.display + 1 && is.where) where.push_back(is.step.label);
      }
      for (std::size_t i = 0; i < inline_steps_.size(); ++i) {
        const auto& is = inline_steps_[i];
        if (!pushed[i] && (is.displays_before <= r.display || (is.displays_before == r.display + 1 && is.where))) {
          pushed[i] = true;
          d_.steps.push_back(is.step);
        }
      }
      fresh = own;
      conditions = conditions_for(r.display, own, conditions, section == last_section);
      earlier = stated_earlier(r.display, section, conditions);
      for (const auto& def : definitions_for(r.display, section))
        if (std::find(conditions.begin(), conditions.end(), def) == conditions.end() &&
            std::find(where.begin(), where.end(), def) == where.end()) {
          where.push_back(def);
          earlier.erase(std::remove(earlier.begin(), earlier.end(), def), earlier.end());
        }
      has_last_side = false;
    }
    const std::vector<std::string>& locals = conditions;
    last_display = r.display;
    last_section = section;
    const std::string base = "L" + std::to_string(r.row->origin.line);
    if (!r.not_read.empty()) {
      has_last_side = false;
      Step s = unread_step(base, r, r.not_read);
      d_.steps.push_back(std::move(s));
      continue;
    }
    // cited rows: \eqref in the row, and tags / \eqref in the prose before the display
    std::vector<std::string> cited;
    for (const auto& ref : r.tex.refs) add_all(cited, by_label[ref]);
    for (const auto& tag : tags_in(disp.prose_before)) add_all(cited, by_tag[tag]);
    for (const auto& label : refs_in(disp.prose_before)) add_all(cited, by_label[label]);
    std::vector<Link> links;
    int link_no = 0;
    std::size_t total = 0;
    for (const auto& ch : r.tex.chains) total += ch.rels.size();
    std::string problem;
    for (std::size_t c = 0; c < r.tex.chains.size(); ++c) {
      const TexChain& ch = r.tex.chains[c];
      std::vector<Node> sides = ch.sides;
      if (ch.continues) {
        if (!has_last_side) {
          problem = "the row begins with a relation but no row before it in this display gives its left side";
          break;
        }
        sides[0] = last_side;
      }
      for (std::size_t i = 0; i + 1 < sides.size(); ++i) {
        Link l{sides[i], sides[i + 1], relation_word(ch.rels[i]), total > 1 ? ++link_no : 0};
        l.chain = c;
        l.after_gives = ch.follows_previous;
        links.push_back(std::move(l));
      }
      if (!sides.empty()) {
        // `A &= B = 0 \\ &= C = 0`: the next row continues the quantity, not the 0 it was
        // said to equal (B = C, not 0 = C)
        last_side = sides.size() >= 3 && is_zero_literal(sides.back()) ? sides[sides.size() - 2] : sides.back();
        has_last_side = true;
      }
    }
    if (!problem.empty()) {
      d_.steps.push_back(unread_step(base, r, problem));
      continue;
    }
    // vectors: each link linear in them, or the row is not read
    // (each link for itself: `T = \frac12 m v^2 = \frac12 v |\mathbf{p}|` reads its first link)
    auto vector_problem = [&](const Link& l) -> std::string {
      if (r.vectors.empty()) return "";
      const int a = vector_degree(l.lhs, r.vectors), b = vector_degree(l.rhs, r.vectors);
      // (a vector beside a scalar expression, `\sum \mathbf{F} = m\dot v + \dot m u`, is the
      // author's component along the motion: read as that scalar relation)
      const bool ok = a >= 0 && b >= 0;
      return ok ? "" : "a vector relation that is not linear in the vectors (a product of vectors, |v|, a "
                       "vector added to a scalar) is not read yet";
    };
    std::vector<std::string> this_row;
    std::map<std::size_t, std::vector<std::string>> chain_labels;
    for (auto& l : links) {
      Step s;
      s.label = l.link == 0 ? base : base + "." + std::to_string(l.link);
      if (d_.find(s.label)) s.label += "_" + std::to_string(r.row->origin.col);
      s.tag = r.tex.tag;
      s.claim.sides = {l.lhs, l.rhs};
      s.claim_text = to_text(s.claim);
      s.pos = r.row->origin;
      s.claim_pos = l.lhs.pos.line > 0 ? l.lhs.pos : r.row->origin;
      s.rule.name = s.rule.written_name = "given";
      DocumentRow dr;
      dr.link = l.link;
      dr.display = static_cast<int>(r.display);
      dr.relation = l.relation;
      dr.locals = locals;
      dr.fresh = fresh;
      dr.earlier = earlier;
      dr.where = where;
      dr.cited = cited;
      // a chain after "=>" follows from the chain before it
      if (l.after_gives && l.chain > 0) add_all(dr.cited, chain_labels[l.chain - 1]);
      // the links before it in the same row come first: a chain continues them
      for (auto it = this_row.rbegin(); it != this_row.rend(); ++it) dr.nearby.push_back(*it);
      // earlier rows of the section whose conditions are in force here too
      // (a definition of the text still in force counts as one of the conditions here)
      std::vector<std::string> in_force = locals;
      add_all(in_force, where);
      for (auto it = section_steps.rbegin(); it != section_steps.rend() && dr.nearby.size() < kNearby; ++it)
        if (it->section == section && subset(it->conditions, in_force))
          dr.nearby.push_back(it->label);
      // the text on both sides: "… where the higher-order term was neglected" follows the display
      // (the sentences that lead into the display, and the one that continues it)
      // (a display that follows another with no prose between continues the same sentence:
      // "Differentiating (2.3), …" leads into both)
      std::size_t lead = r.display;
      while (lead > 0 && doc_.displays[lead].prose_before.find_first_not_of(" \t\n") == std::string::npos) --lead;
      dr.hint = hint_of(doc_.displays[lead].prose_before);
      {
        const std::size_t after_end = r.display + 1 < doc_.displays.size()
                                          ? offset_of(doc_.displays[r.display + 1].pos)
                                          : doc_.source.text.size();
        if (after_end > disp.end)
          dr.hint += " " + continuation_of(doc_.source.text.substr(disp.end, after_end - disp.end));
      }
      dr.not_read = vector_problem(l);
      for (const auto& v : r.vectors) dr.vectors.push_back(v);
      for (const auto& rd : r.tex.readings) s.notes.push_back(rd.message);
      s.document_row = std::move(dr);
      this_row.push_back(s.label);
      chain_labels[l.chain].push_back(s.label);
      // a tag or label names the rows of the latest display that carries it (a long document
      // may number its equations again in a later part)
      auto own = [&](std::vector<std::string>& labels) {
        if (!labels.empty()) {
          const Step* last = d_.find(labels.back());
          if (last && last->document_row && last->document_row->display != static_cast<int>(r.display)) labels.clear();
        }
        labels.push_back(s.label);
      };
      if (!r.tex.label.empty()) own(by_label[r.tex.label]);
      if (!r.tex.tag.empty()) own(by_tag[r.tex.tag]);
      d_.steps.push_back(std::move(s));
    }
    for (const auto& l : this_row) section_steps.push_back({section, l, locals});
  }
  for (std::size_t i = 0; i < inline_steps_.size(); ++i)
    if (!pushed[i]) d_.steps.push_back(inline_steps_[i].step);
}

Step DocumentReader::unread_step(const std::string& label, const ReadRow& r, const std::string& why) {
  Step s;
  s.label = d_.find(label) ? label + "_" + std::to_string(r.row->origin.col) : label;
  Node zero;
  zero.kind = NodeKind::Number;
  zero.text = "0";
  zero.pos = r.row->origin;
  s.claim.sides = {zero, zero};
  std::string text = r.row->text;
  for (char& c : text)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  if (text.size() > 120) text = text.substr(0, 117) + "...";
  s.claim_text = text;
  s.pos = s.claim_pos = r.row->origin;
  s.tag = r.tex.tag;
  s.rule.name = s.rule.written_name = "given";
  DocumentRow dr;
  dr.not_read = why;
  if (!r.tex.chains.empty() && !r.tex.chains[0].sides.empty() && r.tex.chains[0].sides[0].kind == NodeKind::Symbol)
    dr.unread_sets = r.tex.chains[0].sides[0].text;
  s.document_row = dr;
  return s;
}

// Every element of a is in b.
bool DocumentReader::subset(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  for (const auto& x : a)
    if (std::find(b.begin(), b.end(), x) == b.end()) return false;
  return true;
}

// u \cdot w and u \times w between two declared vectors: dot(u, w), cross(u, w) (the product
// binds its neighbouring factors: m u \cdot w is m (u . w)).
void DocumentReader::vector_products(Node& n) const {
  for (auto& a : n.args) vector_products(a);
  if (n.kind != NodeKind::Mul) return;
  const bool cross = n.text == "times";
  Node& left = n.args[0].kind == NodeKind::Mul && !n.args[0].parenthesized ? n.args[0].args[1] : n.args[0];
  int a = 0, b = 0;
  try {
    a = vector_shape(left, d_.symbols);
    b = vector_shape(n.args[1], d_.symbols);
  } catch (const InputError&) {
    return;   // reported when the row is checked
  }
  if (!a || !b) return;
  Node product;
  product.kind = NodeKind::Call;
  product.text = cross ? "cross" : "dot";
  product.pos = left.pos;
  product.args = {left, n.args[1]};
  if (&left == &n.args[0]) {
    product.parenthesized = n.parenthesized;
    n = std::move(product);
  } else {
    n.args[0].args[1] = std::move(product);
    Node outer = std::move(n.args[0]);
    outer.parenthesized = n.parenthesized;
    n = std::move(outer);
  }
}

void DocumentReader::rename_vectors(Node& n, const std::set<std::string>& vectors) {
  walk(n, [&](Node& x) {
    if (x.kind == NodeKind::Symbol && vectors.count(x.text)) x.text += "_vec";
  });
}

void DocumentReader::add_all(std::vector<std::string>& out, const std::vector<std::string>& more) {
  for (const auto& m : more)
    if (std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
}

// Every name the steps use, declared real (unless a directive declared it); the functions
// found in parse_rows with their variable.
void DocumentReader::declare_symbols() {
  std::set<std::string> names;
  std::set<std::string> calls;
  for (const auto& s : d_.steps)
    for (const auto& side : s.claim.sides) {
      symbol_names(side, names);
      walk(side, [&](const Node& x) {
        if (x.kind == NodeKind::Call && function_vars_.count(x.text)) calls.insert(x.text);
      });
    }
  for (const auto& [f, var] : function_vars_) names.insert(var);
  for (const DocDirective* dir : assumes_) {
    try {
      TexRow row = parse_tex_row(std::string_view(dir->text).substr(6), dir->origin, ctx_);
      for (const auto& ch : row.chains)
        for (const auto& side : ch.sides) symbol_names(side, names);
    } catch (const InputError&) {
      // reported by assumptions()
    }
  }
  const Domain real = parse_domain("real", {d_.source.name, 1, 1});
  for (const auto& n : names) {
    if (d_.symbols.find(n)) continue;
    SymbolInfo info;
    info.name = n;
    info.domain = real;
    info.pos = {d_.source.name, 0, 0};
    d_.symbols.declare(std::move(info));
  }
  for (const auto& f : calls) {
    if (d_.symbols.find(f)) continue;
    SymbolInfo info;
    info.name = f;
    info.tex = f.substr(0, f.find("__of_"));
    info.domain = real;
    info.is_function = true;
    info.params = {function_vars_[f]};
    info.pos = {d_.source.name, 0, 0};
    d_.symbols.declare(std::move(info));
  }
}

}  // namespace document_detail

using document_detail::DocumentReader;

Derivation read_document(SourceText source) { return DocumentReader(std::move(source)).run(); }

Derivation load_any(const std::string& path) {
  if (!is_document_path(path)) return load_derivation(path);
  return read_document(SourceText{path, read_file(path)});
}

}  // namespace dc

