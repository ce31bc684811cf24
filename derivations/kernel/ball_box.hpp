// Interval evaluation over a box (ball.cpp): the enclosure behind sign decisions (sign.hpp).
#pragma once
#include <map>
#include <utility>

#include <ginac/ginac.h>

#include "derivations/kernel/ball.hpp"

namespace dc::kernel {

// Each symbol of a box ranges over the closed interval [lo, hi] of exact rationals.
using Box = std::map<GiNaC::ex, std::pair<GiNaC::numeric, GiNaC::numeric>, GiNaC::ex_is_less>;

// Enclose e over a box. A Value encloses every value e takes on the box and certifies that e is
// defined there (every real-only operation had an argument certainly inside its domain, every
// divisor was certainly nonzero).
Ball enclose_box(const GiNaC::ex& e, const Box& box, long prec_bits);

// Every point of the enclosure is >= 0 (a Value only).
bool certainly_nonnegative(const Ball& b);

}  // namespace dc::kernel
