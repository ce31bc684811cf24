// Exact conversions between machine floats and rationals, decimal formatting, and errors in
// ulps. Everything here is exact (CLN rationals) so that the reference and the error
// measurement never add rounding of their own.
#pragma once
#include <string>

#include <ginac/ginac.h>

namespace dc::num {

// The exact rational value of a finite double / long double (throws std::domain_error for
// NaN or infinity, naming `what`).
GiNaC::numeric exact_rational(double x, const char* what = "value");
GiNaC::numeric exact_rational(long double x, const char* what = "value");

// The exact rational value of a real GiNaC number (a float is converted exactly, digit for
// digit of its binary representation). Throws std::domain_error if `x` is not real.
GiNaC::numeric to_exact(const GiNaC::numeric& x);

// Correctly rounded conversion of a real number to double / long double (via a 40-digit
// decimal string and strtod/strtold; the double rounding this implies can only matter when the
// value lies within 1e-40 relative of a rounding midpoint). Overflow gives +-inf.
double round_to_double(const GiNaC::numeric& x);
long double round_to_long_double(const GiNaC::numeric& x);

// Decimal text of a real number with `digits` significant digits, rounded half to even from the
// exact value. Deterministic: plain notation when the decimal exponent k satisfies
// -5 <= k < digits ("0.00012345", "1234.5"), otherwise "1.2345e+20" / "1.2345e-7".
// Zero prints as "0". With `scientific` the exponent form is always used.
std::string format_significant(const GiNaC::numeric& x, int digits, bool scientific = false);

// Parse an exact rational written as  [-]DIGITS[.DIGITS][e[-]DIGITS][/[-]DIGITS]  ("5/2",
// "-0.125", "1e-9", "3/4"). Returns false if `text` is not of that form (or divides by 0).
bool parse_rational(const std::string& text, GiNaC::numeric& out);

// The unit in the last place of double at the magnitude of `ref` (exact, a power of two;
// subnormal spacing 2^-1074 for |ref| < 2^-1022; ref = 0 gives 2^-1074).
GiNaC::numeric double_ulp(const GiNaC::numeric& ref);

// |computed - ref| in units of double_ulp(ref), as a double (inf if computed is not finite).
// `ref` may be a float of any precision or exact.
double error_in_ulps(long double computed, const GiNaC::numeric& ref);

}  // namespace dc::num
