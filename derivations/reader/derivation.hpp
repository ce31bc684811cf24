// A derivation: symbols, assumptions and labelled steps, read from a .dc file (docs/format.md).
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/syntax/expr.hpp"
#include "derivations/syntax/prose.hpp"
#include "derivations/syntax/source.hpp"
#include "derivations/symbolic/symbols.hpp"

namespace dc {

// One `x = value` substitution or label reference in a rule's argument list.
struct RuleArg {
  enum class Kind { Label, Equation, Symbol, Value } kind = Kind::Label;
  std::string label;         // Label: the referenced step; Symbol: the name
  Relation equation;         // Equation: inline `x = value`
  Node value;                // Value: e.g. a limit point or lower bound
  SourcePos pos;
  int length = 1;
  int prime_order = 0;       // Equation `y'(T0) = v0` (1), `y''(T0) = a0` (2): a derivative's value
};

// The rule line: `by NAME ...` parsed into named argument groups. Which groups exist depends
// on the rule (see docs/format.md): refs (labels before the first keyword), and the groups
// introduced by the keywords `for`, `into`, `of`, `with`, `wrt`, `from`, `->`.
struct RuleSpec {
  std::string name;          // canonical: given, definition, rewrite, substitute, solve, limit,
                             // first_order, series, differentiate, integrate, solves_ode
  std::string written_name;  // as written (simplify, expand, factor, algebra are rewrite)
  std::vector<RuleArg> refs;     // labels or inline equations before any keyword
  std::vector<RuleArg> unknowns; // `for x, y`
  std::vector<RuleArg> into;     // `into C` / `of A`: the main referenced step
  std::vector<RuleArg> with;     // `with x = value, y(0) = value`
  std::optional<RuleArg> var;    // `limit x -> p` / `series x -> p` / `wrt t`
  std::optional<RuleArg> point;  // `-> p`, `from T0`
  int dir = 0;                   // `-> p+` (+1, from above), `-> p-` (-1, from below), else 0
  std::optional<int> order;      // `by series ... to order N`: the claim holds up to O((x - p)^N)
  std::vector<RuleArg> smalls;   // `first_order d1, d2 of A`
  SourcePos pos;
  std::string text;
};

struct Erratum {
  std::string why;
  Relation corrected;
  std::string corrected_text;
  SourcePos pos;
};

// A step read from an author's LaTeX or Markdown document (derivations/document/): the author
// wrote no rule; the checker searches for one. What the search may use and must respect.
struct DocumentRow {
  int link = 0;                     // 0: the row's only relation; 1, 2, ...: its relations in order
  int display = 0;                  // which displayed equation of the document it is in (0, 1, ...)
  std::string relation = "=";       // "=", "approx", "<", "<=", ">", ">=", "!=", "inline" (a given
                                    // written in the prose)
  std::vector<std::string> nearby;  // labels of earlier steps the search may cite, nearest first
  std::vector<std::string> locals;  // labels of the inline givens in force for this row
  std::vector<std::string> fresh;   // those of them written in the text just before this display
                                    // (the others carry over from the displays before it)
  std::vector<std::string> earlier; // inline givens of the same section before it that are not
                                    // in force here and that no later text re-gives or bounds
                                    // (`$T_1 = T_2$` paragraphs before): a refutation that they
                                    // would undo is withheld
  std::vector<std::string> where;   // inline givens of the text right after the display that
                                    // define its names ("where $\mu = m_1/m_2$")
  std::vector<std::string> cited;   // labels the author cites (\eqref, "(9.6)") before or in the row
  std::string hint;                 // words of the prose before the display ("substitut", "integrat")
  std::string not_read;             // non-empty: why the row is not checked (notation not read yet)
  std::string unread_sets;          // such a row's left side, when it parsed as a name (`W = \int …`)
  std::vector<std::string> vectors; // names written bold or with an arrow
  bool authors_rule = false;        // the author wrote the rule (`% by …`): checked as a .dc step
};

struct Step {
  std::string label;
  std::string tag;           // "9.6" (without parentheses), may be empty
  Relation claim;
  std::string claim_text;    // as written (whitespace-normalised)
  SourcePos pos;             // of the label
  SourcePos claim_pos;       // of the claim's first character
  RuleSpec rule;
  std::vector<std::string> notes;
  std::string tex;           // `tex "\omega_n"`: the TeX name of the name this step introduces
  SourcePos tex_pos;
  std::optional<Erratum> erratum;
  std::optional<std::string> stable_of;   // `stable LABEL "regime"`
  // The claim is a chain `NAME = E1 = E2 ...` whose NAME (a declared symbol, or a declared
  // function applied to its own parameters, `V(t)`) appears in no earlier step: the step names
  // E1 (NAME is defined as E1 for the steps after it, as by `definition`) and checks the rest
  // of the chain with its rule (`V(t) = diff(X(t), t) = A*omega*cos(omega*t)`).
  bool names_result = false;
  std::string stable_regime;
  bool hidden = false;       // `hide`: checked, but left out of the handout (--annotate shows it)
  // `by series`: the claim's last side ended in an order term, `x - x^3/6 + O(x^5)`; the term
  // was taken off the claim (it gives rule.order) and is kept here for printing.
  std::optional<Node> order_term;
  // The first side is a declared name that no earlier step mentions (and the step does not
  // introduce it): nothing but this claim speaks of it, so a refutation says how to define it.
  bool first_side_fresh = false;
  // Positioned warnings and notes about this step that stop nothing: a premise that mentions a
  // name an earlier step's named result bound (the premise then speaks of that value).
  std::vector<InputError> diagnostics;
  std::optional<DocumentRow> document_row;   // set for a step read from a document
};


struct Derivation {
  SourceText source;
  std::string title;
  std::string handout;       // `handout "..."`: the title of the document `latex` makes of the files
  std::string section;
  SymbolTable symbols;
  std::vector<Step> steps;
  std::vector<Prose> prose;  // in file order
  bool dot_derivatives = false;   // `notation dot`: the LaTeX writes d/dt of x(t) as \dot{x}
  // Positioned warnings about the file's declarations that stop nothing (an assumption whose
  // sides have different dimensions); a step's own are in Step::diagnostics.
  std::vector<InputError> diagnostics;

  const Step* find(const std::string& label) const;

  // Built by index() (parse_derivation calls it): label -> step, and the steps `by definition`
  // by the name they define, so lookups cost O(log n) and checking stays linear in the number
  // of steps. A derivation built by hand is indexed on first use only if index() is called;
  // otherwise lookups scan the steps.
  void index();
  std::map<std::string, std::size_t> label_index;
  std::map<std::string, std::size_t> definition_index;
  bool indexed = false;
};

// Read and parse a .dc file. Structural errors (syntax, duplicate labels, unknown rule,
// references to labels not defined earlier, malformed declarations, empty domains) throw
// InputError with position. Symbol use is resolved here too: undeclared symbols in claims are
// InputErrors — except inside a step with an `erratum`, where the error is kept for the
// checker to report (see Step::erratum) and the corrected claim is used.
Derivation load_derivation(const std::string& path);
Derivation parse_derivation(SourceText source);

// The rule line of one step written by another front end (a document's `% by solve (9.6),
// (9.7) for v_1p` comment, in .dc notation after its refs and names are translated): read as
// the .dc reader reads `by …` for steps[index] of d, against the steps before it and the
// declared names. `text` is what follows "by"; `pos` is where it starts. Throws InputError.
RuleSpec read_rule_line(const Derivation& d, std::size_t index, const std::string& text, const SourcePos& pos);
// A rule as its .dc line: `by solve L5, L6 for v1p, v2p`, `by limit b -> oo of L3` (the
// inverse of the reader's rule line, for rules built by a program).
std::string rule_line_text(const RuleSpec& r);
// Is `name` a rule of the .dc language (or an alias of rewrite)?
bool is_rule_name(const std::string& name);

// A whole side of a `by limit` claim that states what no expression can: `oo`, `-oo`, or
// `undefined` (the limit does not exist; a declared symbol of that name keeps its meaning).
// Such a side has no dimension, side conditions or GiNaC form; the limit rule reads it.
bool limit_value_word(const Node& side, const SymbolTable& symbols);
bool limit_value_side(const Step& s, const Node& side, const SymbolTable& symbols);

// For an erratum step: the InputError the printed claim raises (nullopt if none).
std::optional<InputError> erratum_error(const Derivation& d, const Step& s);

// The step introduces the name on its first side for the steps after it: a `definition`, or a
// named result (Step::names_result). The name's value is the second side.
bool introduces_name(const Step& s);

// Definition steps act as abbreviations: every use of a name introduced by `by definition`
// (NEW or NEW(t)) is replaced by its defining expression (parameters substituted).
// (additive: engineer "checker")
Node resolve_definitions(const Derivation& d, const Node& n);
// n with each symbol named in `values` replaced by its value (parenthesized).
Node substitute_names(const Node& n, const std::map<std::string, const Node*>& values);
// to_ginac of resolve_definitions(d, n) with the derivation's symbol table.
GiNaC::ex resolved_ginac(const Derivation& d, const Node& n);

// The GiNaC form of a step's claim sides (definition symbols resolved).
std::vector<GiNaC::ex> claim_sides(const Derivation& d, const Step& s);

// A formula by label for the numeric module: a step whose claim is `y = expr` with `y` a
// symbol; returns expr (the last side of the chain) and y's name. Throws InputError if the
// label is unknown or not of that shape.
struct Formula {
  std::string label;
  std::string target;        // y
  GiNaC::ex expr;
  // Free symbols of expr, in declaration order. CAUTION: these are GiNaC::symbol copies, and
  // copying a realsymbol/possymbol into a GiNaC::symbol slices it: the copy no longer compares
  // equal to the symbol inside `expr`, so never use them as subs()/exmap keys. Use the name
  // (params[i].get_name()) and Derivation::symbols.find(name)->sym for the real symbol.
  std::vector<GiNaC::symbol> params;
  const Step* step = nullptr;
};
Formula formula(const Derivation& d, const std::string& label);
// `eval FILE STEP --for NAME` (solve_for.cpp): rewrite step LABEL's equation in `d` as
// `NAME = expression` by undoing the operations around NAME's one occurrence (exact inverses
// only: + - * /, powers, exp, log, sqrt of a nonnegative side, sin/cos/tan of NAME declared in
// the inverse's range). Without for_name: a step already 'y = expression' is left alone,
// otherwise NAME is the one symbol of the equation not in `given`. Throws a positioned
// InputError when the step cannot be solved that way.
void solve_step_for(Derivation& d, const std::string& label, const std::string& for_name,
                    const std::vector<std::string>& given);
std::vector<Formula> formulas(const Derivation& d);   // every step of that shape, file order

}  // namespace dc
