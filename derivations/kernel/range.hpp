// Range analysis over the declared domains: interval arithmetic with exact rational bounds,
// and the sign facts it makes evident. Sound but incomplete: a range may be wider than the
// true set of values (dependency problem), never narrower.
#pragma once
#include <string>

#include <ginac/ginac.h>

#include "derivations/symbolic/symbols.hpp"

namespace dc::detail {

struct Range {
  bool lo_inf = true, hi_inf = true;
  GiNaC::numeric lo, hi;
  bool lo_open = true, hi_open = true;
  static Range all() { return {}; }
  bool positive() const;      // every value > 0
  bool negative() const;      // every value < 0
  bool nonnegative() const;   // every value >= 0
  bool nonzero() const { return positive() || negative(); }
  bool within(const GiNaC::numeric& a, const GiNaC::numeric& b) const;   // subset of [a, b]
  std::string to_string() const;
};
Range range_of(const GiNaC::ex& e, const SymbolTable& ctx);
// The same over the points where e is real: a fractional power counts as >= 0 whatever its
// base (sqrt(a^2 - b) + a > 0 for a positive, wherever it is real). For side conditions, each
// of which comes with the conditions of its own parts (a^2 - b >= 0 here).
Range range_where_defined(const GiNaC::ex& e, const SymbolTable& ctx);

// Sign facts that the domains (and GiNaC's info flags) make evident.
bool provably_positive(const GiNaC::ex& e, const SymbolTable& ctx);
bool provably_nonzero(const GiNaC::ex& e, const SymbolTable& ctx);
bool provably_real(const GiNaC::ex& e, const SymbolTable& ctx);

}  // namespace dc::detail
