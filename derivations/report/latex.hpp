// LaTeX output of derivations: equations as the author wrote them.
//
// Equations are printed from the author's tree (dc::Node), so term order, grouping and the
// choice between a/b and (a/b)*c survive; symbols use their declared TeX names. The output is
// a pure function of the derivation (and, with `annotate`, of the check results): byte-identical
// across runs and processes.
//
// Constructs emitted (the reader in latex_read.hpp accepts exactly these):
//   a/b                 \frac{a}{b}   (a fraction times factors stays a product: \frac{1}{2} m v^{2})
//   a^b                 a^{b}         (braced base {v'_1}^{2} when the TeX name has ' or ^;
//                                      a fraction in an exponent is written inline: (v + g t)/u_e)
//   a*b                 a b           (a \cdot b before a digit, a minus or a fraction... see code)
//   sqrt(x)             \sqrt{x}
//   exp(x)              \mathrm{e}^{x}
//   log(x), ln(x)       \ln x, \ln\left(x + 1\right)
//   sin cos tan asin acos atan   \sin ... \arccos ...
//   abs(x)              \left|x\right|
//   diff(v(t), t)       \frac{\mathrm{d} v}{\mathrm{d} t};  diff(f, t) \frac{\mathrm{d}}{\mathrm{d} t}\left(f\right)
//   diff(f, t, 2)       \frac{\mathrm{d}^{2} v}{\mathrm{d} t^{2}}
//   diff(x(t), t[, 2])  \dot{x}, \ddot{x} with LatexStyle::dot_derivatives (`notation dot`)
//   limit(f, x, oo)     \lim_{x \to \infty} f
//   integral(f, t, a, b) \int_{a}^{b} f \, \mathrm{d} t
//   v(t)                v             (a declared function at its own parameters, when no other
//                                     name prints as v; v(0), and v(t) beside a symbol v, as written)
//   pi, oo              \pi, \infty
// A chain a = b = c is one line, or an aligned block (a &= b \\ &= c) when it is long.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "derivations/reader/derivation.hpp"
#include "derivations/syntax/expr.hpp"
#include "derivations/symbolic/printer.hpp"
#include "derivations/symbolic/symbols.hpp"

namespace dc {

struct CheckSummary;

// How quantities are written where a file may choose (`notation dot` in a .dc file).
struct LatexStyle {
  // d/dt of a declared function of one variable as \dot{x}, \ddot{x} instead of dx/dt
  bool dot_derivatives = false;
};

struct LatexOptions {
  bool fragment = false;     // no preamble / \begin{document}: pieces to \input
  bool annotate = false;     // each step on its own, a line with its rule and verdict and its notes under it
  bool units = false;        // each section lists its quantities with their units (siunitx)
  std::string title;         // document title (standalone); default: the derivation's title
  std::string subtitle;      // a line under the title (standalone), may be empty
  // Check results for `annotate` (one per derivation, same order, from dc::check_derivation);
  // when null, the margin notes give the rules without verdicts.
  const std::vector<const CheckSummary*>* checks = nullptr;
  // With `checks`: a step that did not hold (refuted, undecided, a step error) is set apart
  // with a visible mark ("NOT CHECKED: refuted") — for `latex --allow-unchecked`.
  bool mark_unchecked = false;
  // Figures drawn by the code (`derivcheck latex` fills it, numeric/charts/figure_data.hpp): the
  // picture (a pgfplots tikzpicture) that stands above a figure's caption instead of the
  // placeholder box, by the figure's Prose. When it holds any, the preamble loads pgfplots.
  const std::map<const Prose*, std::string>* drawn_figures = nullptr;
};

// Did this step hold (proved, numerically, or a premise), apart from a reported erratum?
bool step_checked_ok(const struct StepResult& r);

// A whole document (or fragment) with one section per derivation: its headings, text and
// figure placeholders in file order, the equations between them in align displays
// (latex_document.cpp).
std::string write_latex(const std::vector<const Derivation*>& derivations, const LatexOptions& opt);
std::string write_latex(const Derivation& d, const LatexOptions& opt);

// One expression / relation (no environment). `aligned`: a chain as `a &= b \\ &= c`.
std::string latex_expression(const Node& n, const SymbolTable& table, const LatexStyle& style = {});
std::string latex_relation(const Relation& r, const SymbolTable& table, bool aligned = false);
// An expression in running text (`expr` in prose): quotients on the line, a/b and
// m (r_1 v_1/s)^{2}/s, so inline math does not open the line spacing.
std::string latex_inline_expression(const Node& n, const SymbolTable& table, const LatexStyle& style = {});

// The rows of an `align` display: `lhs &= rhs` while the whole chain fits in `limit` (width
// units of latex_width, about one per printed character), otherwise one row per side
// (`&= side`), and a side wider than the line broken before its top-level + and -
// (`&\quad + term`). A lone expression is `& expr`.
std::vector<std::string> latex_rows(const Relation& r, const SymbolTable& table, double limit,
                                    const LatexStyle& style = {});
double latex_width(const Node& n);

// Would latex_relation print this chain as an aligned block in the document?
bool latex_prefers_aligned(const Relation& r, const SymbolTable& table);

// ---- Pieces of the handout every output shares (latex_document.cpp): `derivcheck html`
// puts the same TeX on its web page, so the page and the PDF cannot drift apart.

// The width of a display line in latex_width units: a standalone document (11pt on 160 mm)
// and a fragment in a plain article (10pt on 345 pt); measured with the overfull-box test.
constexpr double kLatexLineLimit = 58;
constexpr double kLatexFragmentLineLimit = 44;

// A file's section heading: "9.3.1" and "Direct central impact" (the number is empty when the
// title is numbered itself, "Example 9.4 ...", or the file gives no section).
struct HandoutHeading {
  std::string number, title;
};
HandoutHeading handout_heading(const Derivation& d);
// The document's title: `requested` (--title), else the first `handout "..."` line, else a lone
// file's title, else "Derivations".
std::string handout_title(const std::vector<const Derivation*>& ds, const std::string& requested);
LatexStyle latex_style_of(const Derivation& d);
// Is the step one of the handout's equations (not `hide`, not a stable form)?
bool step_in_handout(const Step& s);
// The rows of one step's equation as the handout displays it, no tag: the claim (the corrected
// one for an erratum, a limit step's first side as the limit it means, an order term where it
// was written) in latex_rows within `limit`, and what it holds under (as $x \to p$, to first
// order in ...) beside the last row.
std::vector<std::string> latex_step_rows(const Derivation& d, const Step& s, double limit);
// An erratum's claim as the source prints it (the footnote's "the source prints ...").
std::string latex_erratum_printed(const Derivation& d, const Step& s);
// The TeX of a $...$ piece (as written) or an `expr` piece (latex_inline_expression) of prose.
std::string latex_prose_math(const ProsePiece& p, const SymbolTable& table, const LatexStyle& style);

// Plain text for LaTeX: escapes \ { } $ & # ^ _ % ~; pairs ASCII quotes ("a" -> ``a'', 'a' ->
// `a', an apostrophe stays '); maps the Unicode a lecturer types (section sign \S, Greek
// letters, micro sign, degree, dashes, typographic quotes, primes, arrows, relations,
// super- and subscript digits, accented Latin letters) to LaTeX; any other non-ASCII character
// becomes \texttt{U+XXXX} so the document always compiles.
std::string latex_escape_text(const std::string& text);


}  // namespace dc
