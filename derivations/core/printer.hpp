// Deterministic printing of GiNaC expressions.
//
// GiNaC's own print order follows hash seeds that change between processes (ASLR), so it is
// never shown to users. This printer sorts the operands of sums and products with a
// comparator of our own (by total degree, then by the printed text of each term), puts a
// canonical sign on each sub-sum, and uses the SymbolTable's names (text) or TeX names (latex).
#pragma once
#include <string>

#include <ginac/ginac.h>

#include "derivations/core/symbols.hpp"

namespace dc {

std::string print_text(const GiNaC::ex& e, const SymbolTable& table);
std::string print_latex(const GiNaC::ex& e, const SymbolTable& table);
// A number for reports: exact rationals as "5/2"; floats with `digits` significant digits.
std::string print_number(const GiNaC::ex& e, int digits = 20);

}  // namespace dc
