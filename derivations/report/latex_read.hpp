// A reader for the LaTeX that latex.cpp emits (and nothing more): it turns an emitted equation
// back into the author's tree, so a round-trip test can prove every printed equation equal to
// its source (a dropped sign or bracket in printing cannot pass).
//
// Accepted: the constructs listed in latex.hpp, symbols and declared functions by their TeX
// names (longest match), `&`, `\\`, `\begin{aligned}`/`\end{aligned}`, `\notag`, `\tag{..}` and
// `\footnotemark` (ignored). Anything else is an InputError at its line and column.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "derivations/syntax/expr.hpp"
#include "derivations/symbolic/symbols.hpp"

namespace dc {

// Parse one emitted relation or expression. `origin` positions errors (line/col advance
// through `latex`).
Relation read_latex_relation(std::string_view latex, const SymbolTable& table,
                             const SourcePos& origin = {"<latex>", 1, 1});
Node read_latex_expression(std::string_view latex, const SymbolTable& table,
                           const SourcePos& origin = {"<latex>", 1, 1});

// One displayed step of an emitted document: the writer puts a comment `% LABEL (FILE:LINE)`
// before each step's display; this collects the display's LaTeX (tag and markers removed).
struct LatexDisplay {
  std::string file;    // FILE of the comment (the .dc file's base name)
  std::string label;
  int source_line = 0; // LINE of the comment
  std::string latex;   // the relation, possibly with aligned markers
  std::string tag;     // from \tag{...}, empty if none
  int line = 0;        // line in the document where the display's LaTeX starts
  bool footnote = false;  // carried \footnotemark (an erratum's corrected claim)
};
std::vector<LatexDisplay> extract_latex_displays(const std::string& document);

}  // namespace dc
