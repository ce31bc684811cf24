// LatexReader for the emitted LaTeX (see latex_read.hpp). Recursive descent over characters:
//   relation := expr ( '=' expr )*            ('&', '\\', aligned markers skipped)
//   expr     := ['-'|'+'] term ( ('+'|'-') term )*
//   term     := factor ( ['\cdot' | '/'] factor )*        juxtaposition is multiplication
//   factor   := primary ( '^' '{' expr '}' | '^{\circ}' )? | '{}^{\circ}'      (the degree sign: *deg)
//   primary  := number | name | name '(' args ')' | '{' expr '}' | '\left(' expr '\right)'
//             | '(' expr ')' | '\left|' expr '\right|' | \frac | \sqrt | \mathrm{e}^ | \ln ...
//             | \lim_{x \to p} factor | \lim_{x \to p^{+}} factor | \int_{a}^{b} expr \, \mathrm{d} x | \pi | \infty
#include "derivations/report/latex_read.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "derivations/syntax/source.hpp"

namespace dc {
namespace {

struct Name {
  std::string tex;
  std::string name;
  bool function = false;
  std::vector<std::string> params;
  bool differential = false;   // \mathrm{d}v, the symbol d(v)
};

class LatexReader {
 public:
  LatexReader(std::string_view s, const SymbolTable& t, SourcePos origin) : s_(s), origin_(std::move(origin)) {
    for (const auto& info : t.all()) {
      if (info.tex.empty()) continue;
      names_.push_back({info.tex, info.name, info.is_function, info.params, info.is_differential});
    }
    // Longest TeX name first; for equal TeX names, the symbol before the function (a call is
    // recognised by the '(' that follows).
    std::stable_sort(names_.begin(), names_.end(), [](const Name& a, const Name& b) {
      if (a.tex.size() != b.tex.size()) return a.tex.size() > b.tex.size();
      return !a.function && b.function;
    });
  }

  Relation relation() {
    Relation r;
    skip_layout();
    r.sides.push_back(expr());
    for (;;) {
      skip_layout();
      if (at_end()) break;
      if (peek() == '=') {
        ++i_;
        skip_layout();
        r.sides.push_back(expr());
        continue;
      }
      fail("expected '=' or the end of the equation");
    }
    return r;
  }

  Node whole_expression() {
    skip_ws();
    Node n = expr();
    skip_ws();
    if (!at_end()) fail("unexpected text after the expression");
    return n;
  }

 private:
  // ------------------------------------------------------------ scanning
  bool at_end() const { return i_ >= s_.size(); }
  char peek() const { return at_end() ? '\0' : s_[i_]; }
  bool starts(std::string_view w) const { return s_.substr(i_, w.size()) == w; }

  // A control word `\name` here, not followed by a further letter.
  bool command(std::string_view w) {
    if (!starts(w)) return false;
    std::size_t j = i_ + w.size();
    if (std::isalpha(static_cast<unsigned char>(w.back())) && j < s_.size() &&
        std::isalpha(static_cast<unsigned char>(s_[j])))
      return false;
    return true;
  }
  bool accept(std::string_view w) {
    skip_ws();
    if (!command(w)) return false;
    i_ += w.size();
    return true;
  }
  void expect(std::string_view w) {
    if (!accept(w)) fail("expected '" + std::string(w) + "'");
  }
  // White space, then the single character c ({ } ( ) _ ^), which is consumed.
  void expect_char(char c, const std::string& what = {}) {
    skip_ws();
    if (peek() != c) fail(what.empty() ? std::string("expected '") + c + "'" : what);
    ++i_;
  }

  void skip_ws() {
    while (!at_end() && std::isspace(static_cast<unsigned char>(peek()))) ++i_;
  }

  // A long sum broken over rows of an align: `\\ &\quad + term` continues the sum.
  void skip_sum_break() {
    std::size_t save = i_;
    if (!starts("\\\\")) return;
    i_ += 2;
    skip_ws();
    if (peek() == '&') {
      ++i_;
      skip_ws();
      if (starts("\\quad ")) {
        i_ += 6;
        skip_ws();
        if (peek() == '+' || peek() == '-') return;
      }
    }
    i_ = save;
  }

  // Whitespace and the layout markers of aligned/gather blocks.
  void skip_layout() {
    for (;;) {
      skip_ws();
      if (peek() == '&') { ++i_; continue; }
      if (starts("\\\\")) { i_ += 2; continue; }
      if (accept("\\begin{aligned}") || accept("\\end{aligned}") || accept("\\notag") ||
          accept("\\footnotemark") || accept("\\qquad\\text{(erratum\\footnotemark)}") ||
          accept("\\qquad\\text{(erratum)}"))
        continue;
      if (accept("\\tag")) {
        brace_group_raw();
        continue;
      }
      break;
    }
  }

  std::string brace_group_raw() {
    skip_ws();
    if (peek() != '{') fail("expected '{'");
    int depth = 0;
    std::size_t start = i_;
    do {
      if (peek() == '{') ++depth;
      else if (peek() == '}') --depth;
      ++i_;
    } while (!at_end() && depth > 0);
    if (depth != 0) fail("unbalanced '{'");
    return std::string(s_.substr(start + 1, i_ - start - 2));
  }

  SourcePos pos_at(std::size_t k) const { return position_in(s_, origin_, k); }

  [[noreturn]] void fail(const std::string& what) const {
    std::string near(s_.substr(i_, 24));
    throw InputError(pos_at(i_), "latex reader: " + what + (at_end() ? " (at the end)" : " at '" + near + "'"));
  }

  static Node make(NodeKind k, std::string text = {}, std::vector<Node> args = {}) {
    Node n;
    n.kind = k;
    n.text = std::move(text);
    n.args = std::move(args);
    return n;
  }
  static Node bin(NodeKind k, Node a, Node b) {
    std::vector<Node> v;
    v.push_back(std::move(a));
    v.push_back(std::move(b));
    return make(k, {}, std::move(v));
  }
  static Node call(std::string name, std::vector<Node> args) { return make(NodeKind::Call, std::move(name), std::move(args)); }

  // ------------------------------------------------------------ grammar
  Node expr() {
    skip_ws();
    Node left;
    if (peek() == '-') {
      ++i_;
      left = make(NodeKind::Neg, {}, {term()});
    } else {
      if (peek() == '+') ++i_;
      left = term();
    }
    for (;;) {
      skip_ws();
      skip_sum_break();
      char c = peek();
      if (c == '+') { ++i_; left = bin(NodeKind::Add, std::move(left), term()); }
      else if (c == '-') { ++i_; left = bin(NodeKind::Sub, std::move(left), term()); }
      else break;
    }
    return left;
  }

  bool factor_can_start() {
    skip_ws();
    if (at_end()) return false;
    char c = peek();
    if (c == '+' || c == '-' || c == '=' || c == '&' || c == '}' || c == ')' || c == ',' || c == '^' || c == '/')
      return false;
    if (match_name()) return true;  // a TeX name may start with anything, even "\,"  
    if (starts("\\\\") || command("\\right") || starts("\\,") || command("\\to") || command("\\cdot") ||
        command("\\notag") || command("\\tag") || command("\\end") || command("\\footnotemark"))
      return false;
    return true;
  }

  Node term() {
    Node left = factor();
    for (;;) {
      if (accept("\\cdot")) { left = bin(NodeKind::Mul, std::move(left), factor()); continue; }
      skip_ws();
      if (peek() == '/') { ++i_; left = bin(NodeKind::Div, std::move(left), factor()); continue; }
      if (factor_can_start()) { left = bin(NodeKind::Mul, std::move(left), factor()); continue; }
      if (starts("\\,")) {   // u_e\,\mathrm{d}m_r: a thin space before a differential factor
        const std::size_t at = i_;
        i_ += 2;
        const Name* n = match_name();
        if (n && n->differential) { left = bin(NodeKind::Mul, std::move(left), factor()); continue; }
        i_ = at;
      }
      break;
    }
    return left;
  }

  Node factor() {
    // the degree sign: 30^{\circ} is 30*deg; {}^{\circ} stands alone after a power
    if (accept("{}^{\\circ}")) return make(NodeKind::Symbol, "deg");
    Node base = primary();
    skip_ws();
    if (accept("^{\\circ}")) return bin(NodeKind::Mul, std::move(base), make(NodeKind::Symbol, "deg"));
    if (peek() == '^') {
      ++i_;
      Node e = braced_expr();
      return bin(NodeKind::Pow, std::move(base), std::move(e));
    }
    return base;
  }

  Node braced_expr() {
    expect_char('{');
    Node n = expr();
    expect_char('}');
    return n;
  }

  Node paren_expr() {  // after \left(
    Node n = expr();
    expect("\\right)");
    n.parenthesized = true;
    return n;
  }

  std::vector<Node> call_args() {  // after '('
    std::vector<Node> args;
    skip_ws();
    for (;;) {
      args.push_back(expr());
      skip_ws();
      if (peek() == ',') { ++i_; continue; }
      if (peek() == ')') { ++i_; break; }
      fail("expected ',' or ')' in a function call");
    }
    return args;
  }

  const Name* match_name() {
    for (const Name& n : names_) {
      if (!starts(n.tex)) continue;
      std::size_t j = i_ + n.tex.size();
      char last = n.tex.back();
      if (j < s_.size() && std::isalpha(static_cast<unsigned char>(last)) &&
          std::isalpha(static_cast<unsigned char>(s_[j])))
        continue;  // the writer separates names; a letter here means a longer name
      return &n;
    }
    return nullptr;
  }

  // A name: a symbol, or a declared function applied to arguments.
  Node name_or_call() {
    const Name* n = match_name();
    if (!n) fail("unknown symbol");
    std::size_t after = i_ + n->tex.size();
    bool paren = after < s_.size() && s_[after] == '(';
    if (paren) {
      // a function with this TeX name (possibly after a symbol of the same spelling)
      const Name* f = nullptr;
      for (const Name& m : names_)
        if (m.function && m.tex == n->tex) f = &m;
      if (f) {
        i_ = after + 1;
        return call(f->name, call_args());
      }
    }
    i_ = after;
    if (n->function) {
      // a declared function printed bare at its own parameters: v is v(t)
      std::vector<Node> a;
      for (const auto& p : n->params) a.push_back(make(NodeKind::Symbol, p));
      return call(n->name, std::move(a));
    }
    return make(NodeKind::Symbol, n->name);
  }

  // The derivand of \frac{\mathrm{d} X}{\mathrm{d} t}: a symbol, or a function of t.
  Node derivand(const std::string& tex, const std::string& var) {
    const Name* sym = nullptr;
    const Name* fn = nullptr;
    for (const Name& m : names_)
      if (m.tex == tex) (m.function ? fn : sym) = &m;
    if (fn) {
      std::vector<Node> a;
      a.push_back(make(NodeKind::Symbol, var));
      return call(fn->name, std::move(a));
    }
    if (sym) return make(NodeKind::Symbol, sym->name);
    fail("unknown symbol '" + tex + "' in a derivative");
  }

  std::string var_name(const std::string& tex) {
    for (const Name& m : names_)
      if (!m.function && m.tex == tex) return m.name;
    fail("unknown variable '" + tex + "'");
  }

  static std::string trim(std::string s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
    std::size_t k = 0;
    while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
    return s.substr(k);
  }

  // \frac{\mathrm{d}[^{n}] [X]}{\mathrm{d} t[^{n}]} [\left( f \right)]
  Node derivative(const std::string& num, const std::string& den) {
    std::string a = trim(num.substr(std::strlen("\\mathrm{d}")));
    std::string order;
    if (!a.empty() && a[0] == '^') {
      auto close = a.find('}');
      if (a.size() < 3 || a[1] != '{' || close == std::string::npos) fail("malformed derivative order");
      order = a.substr(2, close - 2);
      a = trim(a.substr(close + 1));
    }
    std::string d = trim(den);
    if (d.rfind("\\mathrm{d}", 0) != 0) fail("expected '\\mathrm{d}' in a derivative's denominator");
    d = trim(d.substr(std::strlen("\\mathrm{d}")));
    if (!order.empty()) {
      std::string suffix = "^{" + order + "}";
      if (d.size() < suffix.size() || d.compare(d.size() - suffix.size(), suffix.size(), suffix) != 0)
        fail("derivative orders differ");
      d = trim(d.substr(0, d.size() - suffix.size()));
    }
    std::string var = var_name(d);
    Node f;
    if (a.empty()) {
      expect("\\left(");
      f = paren_expr();
    } else {
      f = derivand(a, var);
    }
    std::vector<Node> args;
    args.push_back(std::move(f));
    args.push_back(make(NodeKind::Symbol, var));
    if (!order.empty()) args.push_back(make(NodeKind::Number, order));
    return call("diff", std::move(args));
  }

  Node primary() {
    skip_ws();
    if (at_end()) fail("expected an expression");
    if (accept("\\begin{pmatrix}")) {   // a vector literal, one component per row
      std::vector<Node> rows;
      for (;;) {
        rows.push_back(expr());
        skip_ws();
        if (accept("\\\\")) continue;
        expect("\\end{pmatrix}");
        break;
      }
      return call("vec", std::move(rows));
    }
    char c = peek();
    if (std::isdigit(static_cast<unsigned char>(c))) {
      std::size_t st = i_;
      while (std::isdigit(static_cast<unsigned char>(peek()))) ++i_;
      if (peek() == '.' && i_ + 1 < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_ + 1]))) {
        ++i_;
        while (std::isdigit(static_cast<unsigned char>(peek()))) ++i_;
      }
      return make(NodeKind::Number, std::string(s_.substr(st, i_ - st)));
    }
    if (c == '{') {
      ++i_;
      Node n = expr();
      expect_char('}');
      return n;
    }
    if (c == '(') {
      ++i_;
      Node n = expr();
      expect_char(')');
      n.parenthesized = true;
      return n;
    }
    if (accept("\\left(")) return paren_expr();
    if (accept("\\left|")) {
      Node n = expr();
      expect("\\right|");
      std::vector<Node> a;
      a.push_back(std::move(n));
      return call("abs", std::move(a));
    }
    if (accept("\\frac")) {
      std::size_t at = i_;
      std::string num = brace_group_raw();
      std::string den = brace_group_raw();
      if (trim(num).rfind("\\mathrm{d}", 0) == 0) return derivative(trim(num), den);
      i_ = at;
      Node a = braced_expr();
      Node b = braced_expr();
      return bin(NodeKind::Div, std::move(a), std::move(b));
    }
    if ((starts("\\dot{") || starts("\\ddot{")) && !match_name()) {
      // \dot{x}: d/dt of a declared function of one variable, printed bare (`notation dot`)
      bool second = starts("\\ddot");
      i_ += second ? 5 : 4;
      std::string tex = trim(brace_group_raw());
      const Name* fn = nullptr;
      for (const Name& m : names_)
        if (m.function && m.tex == tex && m.params.size() == 1) fn = &m;
      if (!fn) fail("'\\dot{" + tex + "}' is not a declared function of one variable");
      std::vector<Node> a;
      a.push_back(call(fn->name, {make(NodeKind::Symbol, fn->params[0])}));
      a.push_back(make(NodeKind::Symbol, fn->params[0]));
      if (second) a.push_back(make(NodeKind::Number, "2"));
      return call("diff", std::move(a));
    }
    if (accept("\\sqrt")) {
      std::vector<Node> a;
      a.push_back(braced_expr());
      return call("sqrt", std::move(a));
    }
    if (accept("\\mathrm{e}")) {
      expect_char('^', "expected '^' after \\mathrm{e}");
      std::vector<Node> a;
      a.push_back(braced_expr());
      return call("exp", std::move(a));
    }
    static const std::pair<const char*, const char*> kFuncs[] = {
        {"\\ln", "log"}, {"\\sin", "sin"}, {"\\cos", "cos"}, {"\\tan", "tan"},
        {"\\arcsin", "asin"}, {"\\arccos", "acos"}, {"\\arctan", "atan"}};
    for (const auto& [tex, name] : kFuncs) {
      if (!accept(tex)) continue;
      // \sin^{2} x: a power of the function's value
      std::optional<Node> exponent;
      skip_ws();
      if (peek() == '^') {
        expect_char('^');
        exponent = braced_expr();
      }
      std::vector<Node> a;
      if (accept("\\left(")) {
        Node n = expr();
        expect("\\right)");
        a.push_back(std::move(n));
      } else {
        a.push_back(primary());
      }
      if (exponent) return bin(NodeKind::Pow, call(name, std::move(a)), std::move(*exponent));
      return call(name, std::move(a));
    }
    if (accept("\\lim")) {
      expect_char('_', "expected '_' after \\lim");
      expect_char('{');
      Node var = expr();
      expect("\\to");
      // a one-sided limit: \lim_{x \to 0^{+}} (the writer's fourth argument, "+" or "-")
      std::size_t close = i_;
      for (int depth = 0; close < s_.size(); ++close) {
        if (s_[close] == '{') ++depth;
        else if (s_[close] == '}' && depth-- == 0) break;
      }
      std::string side;
      std::string_view sub = s_.substr(i_, close - i_);
      while (!sub.empty() && std::isspace(static_cast<unsigned char>(sub.back()))) sub.remove_suffix(1);
      for (const char* sfx : {"^{+}", "^{-}"})
        if (sub.size() > 4 && sub.substr(sub.size() - 4) == sfx) side = sfx[2] == '+' ? "+" : "-";
      Node point;
      if (side.empty()) {
        point = expr();
      } else {
        std::string_view whole = s_;
        s_ = s_.substr(0, i_ + sub.size() - 4);   // the point alone
        point = expr();
        skip_ws();
        if (!at_end()) fail("expected '^{" + side + "}' after the limit point");
        s_ = whole;
        i_ += 4;
      }
      expect_char('}');
      Node body = factor();
      std::vector<Node> a;
      a.push_back(std::move(body));
      a.push_back(std::move(var));
      a.push_back(std::move(point));
      if (!side.empty()) a.push_back(make(NodeKind::Symbol, side));
      return call("limit", std::move(a));
    }
    if (accept("\\int")) {
      skip_ws();
      const bool definite = peek() == '_';   // else indefinite: \int f \, \mathrm{d} x
      Node lo, hi;
      if (definite) {
        expect_char('_', "expected '_' after \\int");
        lo = braced_expr();
        expect_char('^', "expected '^' after the lower limit");
        hi = braced_expr();
      }
      Node body = expr();
      expect("\\,");
      expect("\\mathrm{d}");
      skip_ws();
      Node var = primary();
      std::vector<Node> a;
      a.push_back(std::move(body));
      a.push_back(std::move(var));
      if (definite) {
        a.push_back(std::move(lo));
        a.push_back(std::move(hi));
      }
      return call("integral", std::move(a));
    }
    if (accept("\\operatorname")) {
      std::string name = trim(brace_group_raw());
      expect("\\left(");
      std::vector<Node> args;
      for (;;) {
        args.push_back(expr());
        skip_ws();
        if (peek() == ',') { ++i_; continue; }
        break;
      }
      expect("\\right)");
      return call(name, std::move(args));
    }
    // Declared names before \pi and \infty: a TeX name may start with either.
    if (match_name()) return name_or_call();
    if (accept("\\pi")) return make(NodeKind::Symbol, "pi");
    if (accept("\\infty")) return make(NodeKind::Symbol, "oo");
    fail("unknown symbol or unexpected input");
  }

  std::string_view s_;
  std::size_t i_ = 0;
  SourcePos origin_;
  std::vector<Name> names_;
};

}  // namespace

Relation read_latex_relation(std::string_view latex, const SymbolTable& table, const SourcePos& origin) {
  LatexReader r(latex, table, origin);
  return r.relation();
}

Node read_latex_expression(std::string_view latex, const SymbolTable& table, const SourcePos& origin) {
  LatexReader r(latex, table, origin);
  return r.whole_expression();
}

std::vector<LatexDisplay> extract_latex_displays(const std::string& doc) {
  std::vector<LatexDisplay> out;
  bool in_env = false;
  LatexDisplay* cur = nullptr;
  std::size_t start = 0;
  int line_no = 0;
  auto strip = [](std::string& s, const std::string& w) {
    for (std::size_t k; (k = s.find(w)) != std::string::npos;) s.erase(k, w.size());
  };
  while (start <= doc.size()) {
    std::size_t nl = doc.find('\n', start);
    std::string line = doc.substr(start, nl == std::string::npos ? std::string::npos : nl - start);
    ++line_no;
    start = nl == std::string::npos ? doc.size() + 1 : nl + 1;
    if (line.rfind("% ", 0) == 0 && line.size() > 2 && line.back() == ')' && line.find(" (") != std::string::npos &&
        line.rfind("% ----", 0) != 0) {
      // % LABEL (FILE:LINE)
      std::size_t open = line.find(" (");
      std::size_t colon = line.rfind(':');
      if (colon == std::string::npos || colon < open) continue;
      LatexDisplay d;
      d.label = line.substr(2, open - 2);
      d.file = line.substr(open + 2, colon - open - 2);
      d.source_line = std::atoi(line.substr(colon + 1).c_str());
      out.push_back(d);
      cur = &out.back();
      continue;
    }
    if (line.rfind("\\begin{gather}", 0) == 0 || line.rfind("\\begin{equation", 0) == 0 ||
        line.rfind("\\begin{align}", 0) == 0 || line.rfind("\\begin{align*}", 0) == 0) {
      in_env = true;
      continue;
    }
    if (line.rfind("\\end{gather}", 0) == 0 || line.rfind("\\end{equation", 0) == 0 ||
        line.rfind("\\end{align}", 0) == 0 || line.rfind("\\end{align*}", 0) == 0) {
      in_env = false;
      continue;
    }
    if (!in_env || !cur) continue;
    if (cur->latex.empty()) cur->line = line_no;
    cur->latex += (cur->latex.empty() ? "" : "\n") + line;
  }
  for (auto& d : out) {
    std::string& s = d.latex;
    if (auto k = s.find("\\tag{"); k != std::string::npos) {
      auto close = s.find('}', k);
      d.tag = s.substr(k + 5, close - k - 5);
      s.erase(k, close - k + 1);
    }
    if (s.find("\\footnotemark") != std::string::npos) d.footnote = true;
    strip(s, "\\qquad\\text{(erratum\\footnotemark)}");
    // a rule's condition beside the equation, \qquad\text{(as $x \to p$)}: not part of the claim
    for (std::size_t k; (k = s.find("\\qquad\\text{(")) != std::string::npos;) {
      std::size_t j = s.find('{', k), depth = 0;
      for (; j < s.size(); ++j) {
        if (s[j] == '{') ++depth;
        if (s[j] == '}' && --depth == 0) break;
      }
      s.erase(k, std::min(j + 1, s.size()) - k);
    }
    strip(s, "\\footnotemark");
    strip(s, "\\notag");
    // the gather line break after the display
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
    if (s.size() >= 2 && s.compare(s.size() - 2, 2, "\\\\") == 0) s.erase(s.size() - 2);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  }
  return out;
}

}  // namespace dc
