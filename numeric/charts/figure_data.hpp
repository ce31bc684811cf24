// The data of a figure a .dc file names (docs/format.md, "Figures drawn by the code"), and the
// pgfplots code that draws it in the handout (docs/latex.md).
//
// `plot LABEL... over X = LO .. HI with ...`: each step's formula (dc::formula: the GiNaC
// expression of `y = expr`) evaluated exactly at 201 evenly spaced points of the range, the
// other symbols at the values given, then rounded once to a double; `simulate SCENE with ...`:
// the scene's own series (numeric/scenes), at most 400 rows. Values are never typed by hand,
// and the printed table is a pure function of the file: byte-identical across runs.
#pragma once
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "derivations/reader/derivation.hpp"
#include "derivations/syntax/figure.hpp"

namespace dc::chart {

struct FigureTable {
  std::string xlabel, ylabel;          // TeX, with units: "$v_0$ [$\mathrm{m/s}$]"
  std::vector<std::string> legends;    // one per curve (TeX); empty: one curve, named by ylabel
  std::vector<std::vector<double>> rows;   // x, then one value per curve (NaN where undefined)

  // The data file: a header line `x y1 y2 ...`, then one row per point, every number as
  // printf "%.9g" (NaN as `nan`, -0 as 0).
  std::string text() const;
  // A tikzpicture drawing the curves from `data_file` (a file name relative to the .tex, read
  // by pgfplots at compile time); an empty name puts the table inline instead.
  std::string pgfplots(const std::string& data_file) const;
  // The same curves as an inline SVG picture for the web page (`derivcheck html`): axes with
  // ticks, one polyline per curve (broken where a value is undefined), and under it an HTML line
  // naming the axes and the curves in TeX for the page's KaTeX. Deterministic.
  std::string svg() const;
};

// Evaluate the figure. Everything wrong with the figure line is a positioned InputError: an
// unknown label or scene, a step not of the form `y = expression`, an empty or reversed range,
// a symbol left without a value, a value that is not a number or lies outside its symbol's
// declared domain, curves whose units differ, a scene parameter out of bounds.
FigureTable figure_table(const Derivation& d, const FigureSpec& spec);

// Every figure of the documents that names what draws it (reader/figures.hpp), as `latex`
// puts it in LatexOptions::drawn_figures: the picture by the figure's Prose, and the data files
// (name, text) to write beside the .tex, named STEM-figN.dat with N the figure's number in
// the document (placeholders counted). An empty stem puts the data inline in the pictures.
struct DrawnFigures {
  std::map<const Prose*, std::string> pictures;
  std::vector<std::pair<std::string, std::string>> files;
};
DrawnFigures draw_figures(const std::vector<const Derivation*>& ds, const std::string& stem);

// The same figures as SVG pictures (FigureTable::svg), by the figure's Prose, for `html`.
std::map<const Prose*, std::string> svg_figures(const std::vector<const Derivation*>& ds);

}  // namespace dc::chart
