// Signs over the declared domain, decided rigorously where range analysis (range.hpp) is too
// coarse. Two methods, each sound and incomplete:
//   - Sturm: a polynomial in one symbol with rational coefficients has no real root of odd
//     multiplicity (for >= 0) or none at all (for > 0, != 0) in the symbol's declared domain
//     (Sturm's theorem counts the roots of its square-free part; irrational ends are enclosed
//     outward, so the interval counted contains the domain), and its sign at one interior
//     rational point is the sign wanted;
//   - subdivision: every symbol of the expression has a bounded declared domain; the box of
//     their closed hulls is bisected (widest side first, at most `kMaxBoxes` boxes) and the
//     expression enclosed on each piece in Arb balls (ball.hpp, enclose_box) until every piece
//     has the sign wanted.
// Constraints (assumptions) are not used: the set examined contains the admissible one.
// Returns the method that decided, as evidence text ("Sturm sequence: no real root of
// x^2 - 2*x + 2 in (-oo, oo), positive at x = 0"), or nullopt.
#pragma once
#include <optional>
#include <string>

#include <ginac/ginac.h>

#include "derivations/symbolic/symbols.hpp"

namespace dc::kernel {

enum class SignWant { Positive, Nonnegative, Nonzero };

std::optional<std::string> decide_sign(const GiNaC::ex& e, SignWant want, const SymbolTable& ctx);
// Sturm sequences only (cheap: used by provably_positive, range.hpp).
std::optional<std::string> decide_sign_by_sturm(const GiNaC::ex& e, SignWant want, const SymbolTable& ctx);

// The square-free part of p (a polynomial in x with rational coefficients) has a real root in
// the open interval (lo, hi); ends are rationals, lo_inf / hi_inf mark -oo / +oo.
bool sturm_root_inside(GiNaC::ex p, const GiNaC::symbol& x, const GiNaC::numeric& lo, bool lo_inf,
                       const GiNaC::numeric& hi, bool hi_inf);

}  // namespace dc::kernel
