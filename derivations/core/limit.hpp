// Limits and first-order expansions. GiNaC has no limit(); this is the helper.
#pragma once
#include <optional>
#include <string>

#include <ginac/ginac.h>

#include "derivations/core/symbols.hpp"

namespace dc {

struct LimitResult {
  bool ok = false;
  GiNaC::ex value;        // the limit (may be +-infinity as the symbol `oo` is not used:
                          // infinite limits are reported via `infinite` = +1/-1)
  int infinite = 0;
  std::string method;     // "substitution", "series at 0 of eps = 1/x", "series"
  std::string reason;     // when !ok: why it is undecided (Puiseux, essential singularity, ...)
  bool confirmed_numerically = false;  // evaluated along a sequence approaching the point
};

// lim_{x -> point} f. `point` is a finite exact value, or pass at_infinity = +1 / -1.
// Method: try direct substitution when f is continuous there; else substitute x = point + eps
// (or x = 1/eps at infinity), series in eps, check the leading term has non-negative degree
// and an eps-free coefficient; then confirm numerically along eps = 10^-k (CLN, 50 digits).
LimitResult compute_limit(const GiNaC::ex& f, const GiNaC::symbol& x, const GiNaC::ex& point,
                          int at_infinity, const SymbolTable& ctx);

// First order in the small quantities `smalls` (each scaled by eps, series to O(eps^2), eps=1):
// used for "higher-order term dm*dv neglected".
GiNaC::ex first_order(const GiNaC::ex& f, const std::vector<GiNaC::symbol>& smalls);

// f = f(point) + f'(point)(x - point) + O((x-point)^2): the first-order series of f in x.
// With `ctx`, the expansion is checked (ball arithmetic) on every side of the point that the
// declared domain of x allows; one that holds only from one side (abs(x) = x + O(x^2) at 0 for
// real x) gives nullopt with the reason.
std::optional<GiNaC::ex> series_first_order(const GiNaC::ex& f, const GiNaC::symbol& x,
                                            const GiNaC::ex& point, std::string* reason = nullptr,
                                            const SymbolTable* ctx = nullptr);

}  // namespace dc
