// Reader for the derivation file format (.dc), docs/format.md.
//
// The reader is line oriented: comments are blanked (positions survive), a statement is a
// line at column 1 plus the indented lines that follow it. Every expression is parsed by
// dc::parse_relation / parse_expression with its exact origin, so errors point at the
// offending character, GCC style.
#include "derivations/core/derivation.hpp"

#include <algorithm>
#include <functional>
#include <set>

#include "derivations/core/big_o.hpp"
#include "derivations/core/io.hpp"
#include "derivations/core/prose.hpp"
#include "derivations/core/prove.hpp"
#include "derivations/core/satisfiable.hpp"
#include "derivations/core/units.hpp"

namespace dc {

namespace {

const std::vector<std::string> kRuleNames = {"given",  "definition", "rewrite",     "substitute",
                                             "solve",  "limit",      "first_order", "series",
                                             "differentiate", "integrate", "solves_ode"};
const std::vector<std::string> kRewriteAliases = {"simplify", "expand", "factor", "algebra"};
const std::vector<std::string> kRuleKeywords = {"for", "into", "of", "with", "wrt", "from"};
const std::vector<std::string> kStatementKeywords = {"title", "section", "symbol", "function",
                                                     "assume", "heading", "text", "remark", "figure", "notation"};
const std::vector<std::string> kAttributeKeywords = {"by", "note", "erratum", "stable", "hide"};

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

bool is_ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_ident_char(char c) { return is_ident_start(c) || (c >= '0' && c <= '9') || c == '_'; }
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Bytes of the UTF-8 character starting at t[i] (1 for a byte that starts none), so messages
// never quote half a character.
std::size_t utf8_length(const std::string& t, std::size_t i) {
  unsigned char c = static_cast<unsigned char>(t[i]);
  std::size_t n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 1;
  std::size_t k = 1;
  while (k < n && i + k < t.size() && (static_cast<unsigned char>(t[i + k]) & 0xC0) == 0x80) ++k;
  return k;
}

std::string join(const std::vector<std::string>& v, const std::string& sep) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? sep : "") + v[i];
  return out;
}

// A piece of source text with the position of every character (continuation lines are
// joined with '\n' and keep their indentation, so the expression parser's own position
// arithmetic — a newline resets the column to 1 — stays exact).
struct Span {
  std::string text;
  std::vector<SourcePos> pos;   // one per character of text
  SourcePos end;                // just after the last character

  SourcePos at(std::size_t i) const { return i < pos.size() ? pos[i] : end; }
  void append_line(const std::string& file, int line_no, const std::string& line, std::size_t from) {
    if (!text.empty()) {
      text += '\n';
      pos.push_back(SourcePos{file, line_no, 0});
      from = 0;  // continuation lines keep their indentation
    }
    for (std::size_t i = from; i < line.size(); ++i) {
      text += line[i];
      pos.push_back(SourcePos{file, line_no, static_cast<int>(i) + 1});
    }
    end = SourcePos{file, line_no, static_cast<int>(line.size()) + 1};
  }
  Span sub(std::size_t b, std::size_t e) const {
    Span s;
    e = std::min(e, text.size());
    b = std::min(b, e);
    s.text = text.substr(b, e - b);
    s.pos.assign(pos.begin() + static_cast<long>(b), pos.begin() + static_cast<long>(e));
    s.end = at(e);
    return s;
  }
};

// Strip leading/trailing whitespace (including newlines) of a span range.
void trim_range(const std::string& t, std::size_t& b, std::size_t& e) {
  while (b < e && (is_space(t[b]) || t[b] == '\n')) ++b;
  while (e > b && (is_space(t[e - 1]) || t[e - 1] == '\n')) --e;
}

struct Statement {
  int first_line = 0;
  std::vector<std::pair<int, std::string>> lines;   // (line number, comment-blanked text)
};

class Reader {
 public:
  explicit Reader(SourceText src) { d_.source = std::move(src); }

  Derivation run() {
    split_lines();
    collect_labels();
    for (const auto& st : statements_) statement(st);
    check_assumptions();
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

 private:
  Derivation d_;
  std::vector<std::string> lines_;              // comment-blanked
  std::vector<Statement> statements_;
  std::map<std::string, SourcePos> all_labels_;  // every label in the file (to say "later")
  std::map<std::string, std::size_t> defined_;   // labels defined so far -> step index
  std::set<std::string> used_names_;             // identifiers in the claims of the steps so far
  std::string rule_name_;                        // the rule line being read (as written)
  std::optional<SourcePos> first_assume_;
  std::string current_label_;                    // the step being read

  const std::string& file() const { return d_.source.name; }

  [[noreturn]] void fail(const SourcePos& p, const std::string& msg, int length = 1) {
    throw InputError(p, msg, length, d_.source.line(p.line));
  }

  // --- lines and statements ------------------------------------------------------------
  void split_lines() {
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
  static std::string word_at(const std::string& l, std::size_t from, std::size_t* end = nullptr) {
    std::size_t i = from;
    while (i < l.size() && is_ident_char(l[i])) ++i;
    if (end) *end = i;
    return l.substr(from, i - from);
  }

  // Step header: [(TAG)] LABEL ':' ; returns false if the line is not of that shape.
  struct Header {
    std::string tag, label;
    SourcePos label_pos;
    std::size_t claim_from = 0;
  };
  bool parse_header(const std::string& l, int ln, Header& h, bool throw_on_error) {
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

  void collect_labels() {
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

  void statement(const Statement& st) {
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
      if (w == "title" || w == "section") {
        std::size_t p = 0;
        std::string str = string_literal(s, p, "a quoted " + w + ", e.g. " + w + " \"...\"");
        expect_end(s, p);
        (w == "title" ? d_.title : d_.section) = str;
      } else if (w == "notation") {
        // notation dot | leibniz: how the LaTeX writes derivatives of declared functions
        std::size_t p = 0;
        skip_ws(s, p);
        SourcePos at = s.at(p);
        std::string v = identifier(s, p, "'dot' or 'leibniz' after notation");
        if (v != "dot" && v != "leibniz")
          fail(at, "unknown notation '" + v + "'; expected 'dot' (\\dot{x}) or 'leibniz' (dx/dt)",
               static_cast<int>(v.size()));
        expect_end(s, p);
        d_.dot_derivatives = v == "dot";
      } else if (w == "heading" || w == "figure" || w == "text" || w == "remark") {
        prose_statement(w, s, {file(), st.first_line, 1});
      } else if (w == "symbol") {
        symbol_statement(s, false);
      } else if (w == "function") {
        symbol_statement(s, true);
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
           "unknown statement '" + shown + "'; expected one of title, section, symbol, function, assume, "
           "heading, text, remark, figure, notation, or a step '[(TAG)] LABEL: CLAIM'",
           static_cast<int>(std::max<std::size_t>(1, shown.size())));
    }
    step_statement(st, h);
  }

  // heading "..." / figure "..." / text PARAGRAPH / remark PARAGRAPH (docs/format.md, "Text").
  void prose_statement(const std::string& w, const Span& s, const SourcePos& pos) {
    Prose pr;
    pr.pos = pos;
    pr.before_step = d_.steps.size();
    if (w == "heading" || w == "figure") {
      pr.kind = w == "heading" ? Prose::Kind::Heading : Prose::Kind::Figure;
      std::size_t p = 0;
      std::string str = string_literal(s, p, "a quoted " + std::string(w == "heading" ? "heading" : "caption") +
                                                 ", e.g. " + w + " \"...\"");
      expect_end(s, p);
      if (str.find_first_not_of(' ') == std::string::npos) fail(s.at(0), "empty " + w + ": write its text between the quotes");
      pr.pieces.push_back({ProsePiece::Kind::Text, str, {}});
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

  // --- small lexical helpers on spans ----------------------------------------------------
  static std::size_t nonspace(const Span& s, std::size_t p) {
    skip_ws(s, p);
    return p;
  }
  static void skip_ws(const Span& s, std::size_t& p) {
    while (p < s.text.size() && (is_space(s.text[p]) || s.text[p] == '\n')) ++p;
  }

  std::string string_literal(const Span& s, std::size_t& p, const std::string& expected) {
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

  void expect_end(const Span& s, std::size_t p) {
    skip_ws(s, p);
    if (p < s.text.size()) fail(s.at(p), "unexpected text '" + excerpt(s, p) + "'; expected the end of the statement");
  }

  static std::string excerpt(const Span& s, std::size_t p) {
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

  std::string identifier(const Span& s, std::size_t& p, const std::string& expected) {
    skip_ws(s, p);
    if (p >= s.text.size() || !is_ident_start(s.text[p]))
      fail(s.at(p), "expected " + expected + (p < s.text.size() ? ", found '" + excerpt(s, p) + "'" : ""));
    std::size_t b = p;
    while (p < s.text.size() && is_ident_char(s.text[p])) ++p;
    return s.text.substr(b, p - b);
  }

  Node expression(const Span& s, std::size_t b, std::size_t e, const std::string& what) {
    trim_range(s.text, b, e);
    if (b >= e) fail(s.at(b), "expected " + what);
    return parse_expression(std::string_view(s.text).substr(b, e - b), s.at(b));
  }
  Relation relation(const Span& s, std::size_t b, std::size_t e, const std::string& what) {
    trim_range(s.text, b, e);
    if (b >= e) fail(s.at(b), "expected " + what);
    return parse_relation(std::string_view(s.text).substr(b, e - b), s.at(b));
  }

  // Convert with the table, for validation (undefined symbols, exponent limits, ...).
  // Undeclared symbols, bad calls and other input errors throw here. A limit(...) that the
  // limit engine cannot decide is not an input error: the step that uses it is undecided when
  // it is checked (found by fuzz_reader: the whole file was lost).
  void validate(const Node& n) {
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
  GiNaC::ex converted(const Node& n) {
    try {
      return to_ginac(n, d_.symbols);
    } catch (const UndecidedLimit& e) {
      throw InputError(n.pos, std::string("this expression cannot be used in a declaration: ") + e.what(), n.length);
    }
  }

  // --- symbol / function -------------------------------------------------------------
  void symbol_statement(const Span& s, bool is_function) {
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
      for (;;) {
        skip_ws(s, p);
        SourcePos ap = s.at(p);
        std::string a = identifier(s, p, "an argument name (a declared symbol)");
        const SymbolInfo* info = d_.symbols.find(a);
        if (!info || info->is_function)
          fail(ap, "the argument '" + a + "' of function '" + names[0].name +
                       "' must be a declared symbol (declare it first with 'symbol " + a + " : real [s]')",
               static_cast<int>(a.size()));
        params.push_back(a);
        skip_ws(s, p);
        if (p < s.text.size() && s.text[p] == ',') { ++p; continue; }
        if (p < s.text.size() && s.text[p] == ')') { ++p; break; }
        fail(s.at(p), "expected ',' or ')' in the argument list of '" + names[0].name + "'");
      }
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
    std::size_t de;
    if (dw == "in") {
      std::size_t q = we;
      while (q < s.text.size() && is_space(s.text[q])) ++q;
      if (q >= s.text.size() || (s.text[q] != '[' && s.text[q] != '('))
        fail(s.at(q), "expected an interval after 'in', e.g. 'in [0, 1]' or 'in (0, pi)'");
      std::size_t close = s.text.find_first_of("])", q + 1);
      if (close == std::string::npos) fail(s.at(q), "expected ']' or ')' to close the interval");
      de = close + 1;
    } else if (dw.empty()) {
      fail(s.at(p), "expected a domain: real, positive, nonnegative, negative, or an interval 'in [a, b]'");
    } else {
      de = we;
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
      info.pos = names[i].pos;
      info.is_function = is_function;
      info.params = params;
      d_.symbols.declare(std::move(info));
    }
  }

  // --- assume ------------------------------------------------------------------------
  void assume_statement(const Span& s, const SourcePos& at) {
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

  void check_assumptions() {
    Satisfiability sat = decide_satisfiable(d_.symbols);
    if (sat.status == Satisfiability::Status::Satisfiable) return;
    SourcePos p = first_assume_ ? *first_assume_ : SourcePos{file(), 1, 1};
    std::string why = unsatisfiable_message(sat);
    if (sat.status == Satisfiability::Status::Unsatisfiable) why += "; nothing may be derived from a contradiction";
    fail(p, why, 6);
  }

  // --- steps -----------------------------------------------------------------------------
  void step_statement(const Statement& st, const Header& h) {
    if (contains(kRuleKeywords, h.label) || contains(kAttributeKeywords, h.label) || is_reserved_name(h.label))
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
    // Symbols: a definition introduces its left-hand side.
    if (step.rule.name == "definition") introduce_definition(step);
    // Undefined symbols (and other conversion errors) in the claim; for an erratum step the
    // printed claim's error is kept for the report, the corrected claim must be valid.
    if (step.erratum) {
      for (const auto& side : step.erratum->corrected.sides) validate(side);
    } else {
      for (const auto& side : step.claim.sides)
        if (!limit_value_side(step, side, d_.symbols)) validate_side(side);
    }
    step.names_result = names_new_quantity(step);
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
  void order_term(Step& step) {
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

  // See Step::names_result.
  bool names_new_quantity(const Step& step) const {
    if (step.rule.name == "given" || step.rule.name == "definition" || step.erratum) return false;
    if (step.claim.sides.size() < 3) return false;
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
    if (info->domain.kind != Domain::Kind::Real) return false;
    if (n.kind != NodeKind::Call || !info->is_function || n.args.size() != info->params.size()) return false;
    for (std::size_t i = 0; i < n.args.size(); ++i)
      if (n.args[i].kind != NodeKind::Symbol || n.args[i].text != info->params[i]) return false;
    return true;
  }

  // integral(...) cannot be converted to GiNaC; validate its parts instead.
  void validate_side(const Node& n) {
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
  static bool contains_integral(const Node& n) {
    if (n.kind == NodeKind::Call && n.text == "integral") return true;
    for (const auto& a : n.args)
      if (contains_integral(a)) return true;
    return false;
  }

  static std::string normalise_ws(const std::string& t) {
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

  void introduce_definition(Step& step) {
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
  void check_definition_cycle(const std::string& name, const Node& rhs) {
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

  // --- the rule line -------------------------------------------------------------------
  void check_ref(const std::string& label, const SourcePos& p) {
    if (defined_.count(label)) return;
    if (label == current_label_)
      fail(p, "step '" + label + "' refers to itself; a step may only use earlier steps",
           static_cast<int>(label.size()));
    auto it = all_labels_.find(label);
    if (it != all_labels_.end())
      fail(p, "step '" + label + "' is defined later (at " + std::to_string(it->second.line) + ":" +
                  std::to_string(it->second.col) + "); a step may only use earlier steps",
           static_cast<int>(label.size()));
    fail(p, "unknown label '" + label + "'; expected the label of an earlier step", static_cast<int>(label.size()));
  }

  RuleSpec rule_line(const Span& s, const SourcePos& by_pos) {
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
    else fail(name_pos, "unknown rule '" + name + "'; known rules: " + all_rules, static_cast<int>(name.size()));
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
      if (c == '(') { ++depth; continue; }
      if (c == ')') { --depth; continue; }
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
    else if (r == "solve") allowed = {"for"};
    else if (r == "limit") allowed = {"->", "of", "with"};
    else if (r == "series") allowed = {"->", "of", "with", "to"};
    else if (r == "first_order") allowed = {"of"};
    else if (r == "differentiate") allowed = {"wrt"};
    else if (r == "integrate") allowed = {"wrt", "from", "with"};
    else if (r == "solves_ode") allowed = {"wrt", "with"};
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
    } else if (r == "solve") {
      if (pre_items.empty()) fail(s.at(nonspace(s, pre.b)), "expected the labels of the equations to solve" + usage(r));
      for (auto& it : pre_items) spec.refs.push_back(label_arg(s, it.first, it.second));
      const Group& g = require("for");
      for (auto& it : items(s, g)) spec.unknowns.push_back(symbol_or_value(s, it.first, it.second));
      if (spec.unknowns.empty()) fail(s.at(nonspace(s, g.b)), "expected the unknowns after 'for'" + usage(r));
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
      for (auto& it : pre_items) spec.smalls.push_back(symbol_arg(s, it.first, it.second));
      spec.into = labels(s, require("of"), "the label of the step to expand", 1);
    } else if (r == "differentiate" || r == "integrate" || r == "solves_ode") {
      // differentiate and integrate may work on the claim's own diff(...) / integral(...)
      if (pre_items.empty() && r == "solves_ode")
        fail(s.at(nonspace(s, pre.b)), "expected the label of the equation" + usage(r));
      for (auto& it : pre_items) spec.refs.push_back(label_arg(s, it.first, it.second));
      // without a cited equation, differentiate and integrate read the variable from the claim's
      // own diff(f, x) / integral(f, x, a, b), so 'wrt' may be left out
      const Group* g = group("wrt");
      if (!g && (pre_items.empty() && r != "solves_ode")) {
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

  static std::string usage(const std::string& r) {
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
                      "'integral(f, x, a, b) = G"},
        {"solves_ode", "by solves_ode A wrt t [with y(T0) = value, ...]"}};
    auto it = u.find(r);
    return it == u.end() ? "" : "; usage: '" + it->second + "'";
  }

  // Top-level comma-separated items of a group: (begin, end) offsets, trimmed.
  std::vector<std::pair<std::size_t, std::size_t>> items(const Span& s, const auto& g) {
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
      if (c == '(') ++depth;
      else if (c == ')') --depth;
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

  bool plain_identifier(const Span& s, std::size_t b, std::size_t e) const {
    if (b >= e || !is_ident_start(s.text[b])) return false;
    for (std::size_t i = b; i < e; ++i)
      if (!is_ident_char(s.text[i])) return false;
    return true;
  }

  // An argument over s.text[b, e): its position, length and text.
  static RuleArg spanned(const Span& s, std::size_t b, std::size_t e) {
    RuleArg a;
    a.pos = s.at(b);
    a.length = static_cast<int>(e - b);
    a.label = s.text.substr(b, e - b);
    return a;
  }

  RuleArg label_arg(const Span& s, std::size_t b, std::size_t e) {
    RuleArg a = spanned(s, b, e);
    if (!plain_identifier(s, b, e)) fail(a.pos, "expected a step label, found '" + a.label + "'", a.length);
    a.kind = RuleArg::Kind::Label;
    check_ref(a.label, a.pos);
    return a;
  }

  std::vector<RuleArg> labels(const Span& s, const auto& g, const std::string& what, std::size_t count) {
    auto it = items(s, g);
    if (it.size() != count) fail(s.at(nonspace(s, g.b)), "expected " + what + " after '" + g.kw + "'");
    std::vector<RuleArg> out;
    for (auto& i : it) out.push_back(label_arg(s, i.first, i.second));
    return out;
  }

  RuleArg ref_or_equation(const Span& s, std::size_t b, std::size_t e) {
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
    for (const auto& side : rel.sides) validate(side);
    a.kind = RuleArg::Kind::Equation;
    a.equation = std::move(rel);
    return a;
  }

  RuleArg symbol_arg(const Span& s, std::size_t b, std::size_t e) {
    RuleArg a = spanned(s, b, e);
    if (!plain_identifier(s, b, e)) fail(a.pos, "expected a symbol name, found '" + a.label + "'", a.length);
    const SymbolInfo* info = d_.symbols.find(a.label);
    if (!info || info->is_function)
      fail(a.pos, "undefined symbol '" + a.label + "': declare it with 'symbol " + a.label + " ...'", a.length);
    a.kind = RuleArg::Kind::Symbol;
    a.value = parse_expression(a.label, a.pos);
    return a;
  }

  RuleArg value_arg(const Span& s, std::size_t b, std::size_t e) {
    RuleArg a = spanned(s, b, e);
    a.kind = RuleArg::Kind::Value;
    a.value = expression(s, b, e, "a value");
    bool infinite = (a.value.kind == NodeKind::Symbol && a.value.text == "oo") ||
                    (a.value.kind == NodeKind::Neg && a.value.args[0].kind == NodeKind::Symbol &&
                     a.value.args[0].text == "oo");
    if (!infinite) validate(a.value);
    return a;
  }

  RuleArg symbol_or_value(const Span& s, std::size_t b, std::size_t e) {
    if (plain_identifier(s, b, e)) return symbol_arg(s, b, e);
    RuleArg a = value_arg(s, b, e);
    return a;
  }
};

// Definitions by step: name -> (params, body).
struct Definition {
  std::vector<std::string> params;
  const Node* body;
  const Node* at_point = nullptr;   // the body for arguments other than the parameters, if different
};

bool defines_name(const Step& s) {
  return (s.rule.name == "definition" || s.names_result) && s.claim.sides.size() >= 2 &&
         (s.claim.sides[0].kind == NodeKind::Call || s.claim.sides[0].kind == NodeKind::Symbol);
}

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
        if (defines_name(s)) local_[s.claim.sides[0].text] = definition_of(d, s);
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
    if (defines_name(steps[i])) definition_index[steps[i].claim.sides[0].text] = i;
  }
  indexed = true;
}

Derivation parse_derivation(SourceText source) {
  source.text = normalize_text(std::move(source.text));
  SourceText copy = source;
  try {
    Derivation d = Reader(std::move(source)).run();
    d.index();
    return d;
  } catch (const InputError& e) {
    if (!e.line_text().empty() || e.pos().line < 1) throw;
    throw e.with_line_text(copy.line(e.pos().line));
  }
}

Derivation load_derivation(const std::string& path) {
  SourceText src;
  src.name = path;
  src.text = read_file(path);
  return parse_derivation(std::move(src));
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

}  // namespace dc
