// TeX math as authors write it -> the expression tree of expr.hpp (no GiNaC).
//
// The document reader (issue "check the document as its author wrote it") splits a LaTeX or
// Markdown file into displayed rows; this file reads one row of TeX math. The result uses the
// same Node tree as the .dc parser, so the same conversion, rules and reports check it.
//
// Names. A TeX name becomes one identifier ([A-Za-z][A-Za-z0-9_]*), deterministically:
//   m -> m        \theta -> theta      m_1 -> m_1       v_{1n} -> v_1n     e_{12} -> e_12
//   F_{\text{thrust}} -> F_thrust      \Delta T -> Delta_T   \Delta\mathbf{p} -> Delta_p
//   v' -> v_prime    v'_1 and v_1' -> v_1_prime    v''_{2} -> v_2_prime2
//   \dot{x} -> x_dot    \ddot{\theta} -> theta_ddot    \hat{n} -> n_hat   \bar{x} -> x_bar
//   \mathbf{v}, \vec{v}, \boldsymbol{v} -> v (and v is listed in TexRow::vector_names)
//   \mathrm{KE}, \text{KE}, \operatorname{KE} as a name -> KE
// Every name also keeps the TeX the author wrote (TexRow::tex_of), for reports.
//
// Implicit multiplication: juxtaposed factors multiply (m v, 2m_1v_1, (M+m)v_1); single
// letters never merge into a longer name (mv is m*v). f(x) is a call only when f is in
// TexContext::functions; otherwise it is f*(x).
//
// Functions: \sin \cos \tan \arcsin \arccos \arctan \sinh \cosh \tanh \ln \log \exp \sqrt,
// \sqrt[n]{x} (x^(1/n)); \sin^2 x is sin(x)^2, \sin^{-1} x is asin(x). A function written
// without parentheses takes the implicit product that follows, up to the next + - relation
// or function name (\cos\theta, \sin 2\theta, \ln\frac{m_0}{m}).
// \frac \dfrac \tfrac, \cdot \times, \left( \right) \left[ \right] \{ \}, |x| and \left|x\right|
// (abs), e^{x} (exp, when e is Euler's number: see TexContext::e_is_euler), x^\circ and
// x^{\circ} (x*deg), \pi, \infty (oo).
// Calculus: \frac{dv}{dt}, \frac{d v}{d t}, \frac{\mathrm{d}v}{\mathrm{d}t}, \frac{d^2x}{dt^2},
// \frac{d}{dt}(...), \frac{\partial f}{\partial x} -> diff(v, t[, n]) (the reader decides which
// names are functions of t); \int_a^b f\,dx and \int_a^b f\,\mathrm{d}x -> integral(f, x, a, b);
// \lim_{x\to p} f and \lim_{x\rightarrow p} f -> limit(f, x, p), where the operand is the
// implicit product after the subscript. \dot{x} and \ddot{x} are names (see above); whether
// they mean derivatives is the reader's decision.
// Not read yet (a positioned InputError saying so, never a silent guess): \pm and \mp, sums and
// products with symbolic bounds, indefinite integrals, a differential dx outside a derivative
// or an integral, matrices, cases.
//
// Ignored: \, \; \: \! \quad at the ends, \displaystyle, \left. \right., \nonumber, \notag,
// & (alignment), a final . or , after the last relation, \limits.
#pragma once
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "derivations/syntax/expr.hpp"
#include "derivations/syntax/source.hpp"

namespace dc {

enum class TexRel {
  Eq,       // =
  Approx,   // \approx \simeq \sim (as "approximately")
  Lt, Le, Gt, Ge,   // < \le \leq \leqslant > \ge \geq \geqslant
  Ne,       // \ne \neq
  Gives,    // \Rightarrow \implies \Longrightarrow, and \rightarrow \longrightarrow \to outside
            // a \lim subscript: the chain after it follows from the chain before it
};

// One chain of relations: sides[0] rel[0] sides[1] rel[1] sides[2] ...
struct TexChain {
  std::vector<Node> sides;
  std::vector<TexRel> rels;            // rels.size() == sides.size() - 1
  std::vector<SourcePos> rel_pos;      // position of each relation symbol
  // A number written with a unit, `1\,\mathrm{kg}`, `2 \text{ m/s}`: the side's unit text in
  // the .dc unit syntax ("kg", "m/s", "N/m^2"), empty when the side carries none.
  std::vector<std::string> side_units;
  bool follows_previous = false;       // preceded by a Gives relation
  bool continues = false;              // the row began with a relation (&= ...): sides[0] is
                                       // empty (kind Number, text ""); the reader takes the
                                       // previous row's last side
  bool continues_side = false;         // the row began with '+' or '-' after '&' or \quad
                                       // (`&\quad + c`): sides[0] (sign included) is the rest
                                       // of the previous row's last side, broken over rows
};

// What the parser took a token to mean, reported to the author ("e read as Euler's number").
struct TexReading {
  SourcePos pos;
  int length = 1;
  std::string message;
};

struct TexRow {
  std::vector<TexChain> chains;        // split at top-level ',' ';' \quad \qquad \text{and} and Gives
  std::string tag;                     // "9.6" from \tag{9.6}, \tag*{9.6} or a final (9.6)
  std::string label;                   // \label{eq:momentum}
  std::vector<std::string> refs;       // labels of \eqref{..} / \ref{..} inside the row
  std::vector<TexReading> readings;
  std::set<std::string> vector_names;  // names written \mathbf / \vec / \boldsymbol
  std::map<std::string, std::string> tex_of;   // identifier -> the TeX the author wrote
  bool text_only = false;              // the row holds no relation (an expression or prose)
};

// \newcommand{\name}[n]{body} and \def\name{body}: expanded before parsing (#1..#9 replaced).
struct TexMacro {
  int arity = 0;
  std::string body;
  bool has_default = false;            // \newcommand{\x}[2][d]{..}: argument 1 is optional, [d]
  std::string default_arg;
};

struct TexContext {
  std::map<std::string, TexMacro> macros;     // key without the backslash
  std::set<std::string> functions;            // identifiers written f(x) that are calls
  bool e_is_euler = true;                     // e^{x} is exp(x); else e is a symbol
  // The document also uses e as a symbol (the seed handout's coefficient of restitution, in
  // `1 - e^2`): with e_is_euler, e^2, e^{2}, e^{-1} (a plain number as the exponent) is then
  // the symbol's power and e^{...} with a letter in the exponent is exp. Each choice is a
  // TexReading.
  bool e_numeric_power_is_symbol = false;
  ParseLimits limits;
};

// Read one displayed row (no surrounding $$ or environment, no \\). `origin` is the position of
// text[0] in the document; every Node::pos and error position is computed from it (a newline in
// text starts the next line). Throws InputError at the offending token.
TexRow parse_tex_row(std::string_view text, const SourcePos& origin, const TexContext& ctx);

// One expression, no relations (a limit point, a bound).
Node parse_tex_expression(std::string_view text, const SourcePos& origin, const TexContext& ctx);

// Collect \newcommand / \renewcommand / \def definitions from a preamble (or any text) into ctx.
void read_tex_macros(std::string_view text, TexContext& ctx);

}  // namespace dc
