// Internals of the .dc reader (docs/format.md), private to derivations/reader: the class
// DcReader and the helpers and types it uses. Only files in derivations/reader include this.
//
// DcReader's members are defined in
//   dc_reader.cpp        run(), lines and statements, step headers, prose, lexical helpers on
//                        spans, validation of expressions;
//   dc_declarations.cpp  symbol / function / assume statements, names defined by steps;
//   dc_steps.cpp         step statements, order terms, the `by` rule line.
#pragma once
#include <algorithm>
#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/reader/derivation.hpp"
#include "derivations/syntax/expr.hpp"
#include "derivations/syntax/figure.hpp"
#include "derivations/syntax/source.hpp"

namespace dc::reader_detail {

inline const std::vector<std::string> kRuleNames = {"given",  "definition", "rewrite",     "substitute",
                                                    "solve",  "limit",      "first_order", "series",
                                                    "differentiate", "integrate", "solves_ode",
                                                    "stationary", "maximum", "minimum", "instance",
                                                    "coefficients"};
inline const std::vector<std::string> kRewriteAliases = {"simplify", "expand", "factor", "algebra"};
inline const std::vector<std::string> kRuleKeywords = {"for", "into", "of", "with", "wrt", "from"};
inline const std::vector<std::string> kStatementKeywords = {"title", "handout", "section", "symbol", "function", "vector", "assume",
                                                            "heading", "text", "remark", "figure", "notation"};
inline const std::vector<std::string> kAttributeKeywords = {"by", "note", "erratum", "stable", "hide", "tex"};

// The default TeX name of a vector: \mathbf{r}_{0} (command "\\mathbf") for r0 (dc_vectors.cpp).
std::string vector_tex(const std::string& command, const std::string& name);

inline bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

inline bool is_ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
inline bool is_ident_char(char c) { return is_ident_start(c) || (c >= '0' && c <= '9') || c == '_'; }
inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Bytes of the UTF-8 character starting at t[i] (1 for a byte that starts none), so messages
// never quote half a character.
inline std::size_t utf8_length(const std::string& t, std::size_t i) {
  unsigned char c = static_cast<unsigned char>(t[i]);
  std::size_t n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 1;
  std::size_t k = 1;
  while (k < n && i + k < t.size() && (static_cast<unsigned char>(t[i + k]) & 0xC0) == 0x80) ++k;
  return k;
}

inline std::string join(const std::vector<std::string>& v, const std::string& sep) {
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
inline void trim_range(const std::string& t, std::size_t& b, std::size_t& e) {
  while (b < e && (is_space(t[b]) || t[b] == '\n')) ++b;
  while (e > b && (is_space(t[e - 1]) || t[e - 1] == '\n')) --e;
}

struct Statement {
  int first_line = 0;
  std::vector<std::pair<int, std::string>> lines;   // (line number, comment-blanked text)
};

// Reads one .dc source into a Derivation: DcReader(source).run() (parse_derivation calls it).
class DcReader {
 public:
  explicit DcReader(SourceText src) { d_.source = std::move(src); }

  Derivation run();
  // The rule line `text` (what follows "by", starting at pos) of d.steps[index]: see
  // read_rule_line in derivation.hpp.
  static RuleSpec rule_of(const Derivation& d, std::size_t index, const std::string& text, const SourcePos& pos);
  // After run(): what draws each figure that names it, by its index in Derivation::prose.
  const std::map<std::size_t, FigureSpec>& figures() const { return figures_; }

 private:
  Derivation d_;
  std::map<std::size_t, FigureSpec> figures_;
  std::vector<std::string> lines_;              // comment-blanked
  std::vector<Statement> statements_;
  std::map<std::string, SourcePos> all_labels_;  // every label in the file (to say "later")
  std::map<std::string, std::size_t> defined_;   // labels defined so far -> step index
  std::set<std::string> used_names_;             // identifiers in the claims of the steps so far
  std::map<std::string, std::size_t> named_results_;   // name -> index of the step whose named result bound it
  std::string rule_name_;                        // the rule line being read (as written)
  std::optional<SourcePos> first_assume_;
  std::string current_label_;                    // the step being read

  const std::string& file() const { return d_.source.name; }

  [[noreturn]] void fail(const SourcePos& p, const std::string& msg, int length = 1) {
    throw InputError(p, msg, length, d_.source.line(p.line));
  }

  // --- lines and statements (dc_reader.cpp) ----------------------------------------------
  void split_lines();
  static std::string word_at(const std::string& l, std::size_t from, std::size_t* end = nullptr);
  // Step header: [(TAG)] LABEL ':' ; returns false if the line is not of that shape.
  struct Header {
    std::string tag, label;
    SourcePos label_pos;
    std::size_t claim_from = 0;
  };
  bool parse_header(const std::string& l, int ln, Header& h, bool throw_on_error);
  void collect_labels();
  void statement(const Statement& st);
  void prose_statement(const std::string& w, const Span& s, const SourcePos& pos);

  // --- small lexical helpers on spans (dc_reader.cpp) --------------------------------------
  static std::size_t nonspace(const Span& s, std::size_t p);
  static void skip_ws(const Span& s, std::size_t& p);
  std::string string_literal(const Span& s, std::size_t& p, const std::string& expected);
  void expect_end(const Span& s, std::size_t p);
  static std::string excerpt(const Span& s, std::size_t p);
  std::string identifier(const Span& s, std::size_t& p, const std::string& expected);
  Node expression(const Span& s, std::size_t b, std::size_t e, const std::string& what);
  Relation relation(const Span& s, std::size_t b, std::size_t e, const std::string& what);
  void validate(const Node& n);
  GiNaC::ex converted(const Node& n);

  // --- symbol / function (dc_declarations.cpp) ---------------------------------------------
  void symbol_statement(const Span& s, bool is_function);
  void vector_statement(const Span& s);   // dc_vectors.cpp
  std::vector<std::string> parameters(const Span& s, std::size_t& p, const std::string& owner);
  bool vector_arrows_ = false;                     // `notation arrows`
  std::vector<std::string> default_vector_tex_;    // vectors declared without a tex

  // --- assume (dc_declarations.cpp) --------------------------------------------------------
  void assume_statement(const Span& s, const SourcePos& at);
  void check_assumptions();

  // --- steps (dc_steps.cpp; introduce_definition, check_definition_cycle: dc_declarations.cpp)
  void step_statement(const Statement& st, const Header& h);
  void order_term(Step& step);
  bool names_new_quantity(const Step& step) const;
  bool names_operation_result(const Step& step) const;
  void note_bound_names(Step& step) const;
  void warn_assumption_dimensions(const std::vector<Node>& sides);
  void validate_side(const Node& n);
  static bool contains_integral(const Node& n);
  static std::string normalise_ws(const std::string& t);
  void introduce_definition(Step& step);
  void check_definition_cycle(const std::string& name, const Node& rhs);

  // --- the rule line (dc_steps.cpp) --------------------------------------------------------
  void check_ref(const std::string& label, const SourcePos& p);
  RuleSpec rule_line(const Span& s, const SourcePos& by_pos);
  static std::string usage(const std::string& r);
  // items and labels are templates (a group of the rule line); dc_steps.cpp, their only user,
  // defines them.
  std::vector<std::pair<std::size_t, std::size_t>> items(const Span& s, const auto& g);
  bool plain_identifier(const Span& s, std::size_t b, std::size_t e) const;
  static RuleArg spanned(const Span& s, std::size_t b, std::size_t e);
  RuleArg label_arg(const Span& s, std::size_t b, std::size_t e);
  std::vector<RuleArg> labels(const Span& s, const auto& g, const std::string& what, std::size_t count);
  RuleArg ref_or_equation(const Span& s, std::size_t b, std::size_t e);
  RuleArg symbol_arg(const Span& s, std::size_t b, std::size_t e);
  RuleArg value_arg(const Span& s, std::size_t b, std::size_t e);
  RuleArg symbol_or_value(const Span& s, std::size_t b, std::size_t e);
};

}  // namespace dc::reader_detail
