// Deterministic printing of GiNaC expressions.
//
// GiNaC's own print order follows hash seeds that change between processes (ASLR), so it is
// never shown to users. This printer sorts the operands of sums and products with a
// comparator of our own (by total degree, then by the printed text of each term), puts a
// canonical sign on each sub-sum, and uses the SymbolTable's names (text) or TeX names (latex).
#pragma once
#include <string>

#include <ginac/ginac.h>

#include "derivations/symbolic/symbols.hpp"

namespace dc {

std::string print_text(const GiNaC::ex& e, const SymbolTable& table);
std::string print_latex(const GiNaC::ex& e, const SymbolTable& table);
// A number for reports: exact rationals as "5/2"; floats with `digits` significant digits.
std::string print_number(const GiNaC::ex& e, int digits = 20);
// For statements where the sign of `e` does not matter ("e != 0", "the sign of e is not
// determined"): the text of e or of -e, whichever prints without a leading '-' (else the smaller
// text). GiNaC may store 1/(v1 - v2) as -1/(v2 - v1) depending on its symbol order, which shifts
// with anything that creates symbols earlier; this keeps the words the same.
std::string print_text_up_to_sign(const GiNaC::ex& e, const SymbolTable& table);
// The choice itself, for any printer: `of_e` and `of_minus_e` are the texts of e and -e.
std::string text_up_to_sign(std::string of_e, std::string of_minus_e);
// The TeX spelling of a name with no declared TeX name: m1 -> m_{1}, theta -> \theta,
// v_e -> v_{e}, mass -> \mathit{mass}.
std::string default_tex_name(const std::string& name);

}  // namespace dc

namespace dc::detail {

// 10^k, exact.
GiNaC::numeric pow10(int k);

// Numbers for reports: exact rationals as "7/3"; any real number to `sig` significant
// digits ("2.6253741264076874400e17", "-0.5", "1.2345678901234567890"). Deterministic.
std::string exact_text(const GiNaC::numeric& q);
std::string format_number(const GiNaC::numeric& x, int sig = 20);
// Deterministic plain text of a GiNaC expression: operands of sums and products sorted by
// their own text, numbers first in products and last in sums. (A private printer: used for
// residuals and side conditions, never GiNaC's process-dependent print order.)
std::string canon_text(const GiNaC::ex& e);
// Residual text: numerator/denominator expanded and the denominator's sign fixed, so the
// same residual prints identically whatever sign GiNaC's normal() chose for the sub-sums.
// Printed with dc::print_text (the project's deterministic printer). Falls back to a
// term-count note when expansion would be too large.
std::string residual_text(const GiNaC::ex& e, const SymbolTable& ctx, double max_terms = 2000);

}  // namespace dc::detail
