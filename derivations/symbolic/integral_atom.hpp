// A definite integral of a declared function — the normalisation integral(psi(x)^2, x, 0, L) of
// a wave function, the work integral(F(x), x, a, b) of an unspecified force — has no closed
// form, but it is a quantity: a number for each value of its limits and parameters, linear in
// its integrand. References can then determine it and eliminate it like any other quantity
// (`integral(psi(x)^2, x, 0, L) = 1` makes `2*integral(psi(x)^2, x, 0, L) = 2` follow).
//
// Such an integral becomes an *integral quantity*: an application of an opaque GiNaC function
// whose arguments are an identifier of the integrand (a hash of its canonical text), the limits
// and the integrand's parameters, so a substitution or sample point reaches every quantity it
// depends on. The integrand is split first by linearity: constant factors come out
// (integral(2*A*psi^2) = 2*A*integral(psi^2)), sums split, and a part without a declared
// function is integrated as before. Two integrals with the same integrand (up to the name of
// the variable of integration) and limits are one quantity; derivatives follow Leibniz's rule
// (d/db = the integrand at b, d/dp = the integral of the derivative) where the integrand is
// continuous.
//
// What this does not know: relations *between* different integral quantities (a change of
// variable, adjacent intervals, integration by parts). So a proof that treats them as
// independent unknowns is sound (it holds for any values they take), while two sides that
// differ only when they are treated as independent prove nothing false: the kernel never
// refutes a claim that contains one (kernel/probe.cpp), it leaves it undecided.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <utility>

#include <ginac/ginac.h>

#include "derivations/symbolic/symbols.hpp"

namespace dc {

struct IntegralSpec {
  GiNaC::ex f;              // the integrand, in the variable of integration t
  GiNaC::ex t;              // the variable of integration (a fresh symbol of `bound`)
  GiNaC::ex a, b;           // the limits (0 where infinite)
  int a_inf = 0, b_inf = 0; // -1 / +1: that limit is -oo / oo
  const SymbolTable* bound = nullptr;   // the table t belongs to
};

// Does the integrand apply a declared function (or a derivative of one) to an expression
// containing t? Only then is the integral a quantity of its own.
bool integrand_applies_function(const GiNaC::ex& f, const GiNaC::ex& t);

// The integral as a sum of integral quantities times constant factors, plus `rest` applied to
// the part of the integrand that applies no declared function (its value by the usual
// methods; `rest` may throw, e.g. an undecided integral). A part that applies a declared
// function is given to `rest` first too, and becomes a quantity only when `rest` throws
// (integral(diff(psi(x), x), x, 0, L) keeps its value psi(L) - psi(0)). Throws
// std::runtime_error when the integrand is too large to split.
GiNaC::ex integral_quantity(const IntegralSpec& s, const std::function<GiNaC::ex(const GiNaC::ex& part)>& rest);

// Is e an integral quantity, or does it contain one?
bool is_integral_quantity(const GiNaC::ex& e);
bool has_integral_quantity(const GiNaC::ex& e);

// The parts of an integral quantity for printers: the integrand with the application's
// parameters substituted, the variable of integration, and the limits (infinite ones as
// nullopt with their sign). nullopt when e is not one.
struct IntegralView {
  GiNaC::ex f, t;
  GiNaC::ex a, b;
  int a_inf = 0, b_inf = 0;
};
std::optional<IntegralView> integral_view(const GiNaC::ex& e);
// A derivative of an integral quantity that Leibniz's rule does not give (the integrand is not
// continuous): which argument (1, 2: the limits; 3, ...: the parameters) and the quantity.
// An unknown quantity of its own, drawn independently by the probe (and never the ground of a
// refutation, as the quantities are not).
std::optional<std::pair<unsigned, GiNaC::ex>> unknown_partial_of(const GiNaC::ex& e);

}  // namespace dc
