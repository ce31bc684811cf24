// TeX tokens of one math row, after author macros are expanded (private to syntax/).
#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "derivations/syntax/source.hpp"
#include "derivations/syntax/tex_math.hpp"

namespace dc::tex {

enum class TokKind { Cs, Char, End };

struct Token {
  TokKind kind = TokKind::End;
  std::string text;        // control-sequence name without '\' (Cs), or the character (Char)
  std::size_t off = 0;     // byte offset in the row text (a macro's tokens: the offset of its call)
  std::size_t end = 0;     // one past the last byte
  int line = 0, col = 0;   // position of off
  bool space_before = false;
  bool is(char c) const { return kind == TokKind::Char && text.size() == 1 && text[0] == c; }
  bool is_cs(std::string_view name) const { return kind == TokKind::Cs && text == name; }
};

// Tokens of a row: comments dropped, spaces folded into space_before, a trailing End token.
// Multi-byte UTF-8 characters are one Char token; '°' is a Cs "degree".
std::vector<Token> lex(std::string_view text, const SourcePos& origin);

// The tokens with author macros expanded (iteratively; a limit on expansions and on the size
// of the result turns a self-calling macro into an error at its call).
std::vector<Token> expand(std::vector<Token> toks, const TexContext& ctx, const SourcePos& origin);

// ---- tables (names.cpp) ----
bool is_greek(std::string_view cs);                    // theta, Delta, varepsilon, ...
const char* function_name(std::string_view cs);        // sin -> "sin", arcsin -> "asin"; nullptr
bool relation_of(const Token& t, TexRel& rel);         // = < > \le \approx \Rightarrow ...
bool is_ignored_cs(std::string_view cs);               // \, \; \displaystyle \nonumber ...
bool is_size_cs(std::string_view cs);                  // \big \Bigl ... (before a delimiter)
bool is_separator_word(std::string_view text);         // "and", "where", "for", ...
bool looks_like_unit(std::string_view text);           // "kg", "m/s", "N/m^2", "m s^{-2}"
std::string unit_text(std::string_view tex);           // "m\,s^{-2}" -> "m*s^-2"

}  // namespace dc::tex
