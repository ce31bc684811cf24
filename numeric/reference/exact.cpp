#include "numeric/reference/exact.hpp"

#include <cln/cln.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace dc::num {
namespace {

cln::cl_RA as_cl_ra(const GiNaC::numeric& x) {
  if (!x.is_real()) throw std::domain_error("number is not real");
  const cln::cl_R r = cln::the<cln::cl_R>(x.to_cl_N());
  return cln::rational(r);
}

std::string decimal(const cln::cl_I& i) {
  std::ostringstream os;
  os << i;
  return os.str();
}

// 2^k / 10^k for any integer k (cln::expt_pos requires a positive exponent: expt_pos(x, 0)
// does not terminate)
cln::cl_RA ipow(long base, long k) {
  if (k == 0) return 1;
  if (k > 0) return cln::expt_pos(cln::cl_I(base), static_cast<unsigned long>(k));
  return cln::cl_RA(1) / cln::expt_pos(cln::cl_I(base), static_cast<unsigned long>(-k));
}

cln::cl_I from_u64(std::uint64_t v) {
  return cln::cl_I(static_cast<unsigned long long>(v));
}

// x = mant * 2^exp2 exactly, mant an integer (sign included)
GiNaC::numeric from_parts(bool negative, std::uint64_t mant, long exp2) {
  cln::cl_RA r = from_u64(mant) * ipow(2, exp2);
  if (negative) r = -r;
  return GiNaC::numeric(r);
}

cln::cl_RA pow10(long k) { return ipow(10, k); }

}  // namespace

GiNaC::numeric exact_rational(double x, const char* what) {
  if (!std::isfinite(x))
    throw std::domain_error(std::string(what) + " is not finite");
  if (x == 0) return GiNaC::numeric(0);
  int e = 0;
  double m = std::frexp(std::fabs(x), &e);  // |x| = m 2^e, m in [0.5, 1)
  auto mant = static_cast<std::uint64_t>(std::ldexp(m, 53));
  return from_parts(x < 0, mant, static_cast<long>(e) - 53);
}

GiNaC::numeric exact_rational(long double x, const char* what) {
  if (!std::isfinite(x))
    throw std::domain_error(std::string(what) + " is not finite");
  if (x == 0) return GiNaC::numeric(0);
  int e = 0;
  long double m = std::frexp(std::fabs(x), &e);
  constexpr int bits = std::numeric_limits<long double>::digits;  // 64 on x86
  static_assert(bits <= 64, "long double mantissa wider than 64 bits");
  auto mant = static_cast<std::uint64_t>(std::ldexp(m, bits));
  return from_parts(x < 0, mant, static_cast<long>(e) - bits);
}

GiNaC::numeric to_exact(const GiNaC::numeric& x) { return GiNaC::numeric(as_cl_ra(x)); }

std::string format_significant(const GiNaC::numeric& x, int digits, bool scientific) {
  if (digits < 1) digits = 1;
  cln::cl_RA r = as_cl_ra(x);
  if (cln::zerop(r)) return "0";
  const bool negative = cln::minusp(r);
  cln::cl_RA a = cln::abs(r);
  // decimal exponent k = floor(log10 a)
  long k = static_cast<long>(decimal(cln::numerator(a)).size()) -
           static_cast<long>(decimal(cln::denominator(a)).size());
  while (a < pow10(k)) --k;
  while (a >= pow10(k + 1)) ++k;
  cln::cl_I n = cln::round1(a * pow10(digits - 1 - k));  // ties to even
  std::string s = decimal(n);
  if (static_cast<int>(s.size()) > digits) {  // rounded up to 10^digits
    ++k;
    n = cln::round1(a * pow10(digits - 1 - k));
    s = decimal(n);
  }
  std::string out = negative ? "-" : "";
  if (!scientific && k >= -5 && k < digits) {
    if (k >= 0) {
      out += s.substr(0, static_cast<std::size_t>(k) + 1);
      if (static_cast<int>(s.size()) > k + 1) out += "." + s.substr(static_cast<std::size_t>(k) + 1);
    } else {
      out += "0." + std::string(static_cast<std::size_t>(-k - 1), '0') + s;
    }
    return out;
  }
  out += s.substr(0, 1);
  if (s.size() > 1) out += "." + s.substr(1);
  out += (k < 0 ? "e-" : "e+");
  std::string ks = std::to_string(k < 0 ? -k : k);
  if (ks.size() < 2) ks = "0" + ks;
  return out + ks;
}

double round_to_double(const GiNaC::numeric& x) {
  const std::string s = format_significant(x, 40, true);
  return std::strtod(s.c_str(), nullptr);
}

long double round_to_long_double(const GiNaC::numeric& x) {
  const std::string s = format_significant(x, 40, true);
  return std::strtold(s.c_str(), nullptr);
}

bool parse_rational(const std::string& text, GiNaC::numeric& out) {
  // [-]DIGITS[.DIGITS][e[-]DIGITS]
  auto parse_decimal = [](const std::string& t, cln::cl_RA& v) -> bool {
    std::size_t i = 0;
    bool neg = false;
    if (i < t.size() && (t[i] == '-' || t[i] == '+')) neg = t[i++] == '-';
    std::string intpart, frac;
    while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) intpart += t[i++];
    if (i < t.size() && t[i] == '.') {
      ++i;
      while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) frac += t[i++];
    }
    if (intpart.empty() && frac.empty()) return false;
    long exp10 = 0;
    if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
      ++i;
      bool eneg = false;
      if (i < t.size() && (t[i] == '-' || t[i] == '+')) eneg = t[i++] == '-';
      std::string ed;
      while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) ed += t[i++];
      if (ed.empty() || ed.size() > 5) return false;
      exp10 = std::stol(ed) * (eneg ? -1 : 1);
    }
    if (i != t.size()) return false;
    const std::string digits = intpart + frac;
    if (digits.size() > 400) return false;
    cln::cl_I n = 0;
    for (char c : digits) n = n * 10 + (c - '0');
    v = n * pow10(exp10 - static_cast<long>(frac.size()));
    if (neg) v = -v;
    return true;
  };
  const auto slash = text.find('/');
  cln::cl_RA num, den = 1;
  if (!parse_decimal(text.substr(0, slash), num)) return false;
  if (slash != std::string::npos) {
    if (!parse_decimal(text.substr(slash + 1), den)) return false;
    if (cln::zerop(den)) return false;
  }
  out = GiNaC::numeric(num / den);
  return true;
}

GiNaC::numeric double_ulp(const GiNaC::numeric& ref) {
  cln::cl_RA a = cln::abs(as_cl_ra(ref));
  long e = -1074 + 52;  // exponent floor for subnormals: spacing 2^-1074
  if (!cln::zerop(a)) {
    long k = static_cast<long>(cln::integer_length(cln::numerator(a))) -
             static_cast<long>(cln::integer_length(cln::denominator(a)));
    auto p2 = [](long j) { return ipow(2, j); };
    while (a < p2(k)) --k;
    while (a >= p2(k + 1)) ++k;
    e = std::max(k, -1022L);
  }
  const long u = e - 52;
  return GiNaC::numeric(ipow(2, u));
}

double error_in_ulps(long double computed, const GiNaC::numeric& ref) {
  if (!std::isfinite(computed)) return std::numeric_limits<double>::infinity();
  const cln::cl_RA c = as_cl_ra(exact_rational(computed));
  const cln::cl_RA r = as_cl_ra(ref);
  const cln::cl_RA u = as_cl_ra(double_ulp(ref));
  return cln::double_approx(cln::abs(c - r) / u);
}

}  // namespace dc::num
