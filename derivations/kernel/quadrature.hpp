// Rigorous definite integrals (Arb's acb_calc_integrate: adaptive Gauss-Legendre with error
// bounds from analyticity on ellipses around each subinterval), and the numeric check of a
// claimed closed form for a definite integral at sampled parameter values.
#pragma once
#include <ginac/ginac.h>

#include "derivations/symbolic/symbols.hpp"
#include "derivations/symbolic/verdict.hpp"
#include "derivations/kernel/ball.hpp"

namespace dc::kernel {

// integral of f over x from a to b, where f has no free symbol but x and a, b are constants.
// Value: an enclosure of the (real) integral; NotReal: the integrand is not real on [a, b]
// (certified); Unknown: the integrand is not analytic near the path (|x|, a kink), an
// unsupported function, or the evaluation budget ran out.
Ball integrate_constant(const GiNaC::ex& f, const GiNaC::symbol& x, const GiNaC::ex& a, const GiNaC::ex& b,
                        long prec_bits);

// Does integral(f, x, a, b) = G hold on the declared domain? Parameters (every symbol but x)
// are sampled as in the probe; at each point the integral is enclosed rigorously and compared
// with G: a certified difference refutes, rigorous agreement at every point holds numerically.
Verdict probe_definite_integral(const GiNaC::ex& f, const GiNaC::symbol& x, const GiNaC::ex& a, const GiNaC::ex& b,
                                const GiNaC::ex& G, const SymbolTable& ctx, const ProveOptions& opt);

}  // namespace dc::kernel
