// Declared abstract functions (v(t), m_r(t)) as GiNaC functions from a fixed pool.
//
// GiNaC needs a registered function for each abstract function. The pool holds
// kFunctionPoolSize one-argument functions named dcfn0, dcfn1, ... with no eval, evalf or
// derivative rules registered: v(0) stays v(0), and diff(v(t), t) becomes GiNaC's
// fderivative D[0](dcfn0)(t). SymbolTable::function_index maps a declared name to its pool
// index; the helpers below map a pool application (or a derivative of one) back to the
// declaration, for printers. GiNaC's own names (dcfn0) must never reach users.
#pragma once
#include <string>

#include <ginac/ginac.h>

#include "derivations/symbolic/symbols.hpp"

namespace dc {

constexpr int kFunctionPoolSize = 16;

// f_index(arg). Throws std::out_of_range for an index outside [0, kFunctionPoolSize).
GiNaC::ex apply_pool_function(int index, const GiNaC::ex& arg);

// The pool index of `e` when it is a pool function application dcfnK(x) or a derivative of one
// (an fderivative of dcfnK); -1 otherwise.
int pool_function_index(const GiNaC::ex& e);

// How many times a pool application has been differentiated: 0 for v(t), 2 for v''(t);
// -1 when `e` is not a pool function.
int pool_derivative_order(const GiNaC::ex& e);

// The declared function that pool index `index` stands for in `table` (a SymbolInfo with
// is_function); nullptr if none.
const SymbolInfo* pool_function_info(int index, const SymbolTable& table);

// Shorthand: the declaration behind a pool application or derivative; nullptr otherwise.
inline const SymbolInfo* declared_function_of(const GiNaC::ex& e, const SymbolTable& table) {
  int k = pool_function_index(e);
  return k < 0 ? nullptr : pool_function_info(k, table);
}

}  // namespace dc
