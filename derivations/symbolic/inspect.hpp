// What an expression contains, read without evaluating it: its symbols in a deterministic order
// and their domains, abstract function applications (v(t), v'(t)), and the size its expansion
// would have (checked before any expand/normal so that a runaway expansion is refused).
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/symbolic/symbols.hpp"

namespace dc::detail {

// The domain of a symbol (SymbolTable entry; a symbol the table does not know is real, or
// positive when it is a GiNaC possymbol).
// (Symbols travel as GiNaC::ex: copying a realsymbol/possymbol into a GiNaC::symbol slices it
// and the copy no longer compares equal.)
Domain domain_of(const GiNaC::ex& s, const SymbolTable& ctx);

// The symbols of e (each once).
void collect_symbols(const GiNaC::ex& e, GiNaC::exset& out);
// Symbols of e in declaration order (then unknown symbols by name): deterministic, unlike
// GiNaC's traversal order.
std::vector<GiNaC::ex> ordered_symbols(const GiNaC::ex& e, const SymbolTable& ctx);

// Abstract function applications: GiNaC functions that are not one of the evaluable
// built-ins (exp, log, sin, ...) and every fderivative.
bool is_abstract_application(const GiNaC::ex& e);
bool has_abstract_application(const GiNaC::ex& e);
}  // namespace dc::detail

namespace dc {

// Continuous in x on the whole real line: every part that contains x is a sum, a product, a
// power with a nonnegative integer exponent, exp / sin / cos / atan of such a part, or an
// application of a declared function (declared functions are taken to be continuous, as
// physics texts take them). Parts free of x are constants here (their own conditions are the
// claim's). The fundamental theorem of calculus needs the integrand continuous between a and b
// for every admissible b; this guarantees it. 1/x, log(x), sqrt(x), tan(x) fail the test and
// are left to rigorous quadrature (the integral of 1/x from -1 to b > 0 diverges, although
// log(b^2)/2 has derivative 1/b and vanishes at b = -1).
bool continuous_everywhere(const GiNaC::ex& e, const GiNaC::symbol& x);

// Estimated number of terms of expand(e); used to refuse runaway expansions.
double estimate_expanded_terms(const GiNaC::ex& e);

// Does `text` contain `name` as a whole identifier?
bool names_symbol(const std::string& text, const std::string& name);

}  // namespace dc
