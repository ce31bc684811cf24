// The inline markup of literate text in .dc files (docs/format.md, "Text"):
//   $...$      TeX math, copied as written (braces must balance; no '$' inside)
//   `expr`     an expression in the file's own syntax, typeset with its declared symbols
//   *words*    emphasis (may hold $...$ and `expr`: *the energy `T` is lost*)
//   \# \$ \` \*  the character itself
// Everything else is plain text (escaped for LaTeX when printed).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "derivations/syntax/expr.hpp"
#include "derivations/syntax/source.hpp"

namespace dc {

// Literate text between the steps (docs/format.md, "Text"): what `derivcheck latex` prints
// around the equations. The checker ignores it.
struct ProsePiece {
  enum class Kind { Text, Math, Expr, Emph } kind = Kind::Text;
  std::string text;          // Text/Emph: plain text; Math: TeX between $...$; Expr: as written
  Node expr;                 // Expr: `m1*v1 + m2*v2`, typeset with the file's symbols
  std::vector<Node> more;    // Expr written as an equation `beta = v/c`: the sides after expr
  std::vector<ProsePiece> inner;   // Emph: its own pieces (text, $math$, `expr`); text is their plain text
};
struct Prose {
  enum class Kind { Heading, Paragraph, Remark, Figure } kind = Kind::Paragraph;
  std::vector<ProsePiece> pieces;   // Heading: one Text piece (the title); Figure: the caption's pieces
  SourcePos pos;
  std::size_t before_step = 0;      // index of the step it stands before (steps.size(): after all)
};


struct ProseSource {
  const std::string& text;               // the paragraph; lines joined by '\n'
  const std::vector<SourcePos>& pos;     // one position per character of text
  SourcePos end;                         // just after the last character
};

// Split a paragraph into pieces. `validate` checks an `expr` piece against the file's symbols
// (it throws InputError); `fail` throws a positioned InputError (never returns).
std::vector<ProsePiece> parse_prose(const ProseSource& src, const std::function<void(const Node&)>& validate,
                                    const std::function<void(const SourcePos&, const std::string&, int)>& fail);

// Plain text of a paragraph (expressions as written, math as TeX): for messages and tests.
std::string prose_plain_text(const std::vector<ProsePiece>& pieces);

}  // namespace dc
