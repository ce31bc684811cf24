// The reference: CLN evaluation of a formula at a point given as exact rationals.
//
// Substituting exact rationals makes every rational subexpression exact (GiNaC keeps rational
// arithmetic exact); only transcendental functions are evaluated in floating point (CLN long
// floats). Because cancellation inside a formula can eat working digits, the value is computed
// at two precisions (digits+10 and 2*digits+20) and accepted only when they agree to digits+2;
// otherwise the precision is raised (up to 2000 digits) before giving up. GiNaC::Digits is a
// process-wide global and is restored afterwards (dc::DigitsGuard).
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/reader/derivation.hpp"
#include "derivations/kernel/ball.hpp"

namespace dc::num {

// The real value of `e` at `point` (symbol -> exact number) to at least `digits` correct
// significant digits (an exact rational when `e` is rational at the point). Throws
// std::domain_error when `e` is undefined (division by zero) or not real at the point, or
// when symbols remain unbound (naming them).
GiNaC::numeric reference_value(const GiNaC::ex& e, const GiNaC::exmap& point, int digits);

// "m1=1,m2=5/2, e=0.5" -> {("m1",1), ("m2",5/2), ("e",1/2)}; values are exact rationals in the
// forms parse_rational accepts. Throws std::invalid_argument naming the malformed item or a
// repeated name.
std::vector<std::pair<std::string, GiNaC::numeric>> parse_assignments(const std::string& text);

// Binds values to the parameters of formula `f` of derivation `d`, checking: every name is a
// parameter of the formula or a declared symbol that cancelled out of it (its value is checked
// and changes nothing), every parameter has a value, each value lies in its symbol's
// declared domain, and the file's `assume` constraints that involve only bound symbols hold.
// Throws std::domain_error naming the parameter, value and bound (or constraint).
GiNaC::exmap bind_point(const Derivation& d, const Formula& f,
                        const std::vector<std::pair<std::string, GiNaC::numeric>>& values);

// Arb's enclosure of `e` at `point` with `prec` bits: the ball when it is a finite real
// enclosure; nullopt (and the reason in `why`) when this precision cannot decide. Throws
// std::domain_error when the formula certainly has no real value there or divides by zero.
std::optional<kernel::Ball> enclose_formula(const GiNaC::ex& e, const GiNaC::exmap& point, long prec,
                                            std::string* why);

// `derivcheck eval`: the formula's value at the point, printed with `digits` significant
// digits (format_significant: deterministic).
std::string eval_formula(const Derivation& d, const std::string& label, const std::string& at,
                         int digits);

}  // namespace dc::num
