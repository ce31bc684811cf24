// An author's LaTeX or Markdown document, split into what the checker reads (no GiNaC).
//
// The split keeps document positions: every displayed row carries the position of its first
// math character, so a verdict is reported at the author's line. What is read:
//   LaTeX:    equation, align, gather, multline, eqnarray, displaymath (starred or not), \[ \],
//             $$ $$; inside them split, aligned, gathered are unwrapped; rows split at \\ ;
//             inline $…$ and \( \); \section-like commands and blank lines end a paragraph;
//             comments are blanked, `% derivcheck: …` lines are directives; \newcommand and
//             \def anywhere are macros (TexContext).
//   Markdown: $$ $$ and \[ \] displays, inline $…$, '#' headings, blank lines, fenced and
//             indented code (skipped), `<!-- derivcheck: … -->` and a front-matter block
//             (`---` … `---`, lines `derivcheck: …`) as directives.
// Not read: math inside code, tables (array, matrix, cases: the row is reported as not read).
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "derivations/syntax/source.hpp"

namespace dc {

struct DocRow {
  std::string text;          // the row's TeX (no \\, no environment delimiters)
  SourcePos origin;          // position of text[0]
};

struct DocDisplay {
  std::vector<DocRow> rows;
  SourcePos pos;             // where the display starts ($$, \begin{…}, \[)
  std::size_t end = 0;       // offset in the text just after its closing delimiter
  std::string env;           // "equation", "align", "$$", "\\[", ...
  int section = 0;           // counts headings before it
  int paragraph = 0;         // counts paragraph breaks before it
  std::string prose_before;  // the plain text between the previous display and this one
};

struct DocInline {
  std::string text;          // the TeX between $ and $
  SourcePos origin;
  int section = 0;
  int paragraph = 0;
  std::size_t displays_before = 0;   // how many displays precede it
};

struct DocDirective {
  std::string text;          // what follows "derivcheck:" (a .dc declaration line)
  SourcePos origin;          // position of text[0]
  bool addressed = false;    // written after "derivcheck:" (a rule comment: then WORD must be a rule)
};

struct Document {
  enum class Kind { Markdown, Latex } kind = Kind::Markdown;
  SourceText source;
  std::vector<DocDisplay> displays;
  std::vector<DocInline> inlines;
  std::vector<DocDirective> directives;
  // `% by solve (9.6), (9.7) for v_1'` (or `<!-- by … -->`, `% derivcheck: by …`): the rule of
  // the displayed row the comment follows, in .dc rule syntax; text is what follows "by ".
  // A comment `by WORD` whose WORD is no rule is ordinary prose (the reader decides).
  std::vector<DocDirective> rule_comments;
  std::string macro_text;    // the text holding \newcommand / \def (LaTeX: the whole document)
  // Positioned warnings that stop nothing: a display opened and never closed is read as text
  // (the rest of the document is still checked).
  std::vector<InputError> warnings;
};

// Is this path a document the document reader takes (.tex, .ltx, .md, .markdown)?
bool is_document_path(std::string_view path);

// Split a document. An unclosed display or environment is a warning (Document::warnings) and
// its opening delimiter is read as text; only an unclosed HTML comment is an InputError.
Document split_document(SourceText source);

}  // namespace dc
