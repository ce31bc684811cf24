// The recursive descent over TeX math tokens (private to syntax/): parser.cpp holds names,
// scripts, sums and products; atoms.cpp the atoms (\frac, \sqrt, functions, calculus,
// groups); row.cpp the row (cleaning, splitting, chains) and the public functions.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "derivations/syntax/expr.hpp"
#include "derivations/syntax/tex/internal/tokens.hpp"
#include "derivations/syntax/tex_math.hpp"

namespace dc::tex {

struct Parsed {
  Node node;
  int depth = 1;
  std::size_t begin = 0, end = 0;  // byte offsets of the first and one-past-last character
  int end_line = 0;
};

struct Script {
  enum Kind { Expr, Degree, Prime, Star } kind = Expr;
  int primes = 0;
  Parsed value;
};

struct NameParts {
  std::string base, subs, deco;
  int primes = 0;
  bool star = false, vector = false, plain_e = false;
};

class Parser {
 public:
  Parser(std::string_view text, const SourcePos& origin, const TexContext& ctx, std::vector<Token> toks, TexRow& row);

  void check_groups();
  // Parse tokens [b, e) as one chain side or expression; the rest is the row's business.
  void set_range(std::size_t b, std::size_t e) {
    pos_ = b;
    end_ = e;
    end_tok_ = toks_[e];
    end_tok_.kind = TokKind::End;
  }
  std::size_t pos() const { return pos_; }
  std::size_t end() const { return end_; }
  const std::vector<Token>& tokens() const { return toks_; }
  const Token& peek(std::size_t k = 0) const;
  const Token& next();
  [[noreturn]] void fail(const Token& t, const std::string& msg) const;
  std::string describe(const Token& t) const;
  std::string describe_real(const Token& t) const;
  SourcePos at(const Token& t) const;
  std::string plain(std::size_t b, std::size_t e) const;
  std::size_t match(std::size_t open) const { return match_[open]; }

  Parsed sum();
  std::string take_unit_of_side() { return std::exchange(unit_, std::string()); }

 private:
  void enter(const Token& t);
  int length_of(const Parsed& p) const;
  Parsed leaf(NodeKind kind, std::string text, const Token& first, const Token& last) const;
  Parsed binary(NodeKind kind, Parsed left, Parsed right, const Token& op) const;
  Parsed call(std::string name, std::vector<Parsed> args, const Token& first) const;
  Parsed symbol(const std::string& name, const Token& at_tok) const;
  void extend(Parsed& p, const Token& last) const;
  std::pair<std::size_t, std::size_t> arg_range(const std::string& what);
  Parsed parse_range(std::size_t b, std::size_t e, const std::string& what, Parsed (Parser::*f)());

  bool starts_name(const Token& t) const;
  std::size_t species_at(std::size_t i) const;
  std::string subscript_text(std::size_t b, std::size_t e) const;
  Parsed name();
  void name_core(NameParts& parts);
  static bool is_plain_number(const Node& n);
  static bool is_numeric(const Node& n);
  Script script();
  Parsed apply_script(Parsed base, Script sc, const Token& caret);

  bool starts_factor(const Token& t) const;
  Parsed term(bool operand);
  Parsed operand_term() { return term(true); }
  Parsed full_term() { return term(false); }
  Parsed signed_factor();
  Parsed factor();
  std::size_t differential_at(std::size_t i) const;
  bool is_d_mark(std::size_t i, std::size_t& after) const;
  Parsed take_differential();
  bool is_unit_group(std::size_t i) const;
  void take_unit();

  // atoms.cpp
  Parsed atom();
  Parsed number();
  Parsed group(const Token& open, const char* close, bool parenthesized);
  Parsed abs_value(const Token& open);
  Parsed frac(const Token& cs);
  std::optional<Parsed> derivative(std::size_t nb, std::size_t ne, std::size_t db, std::size_t de, const Token& cs);
  Parsed sqrt(const Token& cs);
  Parsed function(const Token& cs, const char* fname);
  Parsed integral(const Token& cs);
  Parsed limit(const Token& cs);
  Parsed big_operator(const Token& cs);
  Parsed eval_bar(Parsed f, const Token& bar);
  Parsed roman(const Token& cs);
  Parsed slash_derivative(const Token& d);

  std::string_view text_;
  const SourcePos& origin_;
  const TexContext& ctx_;
  std::vector<Token> toks_;
  TexRow& row_;
  std::vector<std::size_t> match_;
  std::size_t pos_ = 0, end_ = 0;
  Token end_tok_;
  Token last_;
  int nest_ = 0;
  int max_depth_ = 200;
  int max_tree_depth_ = 5000;
  int abs_depth_ = 0;
  int int_depth_ = 0;
  int sum_terms_ = 0;
  std::string frac_dvar_;       // \int \frac{dm}{m}: the differential taken from a numerator
  std::string last_int_var_;    // the variable of the row's last integral (for [F]_a^b)
  std::map<std::string, std::string> subst_;   // a finite sum's index -> its current value
  std::string unit_;            // the unit written after a number on the current side
  std::size_t unit_end_ = 0;    // the token after that unit's group
};

}  // namespace dc::tex
