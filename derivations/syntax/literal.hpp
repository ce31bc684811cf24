// Exact values of numeric literals ("2.5" is 5/2, never a double). Used by to_ginac and by
// parse_domain.
#pragma once
#include <string_view>

#include <ginac/ginac.h>

namespace dc {

// The literal's exact rational value: digits ('.' digits)?; "0.25" -> 1/4, "007" -> 7.
// Precondition: `literal` was accepted by the expression tokenizer (digits and at most one '.').
GiNaC::numeric exact_literal(std::string_view literal);

}  // namespace dc
