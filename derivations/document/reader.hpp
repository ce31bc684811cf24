// The document reader (document.hpp), internal to the document stage: what the rows of a
// LaTeX or Markdown document mean together. Its members live in three files: reader.cpp (the
// rows, names, functions, vectors and the steps they become), reader_text.cpp (what the
// prose around the displays says: the equations of the text, which of them are in force
// for a display, definitions, "where" clauses, neglected names, lone names, the tags and
// words it cites) and rule_comments.cpp (the author's own `% by …` rule for a row).
#pragma once
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "derivations/document/document.hpp"
#include "derivations/syntax/document.hpp"
#include "derivations/syntax/tex_math.hpp"

namespace dc::document_detail {

inline constexpr std::size_t kNearby = 8;   // earlier rows a step may cite without the author naming them

std::string relation_word(TexRel r);
void walk(Node& n, const std::function<void(Node&)>& f);
void walk(const Node& n, const std::function<void(const Node&)>& f);
// Names used as plain symbols (not calls, not reserved words).
void symbol_names(const Node& n, std::set<std::string>& out);
// How a side is built from vectors: 0 scalar, 1 linear in the vectors, -1 anything else.
int vector_degree(const Node& n, const std::set<std::string>& vectors);
bool is_zero_literal(const Node& n);

// One relation of a row, before it becomes a step.
struct Link {
  Node lhs, rhs;
  std::string relation;
  int link = 0;
  std::size_t chain = 0;
  bool after_gives = false;
};

struct ReadRow {
  const DocRow* row = nullptr;
  std::size_t display = 0;
  TexRow tex;
  std::set<std::string> vectors;   // the row's bold names, renamed NAME_vec
  std::string not_read;
  SourcePos not_read_pos;
};

class DocumentReader {
 public:
  explicit DocumentReader(SourceText source) : doc_(split_document(std::move(source))) {}

  Derivation run();

 private:
  std::string title() const;

  // `derivcheck: symbol …` / `function …` / `assume …` lines, read by the .dc reader; an error
  // is reported at the directive's own position in the document.
  void directives();

  // A directive in the document's own notation, as a .dc line: names may be TeX (`\mu`,
  // `v'_1`), the dimension may be left out (then the names are dimensionless, as every
  // undeclared name of a document is), an assumption may be TeX (`\theta < \pi/2`).
  std::string as_dc(const DocDirective& dir) const;

  // `derivcheck: assume v_1 > v_2` (TeX or .dc notation), once every name is declared.
  void assumptions();

  // Does any row use e as a plain symbol (a coefficient of restitution)? Then e^2 is its square.
  bool uses_symbol_e() const;

  void parse_rows();

  // A row that begins with + or - after the alignment (`&\quad + c`) is the rest of the
  // previous row's last side, broken over two rows: joined to it.
  void join_broken_sides();

  void parse_all_rows();

  // `W = \int_0^L F\,dx` where another row says `F = F_0 x^2/L^2`: the integrand varies with
  // x through that row, and reading F as a constant would be wrong. Not read yet.
  void mark_integrands_through_definitions();

  void mark_functions_and_vectors();
  void read_differentials(std::map<std::size_t, std::map<std::string, std::string>>& functions);

  static std::string function_id(const std::string& name, const std::string& var);

  // Every plain use of a function name becomes its application at the variable.
  void to_functions(Node& n, const std::map<std::string, std::string>& names);

  // `v(0)`, `x(t)` as the parser reads them (value_at): the application of the function that
  // `here` (the display's names differentiated on their own), another row of the document or
  // the written variable (`x(t)`) makes of the name. "" when every one is read, else why not.
  std::string read_values_at(Node& n, const std::map<std::string, std::string>& here);

  // An inline equation of the prose (`$e = 1$`) is a given for the display that follows it.
  void inline_givens();

  // A name written once in the whole document, in the text, is used for nothing and defined
  // nowhere: most often a slip for another name (the seed handout's v_e for u_e).
  void note_lone_names(const TexRow& row);

  // Offsets and positions in the document's text.
  std::size_t offset_of(const SourcePos& p) const;

  // The "where …" clause right after display k: the text from its end to the first full stop,
  // blank line or next display, when that text begins with "where", "with", "here" or "in
  // which". Its equations define the display's names (`where $\mu = m_1/m_2$`).
  bool in_where_clause(std::size_t k, const SourcePos& at) const;

  // "neglect D", "neglecting $D$", "ignoring D" in the text before a display, where D is a
  // name of that display: D = 0 is a condition of the display, listed as a given of the text
  // (the words are the author's; the search may use them to derive a row, never to refute one).
  void neglected_names();

  // The conditions in force for a display: the inline givens of the text just before it
  // (`For equal masses, $m_1 = m_2$, this becomes:`). A display that follows the previous one
  // with no text between, or whose text adds givens of its own (a special case of the case at
  // hand), keeps the conditions of the previous display; a given for a name already given
  // (`$e = 0$` after `$e = 1$`) starts a new case; text without givens ends the case.
  std::vector<std::string> conditions_for(std::size_t k, const std::vector<std::string>& own, const std::vector<std::string>& previous, bool same_section) const;

  // The inline givens of the section before display k that are not in force there, unless a
  // later given for the same name or an inequality of the text about it (`$0 < e < 1$`)
  // supersedes them before the display.
  std::vector<std::string> stated_earlier(std::size_t k, std::size_t section, const std::vector<std::string>& in_force) const;

  // Does inline given g restate p's value (`$\mu = m_1/m_2 \approx 0$` after `$\mu = m_1/m_2$`):
  // a regime of the same quantity, not a new case.
  bool restates(const std::string& g, const std::string& p) const;

  void build_steps();

  Step unread_step(const std::string& label, const ReadRow& r, const std::string& why);

  // Every element of a is in b.
  static bool subset(const std::vector<std::string>& a, const std::vector<std::string>& b);

  static void rename_vectors(Node& n, const std::set<std::string>& vectors);
  void vector_products(Node& n) const;

  static void add_all(std::vector<std::string>& out, const std::vector<std::string>& more);

  // "(9.6)", "Eq. 9.6", "\eqref{x}" in prose: the tags and labels it names.
  static std::vector<std::string> tags_in(const std::string& prose);

  static std::string hint_of(const std::string& prose);
  static std::string continuation_of(const std::string& prose);
  static std::vector<std::string> refs_in(const std::string& prose);

  // Every name the steps use, declared real (unless a directive declared it); the functions
  // found in parse_rows with their variable.
  void declare_symbols();

  struct InlineStep {
    std::size_t displays_before;
    std::size_t section;
    Step step;
    std::string subject;   // the name on its left side ("" when that is no plain name)
    bool where = false;    // in the "where …" clause right after the display before it
    bool defines = false;  // gives a value to a name nothing earlier in its section used
  };

  // Inline givens that define a fresh name (`at a mass rate of $\mu = dm/dt$`): a definition,
  // not a case, so it stays in force for the rest of its section, until the text gives the
  // name again or a display row gives it a value of its own (`\mu = …` on a left side).
  std::vector<std::string> definitions_for(std::size_t k, std::size_t section) const;
  void mark_definitions();

  // `% by solve (9.6), (9.7) for v_1'` in or right after a display: the rule of the row it
  // follows (every link of it), read as the .dc reader reads a rule line once its tags,
  // labels and TeX names are written as step labels and .dc names (rule_comments.cpp).
  void authors_rules();
  std::string as_dc_rule(const DocDirective& c, const std::string& rest) const;

  Document doc_;
  std::map<std::string, std::vector<std::string>> label_rows_, tag_rows_;   // \label / tag -> step labels
  Derivation d_;
  TexContext ctx_;
  std::vector<ReadRow> rows_;
  std::vector<InlineStep> inline_steps_;
  struct Bound {
    std::size_t displays_before;
    SourcePos pos;
    std::string name;
  };
  std::vector<Bound> bounded_;   // names an inline inequality of the text mentions
  std::map<std::string, std::string> subject_of_;   // inline given -> the name it gives a value
  std::map<std::string, std::string> function_vars_;
  std::set<std::string> lone_;
  std::vector<const DocDirective*> assumes_;
};

}  // namespace dc::document_detail
