// Reader for the derivation file format (.dc), docs/format.md.
//
// The reader is line oriented: comments are blanked (positions survive), a statement is a
// line at column 1 plus the indented lines that follow it. Every expression is parsed by
// dc::parse_relation / parse_expression with its exact origin, so errors point at the
// offending character, GCC style.
//
// The class DcReader (internal/dc_reader.hpp) does the reading. This file holds run(), the
// lines, statements and step headers, the lexical helpers on spans and the validation of
// expressions; dc_declarations.cpp the symbol, function and assume statements and the names
// that steps define; dc_steps.cpp the steps and their `by` lines. Then the definitions in
// force (resolve_definitions) and the public functions of derivation.hpp.
#include "derivations/reader/derivation.hpp"
#include "derivations/calculus/install.hpp"

#include <algorithm>
#include <functional>

#include "derivations/reader/internal/dc_reader.hpp"
#include "derivations/reader/figures.hpp"
#include "derivations/symbolic/differential.hpp"
#include "derivations/symbolic/printer.hpp"
#include "derivations/symbolic/vectors.hpp"
#include "derivations/syntax/figure.hpp"
#include "derivations/syntax/io.hpp"
#include "derivations/syntax/prose.hpp"

namespace dc {

namespace reader_detail {

Derivation DcReader::run() {
  split_lines();
  collect_labels();
  for (const auto& st : statements_) statement(st);
  check_assumptions();
  if (vector_arrows_)   // `notation arrows`: \vec{v} for every vector without a tex of its own
    for (const auto& name : default_vector_tex_)
      d_.symbols.set_tex(name, vector_tex("\\vec", name));
  if (d_.steps.empty()) {
    // A file without steps checks nothing; passing it as "0 steps" would hide a wrong file
    // (an empty one, a truncated one, a file of another format).
    std::string what = d_.source.text.empty() ? "the file is empty"
                       : statements_.empty() ? "the file has only comments and blank lines"
                                             : "the file declares symbols but has no step";
    fail({file(), 0, 0}, "no steps (" + what + "); a derivation needs at least one step '[(TAG)] LABEL: CLAIM' "
                         "with an indented 'by RULE' line");
  }
  return std::move(d_);
}

// --- lines and statements ----------------------------------------------------------------

void DcReader::split_lines() {
  const std::string& t = d_.source.text;
  std::size_t start = 0;
  int line_no = 0;
  while (start <= t.size()) {
    std::size_t nl = t.find('\n', start);
    std::string line = t.substr(start, nl == std::string::npos ? std::string::npos : nl - start);
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // blank the comment (outside string literals)
    bool in_str = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      char c = line[i];
      if (in_str) {
        if (c == '\\' && i + 1 < line.size()) ++i;
        else if (c == '"') in_str = false;
      } else if (c == '"') {
        in_str = true;
      } else if (c == '\\' && i + 1 < line.size() && line[i + 1] == '#') {
        ++i;   // \# is a literal '#' (in text); not a comment
      } else if (c == '#') {
        for (std::size_t j = i; j < line.size(); ++j) line[j] = ' ';
        break;
      }
    }
    lines_.push_back(line);
    if (nl == std::string::npos) break;
    start = nl + 1;
  }
  Statement* cur = nullptr;
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    const std::string& l = lines_[i];
    if (l.find_first_not_of(" \t\r") == std::string::npos) continue;
    int ln = static_cast<int>(i) + 1;
    if (is_space(l[0])) {
      if (!cur) {
        std::size_t c = l.find_first_not_of(" \t");
        fail({file(), ln, static_cast<int>(c) + 1},
             "unexpected indented line: indentation continues the statement above, and there is none");
      }
      cur->lines.push_back({ln, l});
    } else {
      statements_.push_back(Statement{ln, {{ln, l}}});
      cur = &statements_.back();
    }
  }
}

// First word of a line (starting at `from`) and its end.
std::string DcReader::word_at(const std::string& l, std::size_t from, std::size_t* end) {
  std::size_t i = from;
  while (i < l.size() && is_ident_char(l[i])) ++i;
  if (end) *end = i;
  return l.substr(from, i - from);
}

bool DcReader::parse_header(const std::string& l, int ln, DcReader::Header& h, bool throw_on_error) {
  std::size_t i = 0;
  if (l[0] == '(') {
    std::size_t close = l.find(')');
    if (close == std::string::npos) {
      if (throw_on_error) fail({file(), ln, 1}, "expected ')' to close the equation tag '(' (e.g. '(9.6) label: claim')");
      return false;
    }
    h.tag = l.substr(1, close - 1);
    std::size_t a = 0, b = h.tag.size();
    trim_range(h.tag, a, b);
    h.tag = h.tag.substr(a, b - a);
    if (h.tag.empty()) {
      if (throw_on_error) fail({file(), ln, 2}, "expected an equation tag inside '( )', e.g. '(9.6)'");
      return false;
    }
    i = close + 1;
    while (i < l.size() && is_space(l[i])) ++i;
  }
  if (i >= l.size() || !is_ident_start(l[i])) {
    if (throw_on_error) fail({file(), ln, static_cast<int>(i) + 1}, "expected a step label after the equation tag");
    return false;
  }
  std::size_t e;
  h.label = word_at(l, i, &e);
  h.label_pos = {file(), ln, static_cast<int>(i) + 1};
  std::size_t j = e;
  while (j < l.size() && is_space(l[j])) ++j;
  if (j >= l.size() || l[j] != ':') {
    if (throw_on_error)
      fail({file(), ln, static_cast<int>(j) + 1},
           "expected ':' after the step label '" + h.label + "' (a step is '[(TAG)] LABEL: CLAIM')");
    return false;
  }
  h.claim_from = j + 1;
  return true;
}

void DcReader::collect_labels() {
  for (const auto& st : statements_) {
    const std::string& l = st.lines[0].second;
    std::string w = word_at(l, 0);
    if (contains(kStatementKeywords, w) && (l.size() == w.size() || !is_ident_char(l[w.size()]))) {
      std::size_t k = w.size();
      while (k < l.size() && is_space(l[k])) ++k;
      if (k >= l.size() || l[k] != ':') continue;  // a keyword statement, not a label
    }
    Header h;
    if (!parse_header(l, st.first_line, h, false)) continue;
    if (!all_labels_.count(h.label)) all_labels_[h.label] = h.label_pos;
  }
}

void DcReader::statement(const Statement& st) {
  const std::string& l = st.lines[0].second;
  std::size_t e;
  std::string w = word_at(l, 0, &e);
  bool keyword_statement = contains(kStatementKeywords, w);
  if (keyword_statement) {
    std::size_t k = e;
    while (k < l.size() && is_space(l[k])) ++k;
    if (k < l.size() && l[k] == ':') keyword_statement = false;  // e.g. a label named 'section'
  }
  if (keyword_statement) {
    Span s;
    for (std::size_t i = 0; i < st.lines.size(); ++i)
      s.append_line(file(), st.lines[i].first, st.lines[i].second, i == 0 ? e : 0);
    if (w == "title" || w == "section" || w == "handout") {
      std::size_t p = 0;
      std::string str = string_literal(s, p, "a quoted " + w + ", e.g. " + w + " \"...\"");
      expect_end(s, p);
      if (w == "handout") {
        if (str.find_first_not_of(' ') == std::string::npos) fail(s.at(0), "empty handout title: write it between the quotes");
        d_.handout = str;
        return;
      }
      (w == "title" ? d_.title : d_.section) = str;
    } else if (w == "notation") {
      // notation dot | leibniz: how the LaTeX writes derivatives of declared functions;
      // notation arrows | bold: how it writes vectors
      std::size_t p = 0;
      skip_ws(s, p);
      SourcePos at = s.at(p);
      std::string v = identifier(s, p, "'dot', 'leibniz', 'arrows' or 'bold' after notation");
      if (v != "dot" && v != "leibniz" && v != "arrows" && v != "bold")
        fail(at, "unknown notation '" + v + "'; expected 'dot' (\\dot{x}), 'leibniz' (dx/dt), 'arrows' (\\vec{v}) or 'bold' (\\mathbf{v})",
             static_cast<int>(v.size()));
      expect_end(s, p);
      if (v == "arrows" || v == "bold") {
        vector_arrows_ = v == "arrows";
        return;
      }
      d_.dot_derivatives = v == "dot";
    } else if (w == "heading" || w == "figure" || w == "text" || w == "remark") {
      prose_statement(w, s, {file(), st.first_line, 1});
    } else if (w == "symbol") {
      symbol_statement(s, false);
    } else if (w == "function") {
      symbol_statement(s, true);
    } else if (w == "vector") {
      vector_statement(s);
    } else {
      assume_statement(s, {file(), st.first_line, 1});
    }
    return;
  }
  Header h;
  if (!parse_header(l, st.first_line, h, false)) {
    // A line starting with '(' is a tagged step: report what is wrong with its header.
    if (l[0] == '(') parse_header(l, st.first_line, h, true);
    std::string shown = w.empty() ? l.substr(0, utf8_length(l, 0)) : w;
    fail({file(), st.first_line, 1},
         "unknown statement '" + shown + "'; expected one of title, handout, section, symbol, function, vector, assume, "
         "heading, text, remark, figure, notation, or a step '[(TAG)] LABEL: CLAIM'",
         static_cast<int>(std::max<std::size_t>(1, shown.size())));
  }
  step_statement(st, h);
}

// heading "..." / figure "..." / text PARAGRAPH / remark PARAGRAPH (docs/format.md, "Text").
void DcReader::prose_statement(const std::string& w, const Span& s, const SourcePos& pos) {
  Prose pr;
  pr.pos = pos;
  pr.before_step = d_.steps.size();
  if (w == "heading" || w == "figure") {
    pr.kind = w == "heading" ? Prose::Kind::Heading : Prose::Kind::Figure;
    std::size_t p = 0;
    std::string str = string_literal(s, p, "a quoted " + std::string(w == "heading" ? "heading" : "caption") +
                                               ", e.g. " + w + " \"...\"");
    if (w == "heading") {
      expect_end(s, p);
    } else {
      // what draws the figure: `simulate SCENE ...` or `plot LABEL ... over X = LO .. HI ...`
      Span rest = s.sub(p, s.text.size());
      FigureSpec spec = parse_figure_spec({rest.text, rest.pos, rest.end},
                                          [&](const SourcePos& q, const std::string& msg, int len) { fail(q, msg, len); });
      for (const auto& c : spec.curves)   // a step later in the file may be drawn earlier
        if (!all_labels_.count(c.name))
          fail(c.pos, "no step labelled '" + c.name + "' in this file to plot", static_cast<int>(c.name.size()));
      if (spec.kind != FigureSpec::Kind::Placeholder) figures_[d_.prose.size()] = std::move(spec);
    }
    if (str.find_first_not_of(' ') == std::string::npos) fail(s.at(0), "empty " + w + ": write its text between the quotes");
    if (pr.kind == Prose::Kind::Figure) {
      // a caption takes the markup of text ($r^2$, `m*g`, *words*); positions from the opening quote
      SourcePos open = s.at(nonspace(s, 0));
      std::vector<SourcePos> cpos;
      for (std::size_t i = 0; i < str.size(); ++i) cpos.push_back({open.file, open.line, open.col + 1 + static_cast<int>(i)});
      SourcePos end{open.file, open.line, open.col + 1 + static_cast<int>(str.size())};
      pr.pieces = parse_prose({str, cpos, end}, [&](const Node& n) { validate_side(n); },
                              [&](const SourcePos& q, const std::string& msg, int len) { fail(q, msg, len); });
    } else {
      pr.pieces.push_back({ProsePiece::Kind::Text, str, {}});
    }
  } else {
    pr.kind = w == "text" ? Prose::Kind::Paragraph : Prose::Kind::Remark;
    std::size_t b = 0, e = s.text.size();
    trim_range(s.text, b, e);
    if (b >= e)
      fail(pos, "empty " + w + ": write the paragraph after '" + w + "' or on the indented lines below it",
           static_cast<int>(w.size()));
    Span body = s.sub(b, e);
    pr.pieces = parse_prose({body.text, body.pos, body.end}, [&](const Node& n) { validate_side(n); },
                            [&](const SourcePos& p, const std::string& msg, int len) { fail(p, msg, len); });
  }
  d_.prose.push_back(std::move(pr));
}

// --- small lexical helpers on spans ------------------------------------------------------

std::size_t DcReader::nonspace(const Span& s, std::size_t p) {
  skip_ws(s, p);
  return p;
}

void DcReader::skip_ws(const Span& s, std::size_t& p) {
  while (p < s.text.size() && (is_space(s.text[p]) || s.text[p] == '\n')) ++p;
}

std::string DcReader::string_literal(const Span& s, std::size_t& p, const std::string& expected) {
  skip_ws(s, p);
  if (p >= s.text.size() || s.text[p] != '"') fail(s.at(p), "expected " + expected);
  SourcePos open = s.at(p);
  std::string out;
  ++p;
  while (p < s.text.size() && s.text[p] != '"') {
    if (s.text[p] == '\n') fail(open, "unterminated string: expected '\"' before the end of the line");
    if (s.text[p] == '\\' && p + 1 < s.text.size() && (s.text[p + 1] == '"' || s.text[p + 1] == '\\')) ++p;
    out += s.text[p++];
  }
  if (p >= s.text.size()) fail(open, "unterminated string: expected '\"' before the end of the line");
  ++p;
  return out;
}

void DcReader::expect_end(const Span& s, std::size_t p) {
  skip_ws(s, p);
  if (p < s.text.size()) fail(s.at(p), "unexpected text '" + excerpt(s, p) + "'; expected the end of the statement");
}

std::string DcReader::excerpt(const Span& s, std::size_t p) {
  std::size_t e = s.text.find('\n', p);
  std::string t = s.text.substr(p, e == std::string::npos ? std::string::npos : e - p);
  while (!t.empty() && is_space(t.back())) t.pop_back();
  if (t.size() > 30) {
    std::size_t cut = 0;
    while (cut < t.size() && cut + utf8_length(t, cut) <= 30) cut += utf8_length(t, cut);
    t = t.substr(0, cut) + "...";
  }
  return t;
}

std::string DcReader::identifier(const Span& s, std::size_t& p, const std::string& expected) {
  skip_ws(s, p);
  if (p >= s.text.size() || !is_ident_start(s.text[p]))
    fail(s.at(p), "expected " + expected + (p < s.text.size() ? ", found '" + excerpt(s, p) + "'" : ""));
  std::size_t b = p;
  while (p < s.text.size() && is_ident_char(s.text[p])) ++p;
  return s.text.substr(b, p - b);
}

Node DcReader::expression(const Span& s, std::size_t b, std::size_t e, const std::string& what) {
  trim_range(s.text, b, e);
  if (b >= e) fail(s.at(b), "expected " + what);
  return parse_expression(std::string_view(s.text).substr(b, e - b), s.at(b));
}

Relation DcReader::relation(const Span& s, std::size_t b, std::size_t e, const std::string& what) {
  trim_range(s.text, b, e);
  if (b >= e) fail(s.at(b), "expected " + what);
  return parse_relation(std::string_view(s.text).substr(b, e - b), s.at(b));
}

// Convert with the table, for validation (undefined symbols, exponent limits, ...).
// Undeclared symbols, bad calls and other input errors throw here. A limit(...) that the
// limit engine cannot decide is not an input error: the step that uses it is undecided when
// it is checked, and the rest of the file is read.
void DcReader::validate(const Node& n) {
  declare_differentials(n, d_.symbols);
  if (const int k = vector_shape(n, d_.symbols)) {   // a vector: each component (vectors.hpp)
    for (int i = 1; i <= k; ++i) validate(vector_component(n, d_.symbols, i));
    return;
  }
  if (has_plus_minus(n) && plus_minus_sign() == 0) {   // both values of a ±
    for (int sign : {1, -1}) {
      PlusMinusSign chosen(sign);
      validate(n);
    }
    return;
  }
  try {
    (void)to_ginac(n, d_.symbols);
  } catch (const UndecidedLimit&) {
  } catch (const InputError&) {
    // Before definitions are put in, diff(p, v) of a defined p is 0 and a division by it an
    // error: judge the expression as the rules will see it, with the definitions in force.
    const Node r = resolve_definitions(d_, n);
    if (to_text(r) == to_text(n)) throw;
    try {
      (void)to_ginac(r, d_.symbols);
    } catch (const UndecidedLimit&) {
    }
  }
}

// The GiNaC form, where a declaration needs it (an assumption's sides): an undecided limit
// there is an input error at the expression.
GiNaC::ex DcReader::converted(const Node& n) {
  try {
    return to_ginac(n, d_.symbols);
  } catch (const UndecidedLimit& e) {
    throw InputError(n.pos, std::string("this expression cannot be used in a declaration: ") + e.what(), n.length);
  }
}

}  // namespace reader_detail

// --- definitions in force, public functions ----------------------------------------------

namespace {

// Definitions by step: name -> (params, body).
struct Definition {
  std::vector<std::string> params;
  const Node* body;
  const Node* at_point = nullptr;   // the body for arguments other than the parameters, if different
};

}  // namespace

bool introduces_name(const Step& s) {
  return (s.rule.name == "definition" || s.names_result) && s.claim.sides.size() >= 2 &&
         (s.claim.sides[0].kind == NodeKind::Call || s.claim.sides[0].kind == NodeKind::Symbol);
}

namespace {

Definition definition_of(const Derivation& d, const Step& s) {
  // A named result `V(t) = E1 = E2` (and a definition written as a chain) names E1: a wrong E2
  // is then reported at its own link. When E1 holds an integral, later steps use the last side:
  // `W = integral(F, x, 0, L) = F0*L/2  by integrate` established that closed form, which the
  // integral inside an expression may have no method to evaluate again.
  // (also a limit: `v_T = limit(v(t), t, oo) = m*g/b  by limit t -> oo of solution`)
  std::function<bool(const Node&)> has_integral = [&](const Node& n) {
    if (n.kind == NodeKind::Call && (n.text == "integral" || n.text == "limit")) return true;
    for (const auto& a : n.args)
      if (has_integral(a)) return true;
    return false;
  };
  // Likewise `v(t) = diff(x(t), t) = v0 - g*t`: v(0) cannot be diff(x(0), 0).
  std::vector<std::string> params;
  if (s.claim.sides[0].kind == NodeKind::Call)
    for (const auto& a : s.claim.sides[0].args) params.push_back(a.text);
  std::function<bool(const Node&)> diff_in_param = [&](const Node& n) {
    if (n.kind == NodeKind::Call && n.text == "diff" && n.args.size() >= 2 && n.args[1].kind == NodeKind::Symbol &&
        std::find(params.begin(), params.end(), n.args[1].text) != params.end())
      return true;
    for (const auto& a : n.args)
      if (diff_in_param(a)) return true;
    return false;
  };
  // And `R = x(T) = v0^2*sin(2*theta)/g`: x(T), a declared function at a point, is one value
  // independent of theta to the algebra; the closed form keeps what the step established.
  std::function<bool(const Node&)> at_a_point = [&](const Node& n) {
    if (n.kind == NodeKind::Call && !is_builtin_function(n.text)) {
      const SymbolInfo* f = d.symbols.find(n.text);
      if (f && f->is_function) {
        if (n.args.size() != f->params.size()) return true;
        for (std::size_t i = 0; i < n.args.size(); ++i)
          if (n.args[i].kind != NodeKind::Symbol || n.args[i].text != f->params[i]) return true;
      }
    }
    for (const auto& a : n.args)
      if (at_a_point(a)) return true;
    return false;
  };
  const bool chain = s.claim.sides.size() >= 3;
  const bool use_last = chain && (has_integral(s.claim.sides[1]) || at_a_point(s.claim.sides[1]));
  Definition def{params, use_last ? &s.claim.sides.back() : &s.claim.sides[1], nullptr};
  // at a point (v(0)) a body that differentiates in the parameter is replaced by the last side
  if (chain && diff_in_param(*def.body)) def.at_point = &s.claim.sides.back();
  return def;
}

// The definitions in force: name -> parameters and body (a later definition of the same name
// wins, as before).
class Definitions {
 public:
  explicit Definitions(const Derivation& d) : d_(d) {
    if (!d.indexed)
      for (const auto& s : d.steps)
        if (introduces_name(s)) local_[s.claim.sides[0].text] = definition_of(d, s);
  }
  bool empty() const { return d_.indexed ? d_.definition_index.empty() : local_.empty(); }
  std::optional<Definition> find(const std::string& name) const {
    if (d_.indexed) {
      auto it = d_.definition_index.find(name);
      if (it == d_.definition_index.end()) return std::nullopt;
      return definition_of(d_, d_.steps[it->second]);
    }
    auto it = local_.find(name);
    if (it == local_.end()) return std::nullopt;
    return it->second;
  }

 private:
  const Derivation& d_;
  std::map<std::string, Definition> local_;
};

Node substitute_params(const Node& n, const std::map<std::string, const Node*>& args) {
  if (n.kind == NodeKind::Symbol) {
    auto it = args.find(n.text);
    if (it != args.end()) {
      Node r = *it->second;
      r.parenthesized = true;
      return r;
    }
    return n;
  }
  Node out = n;
  for (auto& a : out.args) a = substitute_params(a, args);
  return out;
}

// `in_integral`: inside the integrand of an integral, where the functions are applied at the
// variable of integration (a point of (a, b), not the declared parameter): a named derivative
// there uses its closed form, as at any point.
Node resolve(const Node& n, const Definitions& defs, int depth, bool in_integral = false) {
  if (depth > 64) throw InputError(n.pos, "definitions nested too deeply (more than 64 levels)", n.length);
  if (n.kind == NodeKind::Symbol) {
    auto def = defs.find(n.text);
    if (def && def->params.empty()) {
      Node r = resolve(*def->body, defs, depth + 1, in_integral);
      r.parenthesized = true;
      r.pos = n.pos;
      return r;
    }
    return n;
  }
  Node out = n;
  const bool integral = n.kind == NodeKind::Call && n.text == "integral";
  for (std::size_t i = 0; i < out.args.size(); ++i)
    out.args[i] = resolve(out.args[i], defs, depth, in_integral || (integral && i == 0));
  if (n.kind == NodeKind::Call) {
    auto def = defs.find(n.text);
    if (def && !def->params.empty() && def->params.size() == out.args.size()) {
      std::map<std::string, const Node*> args;
      bool at_params = true;
      for (std::size_t i = 0; i < out.args.size(); ++i) {
        args[def->params[i]] = &out.args[i];
        at_params = at_params && out.args[i].kind == NodeKind::Symbol && out.args[i].text == def->params[i];
      }
      const Node& body = (!at_params || in_integral) && def->at_point ? *def->at_point : *def->body;
      Node r = resolve(substitute_params(body, args), defs, depth + 1, in_integral);
      r.parenthesized = true;
      r.pos = n.pos;
      return r;
    }
  }
  return out;
}

}  // namespace

const Step* Derivation::find(const std::string& label) const {
  if (indexed) {
    auto it = label_index.find(label);
    return it == label_index.end() ? nullptr : &steps[it->second];
  }
  for (const auto& s : steps)
    if (s.label == label) return &s;
  return nullptr;
}

void Derivation::index() {
  label_index.clear();
  definition_index.clear();
  for (std::size_t i = 0; i < steps.size(); ++i) {
    label_index.emplace(steps[i].label, i);   // the first step of a label, as the scan finds it
    if (introduces_name(steps[i])) definition_index[steps[i].claim.sides[0].text] = i;
  }
  indexed = true;
}

Derivation parse_derivation(SourceText source) {
  calculus::install();
  source.text = normalize_text(std::move(source.text));
  SourceText copy = source;
  try {
    Derivation d = reader_detail::DcReader(std::move(source)).run();
    d.index();
    return d;
  } catch (const InputError& e) {
    if (!e.line_text().empty() || e.pos().line < 1) throw;
    throw e.with_line_text(copy.line(e.pos().line));
  }
}

RuleSpec read_rule_line(const Derivation& d, std::size_t index, const std::string& text, const SourcePos& pos) {
  return reader_detail::DcReader::rule_of(d, index, text, pos);
}

std::string rule_line_text(const RuleSpec& r) {
  auto arg = [](const RuleArg& a) -> std::string {
    switch (a.kind) {
      case RuleArg::Kind::Label:
      case RuleArg::Kind::Symbol: return a.label;
      case RuleArg::Kind::Equation: return to_text(a.equation);
      case RuleArg::Kind::Value: return to_text(a.value);
    }
    return a.label;
  };
  auto list = [&](const std::vector<RuleArg>& v) {
    std::string out;
    for (const auto& a : v) out += (out.empty() ? "" : ", ") + arg(a);
    return out;
  };
  const std::string& n = r.name;
  std::string out = "by " + (r.written_name.empty() ? n : r.written_name);
  if (n == "limit" || n == "series") {
    if (r.var) out += " " + arg(*r.var);
    if (r.point) out += " -> " + arg(*r.point) + (r.dir > 0 ? "+" : r.dir < 0 ? "-" : "");
    if (!r.into.empty()) out += " of " + list(r.into);
    if (r.order && n == "series") out += " to order " + std::to_string(*r.order);
  } else if (n == "first_order") {
    out += " " + list(r.smalls) + " of " + list(r.into);
  } else if (n == "stationary" || n == "maximum" || n == "minimum" || n == "instance") {
    if (!r.into.empty()) out += " of " + list(r.into);
    if (r.var) out += " wrt " + arg(*r.var);
  } else {
    if (!r.refs.empty()) out += " " + list(r.refs);
    if (!r.into.empty()) out += " into " + list(r.into);
    if (!r.unknowns.empty()) out += " for " + list(r.unknowns);
    if (r.var) out += " wrt " + arg(*r.var);
    if (r.point) out += " from " + arg(*r.point);
  }
  if (!r.with.empty()) out += " with " + list(r.with);
  return out;
}

bool is_rule_name(const std::string& name) {
  return reader_detail::contains(reader_detail::kRuleNames, name) ||
         reader_detail::contains(reader_detail::kRewriteAliases, name);
}

Derivation load_derivation(const std::string& path) {
  SourceText src;
  src.name = path;
  src.text = read_file(path);
  return parse_derivation(std::move(src));
}

Node substitute_names(const Node& n, const std::map<std::string, const Node*>& values) {
  return substitute_params(n, values);
}

Node resolve_definitions(const Derivation& d, const Node& n) {
  Definitions defs(d);
  if (defs.empty()) return n;
  return resolve(n, defs, 0);
}

GiNaC::ex resolved_ginac(const Derivation& d, const Node& n) {
  return to_ginac(resolve_definitions(d, n), d.symbols);
}

std::optional<InputError> erratum_error(const Derivation& d, const Step& s) {
  if (!s.erratum) return std::nullopt;
  try {
    for (const auto& side : s.claim.sides) to_ginac(side, d.symbols);
  } catch (const InputError& e) {
    if (e.line_text().empty() && e.pos().line >= 1) return e.with_line_text(d.source.line(e.pos().line));
    return e;
  }
  return std::nullopt;
}

bool limit_value_word(const Node& n, const SymbolTable& symbols) {
  const Node& v = n.kind == NodeKind::Neg ? n.args[0] : n;
  if (v.kind != NodeKind::Symbol) return false;
  if (v.text == "oo") return true;
  return n.kind == NodeKind::Symbol && v.text == "undefined" && !symbols.find("undefined");
}

bool limit_value_side(const Step& s, const Node& side, const SymbolTable& symbols) {
  return s.rule.name == "limit" && limit_value_word(side, symbols);
}

std::vector<GiNaC::ex> claim_sides(const Derivation& d, const Step& s) {
  const Relation& r = s.erratum ? s.erratum->corrected : s.claim;
  std::vector<GiNaC::ex> out;
  Definitions defs(d);
  for (std::size_t i = 0; i < r.sides.size(); ++i) {
    // A definition's own left-hand side is the name being defined: keep it as a symbol.
    if (i == 0 && s.rule.name == "definition") out.push_back(to_ginac(r.sides[0], d.symbols));
    else out.push_back(to_ginac(defs.empty() ? r.sides[i] : resolve(r.sides[i], defs, 0), d.symbols));
  }
  return out;
}

namespace {

std::optional<Formula> formula_of(const Derivation& d, const Step& s, std::string* why) {
  const Relation& r = s.erratum ? s.erratum->corrected : s.claim;
  if (r.sides.size() < 2 || r.sides[0].kind != NodeKind::Symbol) {
    if (why) *why = "step '" + s.label + "' is not of the form 'y = expression'";
    return std::nullopt;
  }
  const SymbolInfo* info = d.symbols.find(r.sides[0].text);
  if (!info || info->is_function) {
    if (why) *why = "step '" + s.label + "' does not define a symbol";
    return std::nullopt;
  }
  Formula f;
  f.label = s.label;
  f.target = info->name;
  f.step = &s;
  try {
    f.expr = resolved_ginac(d, r.sides.back());
  } catch (const InputError& e) {
    if (why) *why = e.message();
    return std::nullopt;
  }
  for (const auto& sym : d.symbols.all())
    if (!sym.is_function && GiNaC::is_a<GiNaC::symbol>(sym.sym) && f.expr.has(sym.sym))
      f.params.push_back(GiNaC::ex_to<GiNaC::symbol>(sym.sym));
  return f;
}

}  // namespace

Formula formula(const Derivation& d, const std::string& label) {
  const Step* s = d.find(label);
  if (!s) {
    std::vector<std::string> labels;
    for (const auto& st : d.steps) labels.push_back(st.label);
    throw InputError({d.source.name, 0, 0}, "no step labelled '" + label + "' in " + d.source.name);
  }
  std::string why;
  auto f = formula_of(d, *s, &why);
  if (!f) throw InputError(s->pos, why, static_cast<int>(s->label.size()), d.source.line(s->pos.line));
  return *f;
}

std::vector<Formula> formulas(const Derivation& d) {
  std::vector<Formula> out;
  for (const auto& s : d.steps)
    if (auto f = formula_of(d, s, nullptr)) out.push_back(std::move(*f));
  return out;
}

std::map<std::size_t, FigureSpec> figure_specs(const Derivation& d) {
  reader_detail::DcReader r(d.source);
  r.run();
  return r.figures();
}

}  // namespace dc
