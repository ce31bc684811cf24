// LaTeX writer (see latex.hpp): the author's tree in, deterministic LaTeX out.
#include "derivations/report/latex.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "derivations/symbolic/differential.hpp"

namespace dc {
namespace {

bool is_atom(const Node& n) { return n.kind == NodeKind::Number || n.kind == NodeKind::Symbol; }

bool is_call(const Node& n, const char* name) { return n.kind == NodeKind::Call && n.text == name; }

const char* trig_tex(const std::string& f) {
  if (f == "log" || f == "ln") return "\\ln";
  if (f == "sin") return "\\sin";
  if (f == "cos") return "\\cos";
  if (f == "tan") return "\\tan";
  if (f == "asin") return "\\arcsin";
  if (f == "acos") return "\\arccos";
  if (f == "atan") return "\\arctan";
  return nullptr;
}

double width(const Node& n);

class Writer {
 public:
  explicit Writer(const SymbolTable& t, const LatexStyle& style = {}, bool in_text = false)
      : table_(t), style_(style), in_text_(in_text) {}

  // An expression at the top of a side, a numerator, an argument: the author's outer
  // parentheses are redundant there and dropped.
  std::string top(const Node& n) { return body(n); }

  // n in a context where it is an operand; `need` says whether that context needs a group.
  std::string operand(const Node& n, bool need) {
    std::string b = body(n);
    if (need || n.parenthesized) return "\\left(" + b + "\\right)";
    return b;
  }

  std::string body(const Node& n) {
    switch (n.kind) {
      case NodeKind::Number: return n.text;
      case NodeKind::Symbol: return symbol(n.text);
      case NodeKind::Add: return operand(n.args[0], false) + " + " + operand(n.args[1], n.args[1].kind == NodeKind::Neg);
      case NodeKind::Sub: {
        const Node& r = n.args[1];
        bool need = r.kind == NodeKind::Add || r.kind == NodeKind::Sub || r.kind == NodeKind::Neg;
        return operand(n.args[0], false) + " - " + operand(r, need);
      }
      case NodeKind::Neg: {
        const Node& a = n.args[0];
        bool need = a.kind == NodeKind::Add || a.kind == NodeKind::Sub || a.kind == NodeKind::Neg;
        return "-" + operand(a, need);
      }
      case NodeKind::Mul: return product(n);
      case NodeKind::Div: return in_text_ ? inline_term(n) : fraction(n);
      case NodeKind::Pow: return power(n);
      case NodeKind::Call: return call(n);
    }
    return {};
  }

  std::string symbol(const std::string& name) {
    if (name == "pi") return "\\pi";
    if (name == "deg") return "{}^{\\circ}";
    if (name == "oo") return "\\infty";
    if (const SymbolInfo* s = table_.find(name)) return s->tex.empty() ? default_tex_name(name) : s->tex;
    if (name == "undefined") return "\\text{undefined}";   // a limit that does not exist
    return default_tex_name(name);
  }

  // The factors of an unparenthesized product chain, in the author's order.
  static void factors(const Node& n, std::vector<const Node*>& out) {
    if (n.kind == NodeKind::Mul && !n.parenthesized) {
      factors(n.args[0], out);
      factors(n.args[1], out);
    } else {
      out.push_back(&n);
    }
  }

  // Binds like an atom when juxtaposed (no parentheses needed as a factor).
  static bool needs_group_as_factor(const Node& f, bool first) {
    if (is_call(f, "pm") || is_call(f, "mp")) return f.args.size() == 2 || !first;   // (a \pm b) c
    if (is_call(f, "dot") || is_call(f, "cross")) return true;   // b (a \cdot a)
    switch (f.kind) {
      case NodeKind::Add:
      case NodeKind::Sub: return true;
      case NodeKind::Neg: return !first;
      default: return false;
    }
  }

  // A limit or integral swallows what follows it; group it unless it is the last factor.
  static bool is_big_operator(const Node& f) {
    return !f.parenthesized && (is_call(f, "limit") || is_call(f, "integral"));
  }

  std::string join(const std::vector<const Node*>& fs) {
    std::string out;
    for (std::size_t i = 0; i < fs.size(); ++i) {
      const Node& f = *fs[i];
      bool last = i + 1 == fs.size();
      // in running text a quotient before further factors is grouped: (1/2) m v^{2}
      bool text_quotient = in_text_ && !last && f.kind == NodeKind::Div;
      std::string s = operand(f, needs_group_as_factor(f, i == 0) || (!last && is_big_operator(f)) || text_quotient);
      if (i == 0) {
        out = s;
        continue;
      }
      // 30*deg (or 30°) is 30^{\circ}: the degree sign follows its factor directly
      if (f.kind == NodeKind::Symbol && f.text == "deg" && !f.parenthesized) {
        const Node& before = *fs[i - 1];
        out += before.kind == NodeKind::Pow && !before.parenthesized ? "{}^{\\circ}" : "^{\\circ}";
        continue;
      }
      bool dot = !s.empty() && (std::isdigit(static_cast<unsigned char>(s[0])) || s[0] == '-' || s[0] == '.');
      const bool differential = is_differential_call(f, table_) && !f.parenthesized;   // u_e\,\mathrm{d}m_r
      out += dot ? " \\cdot " + s : (differential ? "\\," : " ") + s;
    }
    return out;
  }

  std::string product(const Node& n) {
    std::vector<const Node*> fs;  // n's own parentheses are the caller's business
    factors(n.args[0], fs);
    factors(n.args[1], fs);
    return join(fs);
  }

  std::string frac(const std::string& a, const std::string& b) { return "\\frac{" + a + "}{" + b + "}"; }

  // a/b. When the numerator is a product whose leading factors include a fraction, as in
  // (1 - e^2)/2*m1*m2/(m1 + m2), the author's product of fractions is kept:
  // \frac{1 - e^{2}}{2} \frac{m_1 m_2}{m_1 + m_2}.
  std::string fraction(const Node& n) {
    const Node& num = n.args[0];
    const Node& den = n.args[1];
    std::vector<const Node*> fs;
    if (!num.parenthesized) factors(num, fs);
    if (fs.size() > 1) {
      std::size_t j = fs.size();
      for (std::size_t i = 0; i < fs.size(); ++i)
        if (fs[i]->kind == NodeKind::Div && !fs[i]->parenthesized) j = i;
      if (j < fs.size() - 1) {
        std::vector<const Node*> head(fs.begin(), fs.begin() + static_cast<std::ptrdiff_t>(j + 1));
        std::vector<const Node*> rest(fs.begin() + static_cast<std::ptrdiff_t>(j + 1), fs.end());
        return join(head) + " " + frac(join(rest), top(den));
      }
    }
    // A leading minus stands before the fraction: -k/m is -\frac{k}{m}, -m1*v1/m2 is
    // -\frac{m_1 v_1}{m_2}, not \frac{-k}{m}.
    if (num.kind == NodeKind::Neg && !num.parenthesized) return "-" + frac(top(num.args[0]), top(den));
    if (fs.size() > 1 && fs[0]->kind == NodeKind::Neg && !fs[0]->parenthesized) {
      std::vector<const Node*> rest = fs;
      rest[0] = &fs[0]->args[0];
      if (!needs_group_as_factor(*rest[0], true)) return "-" + frac(join(rest), top(den));
    }
    return frac(top(num), top(den));
  }

  // Inline a/b inside an exponent.
  std::string inline_term(const Node& n) {
    if (n.kind == NodeKind::Div && (!n.parenthesized || in_text_)) {   // in text: never \frac
      const Node& a = n.args[0];
      const Node& b = n.args[1];
      bool nb = !(is_atom(b) || b.kind == NodeKind::Pow || b.kind == NodeKind::Call);
      // e^{-t/\tau}, not e^{(-t)/\tau}: a leading minus stands before the quotient
      if (a.kind == NodeKind::Neg && !a.parenthesized) {
        const Node& p = a.args[0];
        bool np = p.kind == NodeKind::Add || p.kind == NodeKind::Sub || p.kind == NodeKind::Neg;
        return "-" + inline_operand(p, np) + "/" + inline_operand(b, nb);
      }
      bool na = a.kind == NodeKind::Add || a.kind == NodeKind::Sub || a.kind == NodeKind::Neg;
      return inline_operand(a, na) + "/" + inline_operand(b, nb);
    }
    return top(n);
  }
  std::string inline_operand(const Node& n, bool need) {
    std::string b = n.kind == NodeKind::Div ? inline_term(n) : body(n);
    if (need || n.parenthesized || n.kind == NodeKind::Div) return "(" + b + ")";
    return b;
  }

  std::string power(const Node& n) {
    const Node& b = n.args[0];
    // sin(x)^2 is \sin^{2} x (\sin^{2}\frac{\theta}{2}), as textbooks write powers of functions
    if (const char* t = b.kind == NodeKind::Call && !b.parenthesized && b.args.size() == 1 ? trig_tex(b.text) : nullptr;
        t && n.args[1].kind == NodeKind::Number && !n.args[1].parenthesized &&
        n.args[1].text.find_first_not_of("0123456789") == std::string::npos) {
      const Node& a = b.args[0];
      std::string arg = bare_argument(a) || (a.kind == NodeKind::Div && !a.parenthesized && !in_text_) ? " " + top(a)
                                                                                    : "\\left(" + top(a) + "\\right)";
      return std::string(t) + "^{" + n.args[1].text + "}" + arg;
    }
    std::string base;
    if (b.kind == NodeKind::Symbol && !b.parenthesized) {
      base = symbol(b.text);
      if (base.find_first_of("'^") != std::string::npos) base = "{" + base + "}";
    } else if (b.kind == NodeKind::Number && !b.parenthesized) {
      base = b.text;
    } else if (b.kind == NodeKind::Call && !b.parenthesized && !trig_tex(b.text) && !is_call(b, "exp") &&
               !is_call(b, "limit") && !is_call(b, "integral") && !is_call(b, "diff")) {
      base = body(b);  // v(t)^2, \sqrt{x}^2, |x|^2
    } else {
      base = "\\left(" + body(b) + "\\right)";
    }
    return base + "^{" + inline_term(n.args[1]) + "}";
  }

  std::string args(const Node& n, std::size_t from = 0) {
    std::string out;
    for (std::size_t i = from; i < n.args.size(); ++i) {
      if (i > from) out += ", ";
      out += top(n.args[i]);
    }
    return out;
  }

  // One notation per quantity: a declared function at its own parameters, x(t), prints as x
  // (x(0) stays x(0)) unless another declared name prints as x too.
  bool bare_function(const Node& n) {
    const SymbolInfo* s = table_.find(n.text);
    if (!s || !s->is_function || n.args.empty() || s->params.size() != n.args.size()) return false;
    for (std::size_t i = 0; i < n.args.size(); ++i)
      if (n.args[i].kind != NodeKind::Symbol || n.args[i].parenthesized || n.args[i].text != s->params[i]) return false;
    std::string tex = symbol(n.text);
    for (const auto& o : table_.all())
      if (o.name != s->name && (o.tex.empty() ? default_tex_name(o.name) : o.tex) == tex) return false;
    return true;
  }

  // An argument a function name takes without parentheses: a symbol, a number, or a declared
  // function at its own parameters (printed as a symbol): \sin\theta for sin(theta(t)).
  bool bare_argument(const Node& a) {
    if (a.parenthesized) return false;
    return is_atom(a) || (a.kind == NodeKind::Call && !is_builtin_function(a.text) && bare_function(a));
  }

  // The "d f" of a derivative when f is a symbol or a declared function of the variable.
  bool simple_derivand(const Node& f, const Node& var, std::string* tex) {
    if (f.parenthesized) return false;
    if (f.kind == NodeKind::Symbol) {
      *tex = symbol(f.text);
      return true;
    }
    if (f.kind == NodeKind::Call && f.args.size() == 1 && f.args[0].kind == NodeKind::Symbol &&
        f.args[0].text == var.text && !is_builtin_function(f.text)) {
      *tex = symbol(f.text);
      return true;
    }
    return false;
  }

  // A side as rows no wider than `first` (the first row) and `rest` (the others): broken
  // before its top-level + and - when it is too wide, continuation rows start "&\quad + ".
  std::vector<std::string> broken_side(const Node& side, double first, double rest) {
    std::vector<std::pair<char, const Node*>> ts;
    if (!side.parenthesized) sum_terms(side, ts);
    if (ts.size() < 2) return {top(side)};
    std::vector<std::string> rows;
    std::string row;
    double w = 0, limit = first;
    for (std::size_t i = 0; i < ts.size(); ++i) {
      auto [sign, t] = ts[i];
      std::string tex;
      if (sign == 0) tex = operand(*t, false);
      else if (sign == '+') tex = "+ " + operand(*t, t->kind == NodeKind::Neg);
      else tex = "- " + operand(*t, t->kind == NodeKind::Add || t->kind == NodeKind::Sub || t->kind == NodeKind::Neg);
      double tw = width(*t) + 2.5;
      if (i > 0 && w + tw > limit) {
        rows.push_back(row);
        row = "&\\quad " + tex;
        w = 3 + tw;
        limit = rest;
        continue;
      }
      row += (i ? " " : "") + tex;
      w += tw;
    }
    rows.push_back(row);
    return rows;
  }

  static void sum_terms(const Node& n, std::vector<std::pair<char, const Node*>>& out) {
    if (!n.parenthesized && (n.kind == NodeKind::Add || n.kind == NodeKind::Sub)) {
      sum_terms(n.args[0], out);
      out.push_back({n.kind == NodeKind::Add ? '+' : '-', &n.args[1]});
      return;
    }
    out.push_back({0, &n});
  }

  std::string call(const Node& n) {
    const std::string& f = n.text;
    if ((f == "pm" || f == "mp") && (n.args.size() == 1 || n.args.size() == 2)) {   // a \pm b, \mp b
      const std::string sign = f == "pm" ? "\\pm " : "\\mp ";
      const Node& r = n.args.back();
      const bool need = r.kind == NodeKind::Add || r.kind == NodeKind::Sub || r.kind == NodeKind::Neg || is_call(r, "pm") ||
                        is_call(r, "mp");
      if (n.args.size() == 1) return sign + operand(r, need);
      return operand(n.args[0], false) + " " + sign + operand(r, need);
    }
    if (is_differential_call(n, table_)) {   // d(v): \mathrm{d}v, d(f(t)): \mathrm{d}f
      const Node& a = n.args[0];
      return "\\mathrm{d}" + (a.kind == NodeKind::Call && bare_function(a) ? symbol(a.text) : operand(a, a.kind != NodeKind::Symbol));
    }
    if (f == "sqrt" && n.args.size() == 1) return "\\sqrt{" + top(n.args[0]) + "}";
    if (f == "exp" && n.args.size() == 1) return "\\mathrm{e}^{" + inline_term(n.args[0]) + "}";
    if (f == "abs" && n.args.size() == 1) return "\\left|" + top(n.args[0]) + "\\right|";
    if (const char* t = trig_tex(f); t && n.args.size() == 1) {
      const Node& a = n.args[0];
      if (bare_argument(a)) return std::string(t) + " " + body(a);
      return std::string(t) + "\\left(" + top(a) + "\\right)";
    }
    if (f == "diff" && (n.args.size() == 2 || n.args.size() == 3)) {
      const Node& var = n.args[1];
      std::string order = n.args.size() == 3 ? "^{" + top(n.args[2]) + "}" : "";
      std::string v = top(var);
      std::string ftex;
      const Node& f0 = n.args[0];
      // \dot{x}: a declared function at its own single parameter (printed bare), order 1 or 2
      if (style_.dot_derivatives && f0.kind == NodeKind::Call && f0.args.size() == 1 && bare_function(f0) &&
          simple_derivand(f0, var, &ftex) &&
          (n.args.size() == 2 || (n.args[2].kind == NodeKind::Number && n.args[2].text == "2")))
        return std::string(n.args.size() == 2 ? "\\dot{" : "\\ddot{") + ftex + "}";
      if (simple_derivand(n.args[0], var, &ftex))
        return frac("\\mathrm{d}" + order + " " + ftex, "\\mathrm{d} " + v + order);
      return frac("\\mathrm{d}" + order, "\\mathrm{d} " + v + order) + "\\left(" + top(n.args[0]) + "\\right)";
    }
    if (f == "limit" && (n.args.size() == 3 || n.args.size() == 4)) {
      // A fourth argument (only from displayed_claim) is the side: the Symbol "+" or "-".
      const Node& g = n.args[0];
      bool need = !(is_atom(g) || g.kind == NodeKind::Div || g.kind == NodeKind::Pow ||
                    (g.kind == NodeKind::Call && !is_call(g, "limit") && !is_call(g, "integral")));
      std::string side = n.args.size() == 4 ? "^{" + n.args[3].text + "}" : "";
      return "\\lim_{" + top(n.args[1]) + " \\to " + top(n.args[2]) + side + "} " + operand(g, need);
    }
    if (f == "integral" && n.args.size() == 4) {
      const Node& g = n.args[0];
      bool need = g.kind == NodeKind::Add || g.kind == NodeKind::Sub || g.kind == NodeKind::Neg;
      return "\\int_{" + top(n.args[2]) + "}^{" + top(n.args[3]) + "} " + operand(g, need) +
             " \\, \\mathrm{d} " + top(n.args[1]);
    }
    if (f == "integral" && n.args.size() == 2) {   // indefinite
      const Node& g = n.args[0];
      bool need = g.kind == NodeKind::Add || g.kind == NodeKind::Sub || g.kind == NodeKind::Neg;
      return "\\int " + operand(g, need) + " \\, \\mathrm{d} " + top(n.args[1]);
    }
    if (f == "eval_between" && n.args.size() == 4)   // the evaluation bar [F]_a^b
      return "\\left[" + top(n.args[0]) + "\\right]_{" + top(n.args[2]) + "}^{" + top(n.args[3]) + "}";
    if (f == "vec") {   // a column vector
      std::string rows;
      for (const auto& a : n.args) rows += (rows.empty() ? "" : " \\\\ ") + top(a);
      return "\\begin{pmatrix} " + rows + " \\end{pmatrix}";
    }
    if ((f == "dot" || f == "cross") && n.args.size() == 2) {
      auto side = [&](const Node& a) { return operand(a, !is_atom(a) && !(a.kind == NodeKind::Call && a.text == "vec")); };
      return side(n.args[0]) + (f == "dot" ? " \\cdot " : " \\times ") + side(n.args[1]);
    }
    if (f == "norm" && n.args.size() == 1) return "\\left|" + top(n.args[0]) + "\\right|";
    if (is_builtin_function(f)) return "\\operatorname{" + f + "}\\left(" + args(n) + "\\right)";
    if (bare_function(n)) return symbol(f);
    return symbol(f) + "(" + args(n) + ")";
  }

 private:
  const SymbolTable& table_;
  LatexStyle style_;
  bool in_text_ = false;   // math in running text: a/b on the line, never \frac
};

// Rough printed width (in characters of output) of a side, to decide when a chain breaks.
double width(const Node& n) {
  switch (n.kind) {
    case NodeKind::Number: return static_cast<double>(n.text.size());
    case NodeKind::Symbol: return 1.5;
    case NodeKind::Add:
    case NodeKind::Sub: return width(n.args[0]) + width(n.args[1]) + 2.5 + (n.parenthesized ? 1.5 : 0);
    case NodeKind::Neg: return width(n.args[0]) + 1 + (n.parenthesized ? 1.5 : 0);
    case NodeKind::Mul: return width(n.args[0]) + width(n.args[1]) + 0.3 + (n.parenthesized ? 1.5 : 0);
    case NodeKind::Div: return std::max(width(n.args[0]), width(n.args[1])) + 0.6;
    case NodeKind::Pow: return width(n.args[0]) + 0.7 * width(n.args[1]) + (n.parenthesized ? 1.5 : 0);
    case NodeKind::Call: {
      double w = 2.5;
      if (n.text == "diff") return 3 + width(n.args[0]);
      if (n.text == "limit") return 3 + std::max(width(n.args[0]), 4.0) + width(n.args[0]) * 0 + 1;
      for (const auto& a : n.args) w += width(a) + 0.5;
      return w;
    }
  }
  return 1;
}

// Append one UTF-8 code point's LaTeX text.
bool unicode_tex(std::uint32_t cp, std::string& out) {
  struct Map { std::uint32_t cp; const char* tex; };
  static const Map kMap[] = {
      {0x2013, "--"}, {0x2014, "---"}, {0x2018, "`"}, {0x2019, "'"}, {0x201C, "``"}, {0x201D, "''"},
      {0x2026, "\\ldots{}"}, {0x2032, "$'$"}, {0x2033, "$''$"}, {0x00B7, "$\\cdot$"}, {0x00D7, "$\\times$"},
      {0x2212, "$-$"}, {0x2192, "$\\to$"}, {0x2190, "$\\leftarrow$"}, {0x21D2, "$\\Rightarrow$"},
      {0x2248, "$\\approx$"}, {0x2260, "$\\neq$"}, {0x2264, "$\\le$"}, {0x2265, "$\\ge$"},
      {0x226B, "$\\gg$"}, {0x226A, "$\\ll$"}, {0x221E, "$\\infty$"}, {0x2211, "$\\sum$"}, {0x222B, "$\\int$"},
      {0x221A, "$\\surd$"}, {0x00B1, "$\\pm$"}, {0x00B0, "$^\\circ$"}, {0x00B2, "$^2$"}, {0x00B3, "$^3$"},
      {0x00B9, "$^1$"}, {0x2070, "$^0$"}, {0x2074, "$^4$"}, {0x2080, "$_0$"}, {0x2081, "$_1$"},
      {0x2082, "$_2$"}, {0x2083, "$_3$"}, {0x00BD, "$\\frac{1}{2}$"}, {0x2153, "$\\frac{1}{3}$"},
      {0x2154, "$\\frac{2}{3}$"}, {0x00E9, "\\'e"}, {0x00E8, "\\`e"}, {0x00FC, "\\\"u"}, {0x00F6, "\\\"o"},
      {0x00E4, "\\\"a"}, {0x00A0, "~"}, {0x2009, "\\,"}, {0x2713, "$\\checkmark$"}, {0x2717, "$\\times$"},
      {0x2202, "$\\partial$"}, {0x2207, "$\\nabla$"}, {0x2206, "$\\Delta$"},
      // sections, units and typography a lecturer writes in prose
      {0x00A7, "\\S{}"}, {0x00B6, "\\P{}"}, {0x00B5, "$\\mu$"}, {0x00A9, "\\copyright{}"},
      {0x00AE, "\\textregistered{}"}, {0x2122, "\\texttrademark{}"}, {0x2022, "\\textbullet{}"},
      {0x00AD, "\\-"}, {0x2010, "-"}, {0x2011, "-"}, {0x2012, "--"}, {0x2015, "---"}, {0x2044, "/"},
      {0x201A, ","}, {0x201E, ",,"}, {0x2039, "<"}, {0x203A, ">"}, {0x00AB, "$\\ll$"}, {0x00BB, "$\\gg$"},
      {0x2002, "\\enspace{}"}, {0x2003, "\\quad{}"}, {0x202F, "\\,"}, {0x200B, ""}, {0xFEFF, ""},
      {0x00BC, "$\\frac{1}{4}$"}, {0x00BE, "$\\frac{3}{4}$"}, {0x00F7, "$\\div$"}, {0x00AC, "$\\neg$"},
      {0x2030, "\\textperthousand{}"}, {0x2103, "$^\\circ$C"}, {0x212B, "\\AA{}"}, {0x210F, "$\\hbar$"},
      {0x2113, "$\\ell$"}, {0x221D, "$\\propto$"}, {0x2261, "$\\equiv$"}, {0x2243, "$\\simeq$"},
      {0x223C, "$\\sim$"}, {0x2200, "$\\forall$"}, {0x2203, "$\\exists$"}, {0x2208, "$\\in$"},
      {0x2209, "$\\notin$"}, {0x2282, "$\\subset$"}, {0x2286, "$\\subseteq$"}, {0x222A, "$\\cup$"},
      {0x2229, "$\\cap$"}, {0x2227, "$\\wedge$"}, {0x2228, "$\\vee$"}, {0x21D4, "$\\Leftrightarrow$"},
      {0x21D0, "$\\Leftarrow$"}, {0x2194, "$\\leftrightarrow$"}, {0x2191, "$\\uparrow$"},
      {0x2193, "$\\downarrow$"}, {0x21A6, "$\\mapsto$"}, {0x2220, "$\\angle$"}, {0x22A5, "$\\perp$"},
      {0x2225, "$\\parallel$"}, {0x2016, "$\\|$"}, {0x27E8, "$\\langle$"}, {0x27E9, "$\\rangle$"},
      {0x2213, "$\\mp$"}, {0x22C5, "$\\cdot$"}, {0x2218, "$\\circ$"}, {0x2205, "$\\emptyset$"},
      {0x2211, "$\\sum$"}, {0x220F, "$\\prod$"}, {0x2032, "$'$"}, {0x03D1, "$\\vartheta$"},
      {0x03D5, "$\\phi$"}, {0x03F5, "$\\epsilon$"}, {0x03F1, "$\\varrho$"}, {0x03D6, "$\\varpi$"},
      {0x2074, "$^4$"}, {0x2075, "$^5$"}, {0x2076, "$^6$"}, {0x2077, "$^7$"}, {0x2078, "$^8$"},
      {0x2079, "$^9$"}, {0x207A, "$^+$"}, {0x207B, "$^-$"}, {0x207F, "$^n$"}, {0x2084, "$_4$"},
      {0x2085, "$_5$"}, {0x2086, "$_6$"}, {0x2087, "$_7$"}, {0x2088, "$_8$"}, {0x2089, "$_9$"},
      {0x00DF, "\\ss{}"}, {0x00E6, "\\ae{}"}, {0x00C6, "\\AE{}"}, {0x00F8, "\\o{}"}, {0x00D8, "\\O{}"},
      {0x00E5, "\\aa{}"}, {0x00C5, "\\AA{}"}, {0x0153, "\\oe{}"}, {0x0152, "\\OE{}"}, {0x0131, "\\i{}"},
      {0x0142, "\\l{}"}, {0x0141, "\\L{}"}, {0x00E7, "\\c{c}"}, {0x00C7, "\\c{C}"},
  };
  for (const auto& m : kMap)
    if (m.cp == cp) {
      out += m.tex;
      return true;
    }
  // Latin-1 letters with an accent: \'e, \"o, \~n ... (base letter and TeX accent)
  if (cp >= 0x00C0 && cp <= 0x00FF) {
    static const char kBase[] = "AAAAA___EEEEIIII_NOOOOO__UUUUY__aaaaa___eeeeiiii_nooooo__uuuuy_y";
    static const char kAcc[] = "`'^~\"___`'^\"`'^\"_~`'^~\"__`'^\"'__`'^~\"___`'^\"`'^\"_~`'^~\"__`'^\"'_\"";
    char b = kBase[cp - 0x00C0], a = kAcc[cp - 0x00C0];
    if (b != '_') {
      out += std::string("\\") + a + "{" + (b == 'i' ? std::string("\\i") : std::string(1, b)) + "}";
      return true;
    }
  }
  static const char* const kGreekLower[] = {"alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta",
                                            "theta", "iota", "kappa", "lambda", "mu", "nu", "xi", "o",
                                            "pi", "rho", "varsigma", "sigma", "tau", "upsilon", "phi",
                                            "chi", "psi", "omega"};
  static const char* const kGreekUpper[] = {"A", "B", "\\Gamma", "\\Delta", "E", "Z", "H", "\\Theta", "I",
                                            "K", "\\Lambda", "M", "N", "\\Xi", "O", "\\Pi", "P", "",
                                            "\\Sigma", "T", "\\Upsilon", "\\Phi", "X", "\\Psi", "\\Omega"};
  if (cp >= 0x03B1 && cp <= 0x03C9) {
    std::string g = kGreekLower[cp - 0x03B1];
    out += g == "o" ? "o" : "$\\" + g + "$";
    return true;
  }
  if (cp >= 0x0391 && cp <= 0x03A9 && cp != 0x03A2) {
    std::string g = kGreekUpper[cp - 0x0391];
    out += g[0] == '\\' ? "$" + g + "$" : g;
    return true;
  }
  return false;
}

std::string hex4(std::uint32_t cp) {
  static const char* d = "0123456789ABCDEF";
  std::string s;
  for (int shift = (cp > 0xFFFF ? 20 : 12); shift >= 0; shift -= 4) s += d[(cp >> shift) & 0xF];
  return s;
}

}  // namespace

std::string latex_expression(const Node& n, const SymbolTable& table, const LatexStyle& style) {
  return Writer(table, style).top(n);
}

std::string latex_inline_expression(const Node& n, const SymbolTable& table, const LatexStyle& style) {
  return Writer(table, style, true).top(n);
}

bool latex_prefers_aligned(const Relation& r, const SymbolTable& table) {
  if (r.sides.size() < 3) return false;
  double total = 0;
  for (const auto& s : r.sides) total += width(s) + 2;
  return total > 48;
}

std::string latex_relation(const Relation& r, const SymbolTable& table, bool aligned) {
  Writer w(table);
  std::string out;
  for (std::size_t i = 0; i < r.sides.size(); ++i) {
    std::string side = w.top(r.sides[i]);
    if (i == 0) out = side;
    else if (aligned) out += (i == 1 ? " &= " : " \\\\\n  &= ") + side;
    else out += " = " + side;
  }
  return out;
}

std::vector<std::string> latex_rows(const Relation& r, const SymbolTable& table, double limit,
                                    const LatexStyle& style) {
  Writer w(table, style);
  if (r.sides.size() == 1) {
    std::vector<std::string> rows = w.broken_side(r.sides[0], limit, limit - 3);
    rows[0] = "& " + rows[0];
    return rows;
  }
  double total = 0;
  for (const auto& s : r.sides) total += width(s) + 2;
  std::string lhs = w.top(r.sides[0]);
  if (total <= limit) {
    std::string row = lhs;
    for (std::size_t i = 1; i < r.sides.size(); ++i) row += (i == 1 ? " &= " : " = ") + w.top(r.sides[i]);
    return {row};
  }
  std::vector<std::string> rows;
  double lw = width(r.sides[0]) + 2;
  for (std::size_t i = 1; i < r.sides.size(); ++i) {
    std::vector<std::string> part = w.broken_side(r.sides[i], limit - lw, limit - lw - 3);
    part[0] = (i == 1 ? lhs : std::string()) + " &= " + part[0];
    for (auto& p : part) rows.push_back(std::move(p));
  }
  return rows;
}

double latex_width(const Node& n) { return width(n); }

std::string latex_escape_text(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      switch (c) {
        case '\\': out += "\\textbackslash{}"; break;
        case '{': out += "\\{"; break;
        case '}': out += "\\}"; break;
        case '$': out += "\\$"; break;
        case '&': out += "\\&"; break;
        case '#': out += "\\#"; break;
        case '^': out += "\\^{}"; break;
        case '_': out += "\\_"; break;
        case '%': out += "\\%"; break;
        case '~': out += "\\~{}"; break;
        case '<': out += "$<$"; break;
        case '>': out += "$>$"; break;
        case '|': out += "$|$"; break;
        case '\n': case '\r': case '\t': out += ' '; break;
        case '"':
        case '\'': {
          // ASCII quotes pair up: one after a space, an opening bracket or the start opens
          // (``sweet spot'', `word'); any other is a closing quote or an apostrophe (don't).
          char before = i == 0 ? ' ' : text[i - 1];
          bool opens = before == ' ' || before == '(' || before == '[' || before == '{' || before == '\n' ||
                       before == '\t' || before == '"' || before == '\'' || before == '-' || before == '/';
          if (c == '"') out += opens ? "``" : "''";
          else out += opens ? "`" : "'";
          break;
        }
        default:
          if (c >= 0x20) out += static_cast<char>(c);
      }
      ++i;
      continue;
    }
    // decode UTF-8 (invalid bytes become U+FFFD)
    std::uint32_t cp = 0xFFFD;
    std::size_t len = 1;
    if ((c & 0xE0) == 0xC0) len = 2, cp = c & 0x1F;
    else if ((c & 0xF0) == 0xE0) len = 3, cp = c & 0x0F;
    else if ((c & 0xF8) == 0xF0) len = 4, cp = c & 0x07;
    else len = 1;
    bool ok = len > 1 && i + len <= text.size();
    for (std::size_t k = 1; ok && k < len; ++k) {
      unsigned char cc = static_cast<unsigned char>(text[i + k]);
      if ((cc & 0xC0) != 0x80) ok = false;
      else cp = (cp << 6) | (cc & 0x3F);
    }
    if (!ok) { cp = 0xFFFD; len = 1; }
    if (!unicode_tex(cp, out)) out += "\\texttt{U+" + hex4(cp) + "}";
    i += len;
  }
  return out;
}

}  // namespace dc
