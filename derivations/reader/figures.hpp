// What draws each figure of a derivation (docs/format.md, "Figures drawn by the code").
//
// The reader checks the words after a figure's caption when it reads the file; the Derivation
// keeps the caption only, and `latex` asks for the rest here (the file is read again from
// Derivation::source, so the specs and their positions are exactly the reader's).
#pragma once
#include <cstddef>
#include <map>

#include "derivations/reader/derivation.hpp"
#include "derivations/syntax/figure.hpp"

namespace dc {

// Prose index (into d.prose) -> the figure's spec, for the figures that name what draws them
// (a bare `figure "caption"` is not listed). Throws InputError as load_derivation would.
std::map<std::size_t, FigureSpec> figure_specs(const Derivation& d);

}  // namespace dc
