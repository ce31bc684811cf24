// Helpers shared by the chart data files (chart_data.cpp, chart_maps.cpp); private to numeric/charts.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/reader/derivation.hpp"
#include "numeric/evaluator.hpp"

namespace dc::chart::support {

// Bits of accuracy left after an error of `ulps` units in the last place (53 for a finite 0).
double bits_from_ulps(double ulps);
// |x - ref| / |ref| exactly (absolute when ref = 0); inf for non-finite x.
double rel_error(long double x, const GiNaC::numeric& ref);
// The evaluator with every rewrite off: the formula as written.
num::CompileOptions naive_options();
// Table symbols named `names` -> fresh plain symbols (see PlainFormula).
std::pair<GiNaC::exmap, std::vector<GiNaC::symbol>> plain_symbols(const Derivation& d,
                                                                  const std::vector<std::string>& names);

}  // namespace dc::chart::support
