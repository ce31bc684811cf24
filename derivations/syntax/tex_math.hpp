// TeX math as authors write it -> the expression tree of expr.hpp (no GiNaC).
//
// The document reader (issue "check the document as its author wrote it") splits a LaTeX or
// Markdown file into displayed rows; this file reads one row of TeX math. The result uses the
// same Node tree as the .dc parser, so the same conversion, rules and reports check it.
//
// The implementation is the stage folder syntax/tex/ (lexer, names, parser, atoms, row); this
// header stays here, the contract the document reader codes against.
//
// Names. A TeX name becomes one identifier ([A-Za-z][A-Za-z0-9_]*), deterministically:
//   m -> m        \theta -> theta      m_1 -> m_1       v_{1n} -> v_1n     e_{12} -> e_12
//   F_{\text{thrust}} -> F_thrust      \Delta T -> Delta_T   \Delta\mathbf{p} -> Delta_p
//   v' -> v_prime    v'_1 and v_1' -> v_1_prime    v''_{2} -> v_2_prime2   v^{\prime} -> v_prime
//   \dot{x} -> x_dot    \ddot{\theta} -> theta_ddot    \hat{n} -> n_hat   \bar{x} -> x_bar
//   \dot{x}_1 and \dot{x_1} -> x_1_dot    x^* -> x_star    x_{\max} -> x_max
//   \mathbf{v}, \vec{v}, \boldsymbol{v}, \bm{v}, \textbf{v}, \vb{v}, {\bf v} -> v (and v is listed
//   in TexRow::vector_names)
//   \mathrm{KE}, \text{KE}, \operatorname{KE} as a name -> KE
// Order of the parts: base, _subscript, _decoration, _prime, _star. Every name also keeps the
// TeX the author wrote (TexRow::tex_of, the first spelling), for reports.
//
// Implicit multiplication: juxtaposed factors multiply (m v, 2m_1v_1, (M+m)v_1); single
// letters never merge into a longer name (mv is m*v). f(x) is a call only when f is in
// TexContext::functions; otherwise it is f*(x), and a TexReading says so ("v(t) read as the
// product v*(t); declare v a function if it is one"). A slash divides left to right
// (1/2 m v^2 is (1/2)*m*v^2), but factors written against the denominator without a space
// belong to it: v^2/2g is v^2/(2*g), reported as a TexReading.
//
// Functions: \sin \cos \tan \arcsin \arccos \arctan \sinh \cosh \tanh \ln \log \exp \sqrt,
// and \cot \sec \csc \sgn \lg \arsinh \arcosh \artanh (Call nodes named cot sec csc sgn log10
// asinh acosh atanh: the converter may not know them yet), \operatorname{sin}, \mathrm{ln};
// \sqrt[n]{x} (x^(1/n)); \sin^2 x is sin(x)^2, \sin^{-1} x is asin(x), \log_b x is log(x)/log(b).
// A function written without parentheses takes the implicit product that follows, up to the
// next + - relation or function name (\cos\theta, \sin 2\theta, \ln\frac{m_0}{m}).
// \frac \dfrac \tfrac \cfrac (\frac12 too), \cdot \times \div, \left( \right) \left[ \right]
// \{ \} \bigl( \Big[ and the other sizes, |x| \left|x\right| \lvert x\rvert \|x\| \abs{x}
// \norm{x} (abs), e^{x} and \mathrm{e}^{x} (exp, when e is Euler's number: see
// TexContext::e_is_euler), x^\circ, x^{\circ} and x° (x*deg), 5\% (5/100), \pi, \infty (oo),
// x^-1 (as TeX prints it: x^(-1)), \boxed{..} (only typesets).
// Calculus: \frac{dv}{dt}, \frac{d v}{d t}, \frac{\mathrm{d}v}{\mathrm{d}t}, \frac{\text d v}{\text d t},
// \frac{{\rm d}v}{{\rm d}t}, \frac{{dx}}{{dt}}, \frac{d^2x}{dt^2}, \frac{d}{dt}(...),
// \frac{\partial f}{\partial x}, dv/dt and d(mv)/dt, the physics package's \dv{v}{t} \dv[2]{x}{t}
// \dv{t}(..) \pdv{f}{x} -> diff(v, t[, n]) (the reader decides which names are functions of t);
// \int_a^b f\,dx, \int_a^b f\,\mathrm{d}x, \int_a^b f\,\dd{x}, \int_a^b f \cdot dx, \int_a^b dx\,f and
// \int_a^b \frac{dm}{m} -> integral(f, x, a, b) (the integrand runs to the differential);
// \lim_{x\to p} f, \lim_{x\rightarrow p} f -> limit(f, x, p), the operand being the product after
// the subscript; \sum_{i=1}^{3} f and \prod_{i=1}^{3} f with numbers as bounds (at most 100
// terms; the index is substituted in names too: m_i -> m_1) -> the terms added or multiplied;
// \left[F\right]_a^b, \Big[F\Big]_a^b, \left.F\right|_a^b -> eval_between(F, x, a, b), x being the
// variable written in the lower end ([F]_{x=a}^{b}) or else that of the row's last integral.
// \dot{x} and \ddot{x} are names (see above); whether they mean derivatives is the reader's
// decision. The ambiguous letters are reported as TexReadings: e^{..} read as exp (or, with
// e_numeric_power_is_symbol, e^2 as the symbol's power), e alone read as a symbol, d alone read
// as a symbol (a distance), v(t) read as a product, a/bc read as a/(b*c).
// Not read yet (a positioned InputError saying "... is not read yet", never a silent guess): \pm
// and \mp, sums and products with symbolic bounds or none (\sum_i^n, \sum F, \Sigma F),
// indefinite and multiple integrals, a differential dx outside a derivative or an integral
// (dv = -g\,dt), one-sided limits, an evaluation at one point F|_{x=a}, matrices and cases
// (\begin inside a row), \cdots, factorials, binomials, \nabla, \partial outside \frac, relations
// such as \gg \propto \in, \times between two vectors, a number with a unit inside an expression.
// An unknown control sequence is named in its error.
//
// A row: split into chains at top-level , ; : \quad \qquad \hfill \hspace{..}, at \text{..} holding
// prose (and, where, for t > 0, or any text with spaces), and at gives-arrows. A piece before a
// ':' holding no relation is a heading and is dropped (\sum F_t : \quad F = m a). a := b is a = b.
// \overset{(9.6)}{=} and \stackrel{..}{=} are the relation with a reference.
// Tags: \tag{9.6}, \tag*{9.6}, \text{(9.6)}, and a trailing (9.6) after \quad or \qquad (or after a
// space when it has a dot: m v (3) is a product). Labels: \label{..}; \eqref \ref \cref inside
// the row, also inside prose \text{by \eqref{..}}, go to TexRow::refs.
// Units: a side that is a number followed by \mathrm{..}, \text{..}, \si{..} holding units
// (1\,\mathrm{kg}, 2 \text{ m/s}, 9.81\,\mathrm{m\,s^{-2}}, \SI{3}{km}) -> the side is the number and
// TexChain::side_units holds "kg", "m/s", "m*s^-2".
//
// Ignored: \, \; \: \! \quad at the ends, \displaystyle, \left. \right., \nonumber, \notag,
// & (alignment), a final . , or ; after the last relation, \limits, \phantom{..}, \color{..},
// \\[2pt]. Comments (% to the end of the line) are dropped.
//
// Limits: ParseLimits::max_length (characters), max_depth (groups, parentheses and nesting,
// capped at 1000; checked by an iterative scan before any recursion), max_int_digits,
// max_tree_depth. Author macros expand at most 2000 times per row and move at most 200000
// tokens (a macro that calls itself is an error at its call).
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
  Eq,       // =  \equiv  \coloneqq  \doteq  :=
  Approx,   // \approx \simeq \sim \thickapprox (as "approximately")
  Lt, Le, Gt, Ge,   // < \lt \le \leq \leqslant > \gt \ge \geq \geqslant
  Ne,       // \ne \neq
  Gives,    // \Rightarrow \implies \Longrightarrow \therefore \iff \Leftrightarrow
            // \Longleftrightarrow \mapsto \leadsto, and \rightarrow \longrightarrow \to outside a
            // \lim subscript: the chain after it follows from the chain before it (a Gives never
            // appears in TexChain::rels: it splits the row, see follows_previous)
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

// \newcommand{\name}[n]{body}, \newcommand{\name}[n][default]{body}, \renewcommand,
// \providecommand, \DeclareMathOperator{\name}{text} and \def\name#1#2{body}: expanded before
// parsing (#1..#9 replaced); the expansion takes the position of the call.
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
