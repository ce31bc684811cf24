#include "derivations/calculus/install.hpp"

#include "derivations/calculus/definite.hpp"
#include "derivations/calculus/limit_entry.hpp"

namespace dc::calculus {

namespace {

LimitResult two_sided_limit(const GiNaC::ex& f, const GiNaC::symbol& x, const GiNaC::ex& point, int at_infinity,
                            const SymbolTable& ctx) {
  return compute_limit(f, x, point, at_infinity, ctx);
}

}  // namespace

void install() {
  CalculusHooks h;
  h.limit = &two_sided_limit;
  h.definite = &integrals::definite_integral;
  set_calculus_hooks(h);
}

}  // namespace dc::calculus
