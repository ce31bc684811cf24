// What draws a figure: the words after a `figure "caption"` line's caption (docs/format.md,
// "Figures drawn by the code"). Pure syntax: names are checked against the file's steps and
// symbols, and values evaluated, where the figure is drawn (numeric/charts/figure_data).
//
//   figure "caption"                                                a captioned placeholder box
//   figure "caption" simulate SCENE [with NAME = VALUE, ...]        a scene of `derivcheck simulate`
//   figure "caption" plot LABEL[, LABEL...] over X = LO .. HI [with NAME = VALUE, ...]
//                                                                   formulas `y = expr` against X
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "derivations/syntax/expr.hpp"
#include "derivations/syntax/prose.hpp"
#include "derivations/syntax/source.hpp"

namespace dc {

struct FigureName {
  std::string name;
  SourcePos pos;
};

// `NAME = VALUE` after `with`: a scene parameter, or a symbol of the file held fixed.
struct FigureValue {
  FigureName name;
  Node value;   // a constant expression (numbers, pi, arithmetic); checked where it is evaluated
};

struct FigureSpec {
  enum class Kind { Placeholder, Scene, Plot } kind = Kind::Placeholder;
  SourcePos pos;                    // the word `simulate` / `plot`
  FigureName scene;                 // Scene: the scene's name (`derivcheck simulate --list`)
  std::vector<FigureName> curves;   // Plot: the labels of the steps drawn, one curve each
  FigureName var;                   // Plot: the symbol along the horizontal axis
  Node lo, hi;                      // Plot: the range of var
  SourcePos range_pos;              // Plot: the first character of LO
  int range_length = 1;             // Plot: characters from LO to the end of HI
  std::vector<FigureValue> with;    // in the order written
};

// Parse the words after the caption (`src` starts just after its closing quote). Empty or
// blank text is a Placeholder. `fail` throws a positioned InputError (never returns).
FigureSpec parse_figure_spec(const ProseSource& src,
                             const std::function<void(const SourcePos&, const std::string&, int)>& fail);

}  // namespace dc
