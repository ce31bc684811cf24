// Exact values of numeric literals (literal.hpp).
#include "derivations/syntax/literal.hpp"

#include <string>

#include <cln/integer.h>

namespace dc {

GiNaC::numeric exact_literal(std::string_view literal) {
  std::string digits;
  digits.reserve(literal.size());
  int frac = 0;
  bool after_point = false;
  for (char c : literal) {
    if (c == '.') {
      after_point = true;
      continue;
    }
    digits += c;
    if (after_point) ++frac;
  }
  std::size_t nz = digits.find_first_not_of('0');
  digits = nz == std::string::npos ? "0" : digits.substr(nz);
  GiNaC::numeric value(cln::cl_I(digits.c_str()));
  if (frac > 0) value = value / GiNaC::numeric(10).power(frac);
  return value;
}

}  // namespace dc
