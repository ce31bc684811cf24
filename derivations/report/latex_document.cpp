// LaTeX documents (see latex.hpp): sections, the author's text and the equations between it.
//
// Layout: each file is a section; its headings, paragraphs, remarks and figure placeholders
// (Derivation::prose) stand where the author put them, and the steps between two pieces of
// text share one `align` display, every chain aligned on its first '=' (latex_rows breaks long
// chains and sums). An erratum step stands in an equation of its own (a footnote mark inside
// `align` would be counted twice). With `annotate`, every step gets its own display followed
// by a small line with its label, rule and verdict, and its notes; hidden and stable steps are
// shown there too.
#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "derivations/report/latex.hpp"
#include "derivations/rules/check.hpp"

namespace dc {
namespace {

std::string basename_of(const std::string& path) {
  auto s = path.find_last_of('/');
  return s == std::string::npos ? path : path.substr(s + 1);
}

// What the handout shows for a step: a `by limit x -> p` step without `of` states
// "f = L" meaning "f -> L as x -> p", so its first side is shown as the limit it means.
Relation with_order_term(const Step& s, const Relation& claim);

Relation displayed_claim(const Step& s, const Relation& claim_in) {
  const Relation claim = with_order_term(s, claim_in);
  if (s.rule.name != "limit" || !s.rule.into.empty() || claim.sides.size() < 2 || !s.rule.var || !s.rule.point)
    return claim;
  const Node& f = claim.sides[0];
  if (f.kind == NodeKind::Call && f.text == "limit") return claim;
  Relation shown = claim;
  Node lim;
  lim.kind = NodeKind::Call;
  lim.text = "limit";
  lim.pos = f.pos;
  lim.args = {f, s.rule.var->value, s.rule.point->value};
  if (s.rule.dir != 0) {
    Node side;
    side.kind = NodeKind::Symbol;
    side.text = s.rule.dir > 0 ? "+" : "-";
    lim.args.push_back(side);
  }
  shown.sides[0] = std::move(lim);
  return shown;
}

// A series step's order term, taken off the claim by the reader, is printed where it was written.
Relation with_order_term(const Step& s, const Relation& claim) {
  if (!s.order_term || claim.sides.empty()) return claim;
  Relation shown = claim;
  Node o;
  o.kind = NodeKind::Call;
  o.text = "O";
  o.pos = s.order_term->pos;
  o.args = {*s.order_term};
  Node& last = shown.sides.back();
  if (last.kind == NodeKind::Number && last.text == "0") {
    last = o;
  } else {
    Node sum;
    sum.kind = NodeKind::Add;
    sum.pos = last.pos;
    sum.args = {last, o};
    last = std::move(sum);
  }
  return shown;
}

std::string verdict_text(const StepResult& r) {
  if (r.premise && r.verdict.holds()) return "$\\bullet$ premise";
  std::string s;
  switch (r.verdict.kind) {
    case VerdictKind::Proved:
    case VerdictKind::HoldsNumerically: s = "$\\checkmark$ "; break;
    case VerdictKind::Refuted: s = "$\\times$ "; break;
    case VerdictKind::Undecided: s = "? "; break;
  }
  s += verdict_words(r.verdict.kind);
  if (!r.verdict.method.empty()) s += " (" + latex_escape_text(r.verdict.method) + ")";
  return s;
}

std::string rule_text(const Step& s) {
  if (!s.rule.text.empty()) {
    std::string t = s.rule.text;
    if (t.rfind("by ", 0) == 0) t = t.substr(3);
    return t;
  }
  return s.rule.written_name.empty() ? s.rule.name : s.rule.written_name;
}

std::string prose_tex(const std::vector<ProsePiece>& pieces, const SymbolTable& table, const LatexStyle& style) {
  std::string out;
  for (const auto& p : pieces) {
    switch (p.kind) {
      case ProsePiece::Kind::Text: out += latex_escape_text(p.text); break;
      case ProsePiece::Kind::Emph:
        out += "\\emph{" + (p.inner.empty() ? latex_escape_text(p.text) : prose_tex(p.inner, table, style)) + "}";
        break;
      case ProsePiece::Kind::Math:
      case ProsePiece::Kind::Expr: out += "$" + latex_prose_math(p, table, style) + "$"; break;
    }
  }
  return out;
}

class DocumentWriter {
 public:
  explicit DocumentWriter(const LatexOptions& o) : opt_(o) {}

  std::string section(const Derivation& d, const CheckSummary* checks) {
    std::string out;
    file_ = basename_of(d.source.name);
    const HandoutHeading heading = handout_heading(d);
    std::string shown = latex_escape_text(heading.title);
    if (!heading.number.empty()) shown = latex_escape_text(heading.number) + "\\quad " + shown;
    out += "% ---- " + file_ + "\n";
    out += "\\section*{" + shown + "}\n";
    out += "\\addcontentsline{toc}{section}{" + shown + "}\n\n";
    if (opt_.units) out += quantities(d);
    std::vector<const Step*> run;   // consecutive steps of one display
    auto flush = [&] {
      if (!run.empty()) out += display(d, run);
      run.clear();
    };
    std::size_t next_prose = 0;
    auto prose_before = [&](std::size_t step_index) {
      while (next_prose < d.prose.size() && d.prose[next_prose].before_step <= step_index) {
        flush();
        out += prose(d.prose[next_prose++], d.symbols, style_of(d));
      }
    };
    for (std::size_t i = 0; i < d.steps.size(); ++i) {
      prose_before(i);
      const Step& s = d.steps[i];
      const StepResult* r = checks && i < checks->results.size() ? &checks->results[i] : nullptr;
      // Stable rewrites (for computing) and hidden helper steps are not handout equations;
      // --annotate shows them with the rest.
      if (!step_in_handout(s) && !opt_.annotate) continue;
      bool unchecked = opt_.mark_unchecked && r && !step_checked_ok(*r);
      if (opt_.annotate || s.erratum) {
        flush();
        out += single(d, s, r);
        continue;
      }
      if (unchecked) {
        flush();
        out += single(d, s, r);
        continue;
      }
      run.push_back(&s);
    }
    prose_before(d.steps.size());
    flush();
    return out;
  }

  // Does every name in n have a known dimension (declared, or defined from such names)?
  static bool dimension_known(const Node& n, const SymbolTable& t) {
    if (n.kind == NodeKind::Symbol) {
      const SymbolInfo* s = t.find(n.text);
      return n.text == "pi" || (s && s->has_dimension);
    }
    if (n.kind == NodeKind::Call && !is_builtin_function(n.text)) {
      const SymbolInfo* s = t.find(n.text);
      if (!s || !s->has_dimension) return false;
    }
    for (const auto& a : n.args)
      if (!dimension_known(a, t)) return false;
    return true;
  }

  // "Quantities." with each quantity's unit, quantities of one unit together, in the order
  // they are declared or defined: $m_1$, $m_2$ in \si{kg}; $v_1$ in \si{m/s}; dimensionless: $e$.
  // A name introduced by a step (a definition, a named result) is listed with the dimension
  // the checker infers for it, when every name in its defining expression has a known one.
  static std::string quantities(const Derivation& d) {
    std::vector<std::pair<std::string, std::vector<std::string>>> groups;   // unit -> TeX names
    for (const SymbolInfo& s : d.symbols.all()) {
      if (!s.has_dimension || s.is_differential) continue;
      if (s.defined_by_step) {
        const Step* def = nullptr;
        for (const Step& st : d.steps)
          if (!def && st.claim.sides.size() >= 2 &&
              (st.claim.sides[0].kind == NodeKind::Symbol || st.claim.sides[0].kind == NodeKind::Call) &&
              st.claim.sides[0].text == s.name)
            def = &st;
        if (!def || !dimension_known(def->claim.sides[1], d.symbols)) continue;
      }
      // the unit as the author wrote it ([N*s], [rad/s]) when it names units; otherwise the
      // dimension in base units ([momentum] is kg.m/s)
      std::string unit = !s.unit.empty() ? siunitx_unit(s.unit)
                             : s.dimension.dimensionless() ? std::string() : siunitx_unit(s.dimension.to_ascii());
      auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& x) { return x.first == unit; });
      if (g == groups.end()) groups.push_back({unit, {}}), g = groups.end() - 1;
      std::string name = "$" + (s.tex.empty() ? default_tex_name(s.name) : s.tex) + "$";
      // a function and the symbol standing for its value share a TeX name (m_r(t), m_r): once
      if (std::find(g->second.begin(), g->second.end(), name) == g->second.end()) g->second.push_back(name);
    }
    if (groups.empty()) return {};
    std::string out = "\\paragraph*{Quantities.}";
    std::string dimensionless;
    bool first = true;
    for (const auto& [unit, names] : groups) {
      std::string list;
      for (std::size_t i = 0; i < names.size(); ++i) list += (i ? ", " : "") + names[i];
      if (unit.empty()) {
        dimensionless = list;
        continue;
      }
      out += (first ? " " : "; ") + list + " in \\si{" + unit + "}";
      first = false;
    }
    if (!dimensionless.empty()) out += (first ? " dimensionless: " : "; dimensionless: ") + dimensionless;
    return out + ".\n\n";
  }

  // An exponent "p/q" as siunitx prints it: a half as a decimal (3/2: 1.5, -1/2: -0.5),
  // other fractions as written (1/3); an integer unchanged.
  static std::string fraction_exponent(const std::string& e) {
    const std::size_t slash = e.find('/');
    if (slash == std::string::npos) return e;
    if (e.substr(slash + 1) != "2") return e;
    const std::string p = e.substr(0, slash);
    const bool neg = !p.empty() && p[0] == '-';
    const long whole = std::labs(std::stol(p)) / 2;   // p is odd: the fraction is reduced
    return (neg ? "-" : "") + std::to_string(whole) + ".5";
  }

  // "kg*m/s^2" (Dimension::to_ascii, or the unit as written: "N*s", "m^(-1/2)") in siunitx's
  // literal form: kg.m/s^{2}; m^(1/2): m^{0.5}.
  static std::string siunitx_unit(const std::string& ascii) {
    // the derived units a handout writes (energy and torque share J's dimension)
    if (ascii == "kg*m^2/s^2") return "J";
    if (ascii == "kg*m/s^2") return "N";
    if (ascii == "kg*m^2/s^3") return "W";
    if (ascii == "kg/(m*s^2)") return "Pa";
    std::string out;
    for (std::size_t i = 0; i < ascii.size(); ++i) {
      char c = ascii[i];
      if (c == '*') {
        out += '.';
      } else if (c == '^') {
        std::size_t j = i + 1;
        std::string e;
        if (j < ascii.size() && ascii[j] == '(') {
          std::size_t close = ascii.find(')', j);
          e = fraction_exponent(ascii.substr(j + 1, close - j - 1));
          i = close;
        } else {
          while (j < ascii.size() && (std::isdigit(static_cast<unsigned char>(ascii[j])) || ascii[j] == '-')) e += ascii[j++];
          i = j - 1;
        }
        out += "^{" + e + "}";
      } else {
        out += c;
      }
    }
    return out;
  }

  std::string preamble(const std::string& title) {
    std::string out;
    out += "% Generated by derivcheck latex. Do not edit: regenerate from the .dc files.\n";
    out += "\\documentclass[11pt,a4paper]{article}\n";
    out += "\\usepackage{amsmath,amssymb}\n\\allowdisplaybreaks\n";
    if (opt_.units) out += "\\usepackage{siunitx}\n";
    if (draws_figures()) out += "\\usepackage{pgfplots}\n\\pgfplotsset{compat=1.18}\n";
    out += "\\usepackage[margin=25mm]{geometry}\n";
    out += "\\setlength{\\parindent}{0pt}\n\\setlength{\\parskip}{5pt plus 1pt}\n\\setlength{\\jot}{5pt}\n";
    out += "\\title{" + latex_escape_text(title) + "}\n";
    out += "\\author{}\n\\date{" + (opt_.subtitle.empty() ? std::string() : latex_escape_text(opt_.subtitle)) + "}\n";
    out += "\\begin{document}\n\\maketitle\n\n";
    return out;
  }

  std::string fragment_header() const {
    return std::string("% Generated by derivcheck latex --fragment. Needs \\usepackage{amsmath,amssymb}") +
           (opt_.units ? ", \\usepackage{siunitx}" : "") +
           (draws_figures() ? ", \\usepackage{pgfplots} (\\pgfplotsset{compat=1.18})" : "") + " in the host.\n\\begingroup\\allowdisplaybreaks\n\n";
  }
  static std::string fragment_footer() { return "\\endgroup\n"; }

  // The rows of a step's equation (latex_step_rows).
  static std::vector<std::string> step_rows(const Derivation& d, const Step& s, double limit) {
    const Relation claim = displayed_claim(s, s.erratum ? s.erratum->corrected : s.claim);
    const std::string cond = s.erratum ? std::string() : condition(d, s);
    std::vector<std::string> rs = latex_rows(claim, d.symbols, limit - (cond.empty() ? 0 : 18), style_of(d));
    if (!cond.empty()) rs.back() += cond;
    return rs;
  }

 private:
  const LatexOptions& opt_;
  bool draws_figures() const { return opt_.drawn_figures && !opt_.drawn_figures->empty(); }
  std::string file_;

  // Width of a display line in latex_width units: 11pt on 160 mm (standalone), 10pt on
  // 345 pt (a plain article hosting the fragment). Measured with the overfull-box test.
  double line_limit() const { return opt_.fragment ? kLatexFragmentLineLimit : kLatexLineLimit; }

  std::string comment(const Step& s) const {
    return "% " + s.label + " (" + file_ + ":" + std::to_string(s.pos.line) + ")\n";
  }

  static LatexStyle style_of(const Derivation& d) { return latex_style_of(d); }

  std::string prose(const Prose& p, const SymbolTable& table, const LatexStyle& style) {
    switch (p.kind) {
      case Prose::Kind::Heading: return "\\subsection*{" + prose_tex(p.pieces, table, style) + "}\n\n";
      case Prose::Kind::Paragraph: return prose_tex(p.pieces, table, style) + "\n\n";
      case Prose::Kind::Remark: return "\\paragraph*{Remark.} " + prose_tex(p.pieces, table, style) + "\n\n";
      case Prose::Kind::Figure:
        if (opt_.drawn_figures) {
          auto it = opt_.drawn_figures->find(&p);
          if (it != opt_.drawn_figures->end())
            // a minipage keeps the picture and its caption on one page
            return "\\begin{center}\n\\begin{minipage}{\\linewidth}\n\\centering\n" + it->second +
                   "\\\\[1ex]\n\\parbox{0.8\\linewidth}{\\centering\\textit{Figure:} " + prose_tex(p.pieces, table, style) +
                   "}\n\\end{minipage}\n\\end{center}\n\n";
        }
        return "\\begin{center}\n\\fbox{\\parbox{0.8\\linewidth}{\\centering\\vspace{3ex}"
               "\\textit{Figure:} " + prose_tex(p.pieces, table, style) + "\\vspace{3ex}}}\n\\end{center}\n\n";
    }
    return {};
  }

  // What a step's equation holds under, when its rule says so and the equation does not show
  // it: `by limit x -> p of A` (the equation is A's limit, not A: "(as $x \to p$, with $v_2 =
  // 0$)"), `by first_order dm, dv of A` ("(to first order in $dm$, $dv$)"), `by series x -> p
  // of A` without an order term ("(series as $x \to p$)"). Typeset beside the last row, so a
  // student does not read the special case as a contradiction of the general formula.
  static std::string condition(const Derivation& d, const Step& s) {
    const RuleSpec& r = s.rule;
    auto tex = [&](const Node& n) { return latex_inline_expression(n, d.symbols, style_of(d)); };
    auto approach = [&] {
      std::string side = r.dir > 0 ? "^{+}" : r.dir < 0 ? "^{-}" : "";
      return "$" + tex(r.var->value) + " \\to " + tex(r.point->value) + side + "$";
    };
    std::string out;
    if (r.name == "limit" && !r.into.empty() && r.var && r.point) {
      // a chain that already shows the limit (v = lim_{m2 -> oo} ... = -v1) needs only the `with`
      bool shown = false;
      for (const Node& side : s.claim.sides)
        shown = shown || (side.kind == NodeKind::Call && side.text == "limit" && side.args.size() >= 2 &&
                          to_text(side.args[1]) == to_text(r.var->value));
      out = shown ? "" : "as " + approach();
      for (std::size_t i = 0; i < r.with.size(); ++i) {
        const Relation& w = r.with[i].equation;
        std::string eq;
        for (std::size_t k = 0; k < w.sides.size(); ++k) eq += (k ? " = " : "") + tex(w.sides[k]);
        out += (i == 0 ? (out.empty() ? "with $" : ", with $") : ", $") + eq + "$";
      }
    } else if (r.name == "first_order" && !r.smalls.empty()) {
      out = "to first order in ";
      for (std::size_t i = 0; i < r.smalls.size(); ++i) out += (i ? ", $" : "$") + tex(r.smalls[i].value) + "$";
    } else if (r.name == "series" && !r.into.empty() && !s.order_term && r.var && r.point) {
      out = "series as " + approach();
    }
    return out.empty() ? out : "\\qquad\\text{(" + out + ")}";
  }

  // The rows of a step in an align (tag on its last row).
  std::string rows(const Derivation& d, const Step& s, const std::string& last_extra = {}) {
    const std::vector<std::string> rs = step_rows(d, s, line_limit());
    std::string out;
    for (std::size_t i = 0; i < rs.size(); ++i) {
      bool last = i + 1 == rs.size();
      out += rs[i];
      if (last) {
        out += last_extra;
        out += s.tag.empty() ? " \\notag" : " \\tag{" + latex_escape_text(s.tag) + "}";
      } else {
        out += " \\notag \\\\\n";
      }
    }
    return out;
  }

  // Consecutive steps in one align display.
  std::string display(const Derivation& d, const std::vector<const Step*>& steps) {
    std::string out = "\\begin{align}\n";
    for (std::size_t i = 0; i < steps.size(); ++i) {
      out += comment(*steps[i]);
      out += rows(d, *steps[i]);
      out += i + 1 < steps.size() ? " \\\\\n" : "\n";
    }
    return out + "\\end{align}\n\n";
  }

  // A step on its own: an erratum (footnote), a step marked NOT CHECKED, every annotated step.
  std::string single(const Derivation& d, const Step& s, const StepResult* r) {
    std::string extra;
    if (s.erratum) extra += "\\qquad\\text{(erratum\\footnotemark)}";
    if (opt_.mark_unchecked && r && !step_checked_ok(*r))
      extra += "\\qquad\\text{\\textbf{NOT CHECKED: " + latex_escape_text(std::string(to_string(r->verdict.kind))) +
               (r->verdict.holds() ? " with errors" : "") + "}}";
    std::string out = comment(s);
    if (s.erratum) {
      // equation + aligned: the footnote mark is typeset once
      std::vector<std::string> rs = step_rows(d, s, line_limit() - 12);
      out += s.tag.empty() ? "\\begin{equation*}\n" : "\\begin{equation}\n";
      out += "\\begin{aligned}\n";
      for (std::size_t i = 0; i < rs.size(); ++i) out += rs[i] + (i + 1 < rs.size() ? " \\\\\n" : "\n");
      out += "\\end{aligned}" + extra;
      if (!s.tag.empty()) out += "\n\\tag{" + latex_escape_text(s.tag) + "}";
      out += s.tag.empty() ? "\n\\end{equation*}\n" : "\n\\end{equation}\n";
      out += "\\footnotetext{Corrected: the source prints $" + latex_erratum_printed(d, s) + "$; " + latex_escape_text(s.erratum->why) +
             ".}\n";
    } else {
      out += "\\begin{align}\n" + rows(d, s, extra) + "\n\\end{align}\n";
    }
    if (opt_.annotate) out += annotation(s, r);
    return out + "\n";
  }

  // The line under an annotated step: label, rule, verdict; then the step's notes.
  std::string annotation(const Step& s, const StepResult* r) {
    std::string a = "{\\footnotesize\\raggedright\\noindent\\texttt{" + latex_escape_text(s.label) + "}: by " +
                    latex_escape_text(rule_text(s));
    if (r) a += " \\quad " + verdict_text(*r);
    if (s.hidden) a += " \\quad (hidden in the handout)";
    if (s.stable_of) a += " \\quad (stable form, hidden in the handout)";
    a += "\\par}\n";
    for (const auto& n : s.notes) a += "{\\footnotesize\\itshape " + latex_escape_text(n) + "\\par}\n";
    return a;
  }
};

}  // namespace

bool step_checked_ok(const StepResult& r) {
  std::size_t own = r.errors.size() - (r.erratum_reported ? 1 : 0);
  return own == 0 && r.verdict.holds();
}

std::string latex_prose_math(const ProsePiece& p, const SymbolTable& table, const LatexStyle& style) {
  if (p.kind == ProsePiece::Kind::Math) return p.text;
  std::string out = latex_inline_expression(p.expr, table, style);
  for (const auto& side : p.more) out += " = " + latex_inline_expression(side, table, style);
  return out;
}

HandoutHeading handout_heading(const Derivation& d) {
  HandoutHeading h;
  h.title = d.title.empty() ? basename_of(d.source.name) : d.title;
  const bool numbered_title = !h.title.empty() && (std::isdigit(static_cast<unsigned char>(h.title[0])) ||
                                                   h.title.rfind("Example", 0) == 0);
  if (!numbered_title) h.number = d.section;
  return h;
}

std::string handout_title(const std::vector<const Derivation*>& ds, const std::string& requested) {
  // --title, else the first file's `handout "..."` line, else a lone file's title
  std::string title = requested;
  for (const Derivation* d : ds)
    if (title.empty()) title = d->handout;
  if (title.empty()) title = ds.size() == 1 ? ds[0]->title : "Derivations";
  return title;
}

LatexStyle latex_style_of(const Derivation& d) {
  LatexStyle st;
  st.dot_derivatives = d.dot_derivatives;
  return st;
}

bool step_in_handout(const Step& s) { return !s.stable_of && !s.hidden; }

std::vector<std::string> latex_step_rows(const Derivation& d, const Step& s, double limit) {
  return DocumentWriter::step_rows(d, s, limit);
}

std::string latex_erratum_printed(const Derivation& d, const Step& s) {
  std::string text;
  for (std::size_t i = 0; i < s.claim.sides.size(); ++i)
    text += (i ? " = " : "") + latex_expression(s.claim.sides[i], d.symbols, latex_style_of(d));
  return text;
}

std::string write_latex(const std::vector<const Derivation*>& ds, const LatexOptions& opt) {
  DocumentWriter w(opt);
  std::vector<const CheckSummary*> checks(ds.size(), nullptr);
  if ((opt.annotate || opt.mark_unchecked) && opt.checks) {
    if (opt.checks->size() != ds.size())
      throw std::invalid_argument("write_latex: one check summary per derivation is needed");
    checks = *opt.checks;
  }
  std::string out;
  if (opt.fragment) {
    out += w.fragment_header();
  } else {
    out += w.preamble(handout_title(ds, opt.title));
  }
  for (std::size_t i = 0; i < ds.size(); ++i) out += w.section(*ds[i], checks[i]);
  out += opt.fragment ? w.fragment_footer() : "\\end{document}\n";
  return out;
}

std::string write_latex(const Derivation& d, const LatexOptions& opt) {
  std::vector<const Derivation*> v{&d};
  return write_latex(v, opt);
}

}  // namespace dc
