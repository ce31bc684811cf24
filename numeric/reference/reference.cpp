#include "numeric/reference/reference.hpp"

#include <algorithm>
#include <set>
#include <sstream>
#include <stdexcept>

#include "derivations/symbolic/printer.hpp"
#include "derivations/decide/prove.hpp"
#include "numeric/reference/exact.hpp"

namespace dc::num {
namespace {

using GiNaC::ex;

void free_symbol_names(const ex& e, std::set<std::string>& out) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    out.insert(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
    return;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) free_symbol_names(e.op(i), out);
}

// One evaluation at `prec` digits: a real numeric, or throws.
GiNaC::numeric eval_at(const ex& substituted, int prec) {
  DigitsGuard guard(prec);
  ex v;
  try {
    v = GiNaC::evalf(substituted);
  } catch (const std::exception& err) {
    throw std::domain_error(std::string("the formula is undefined at this point (") + err.what() + ")");
  }
  if (!GiNaC::is_a<GiNaC::numeric>(v))
    throw std::domain_error("the formula does not evaluate to a number at this point");
  const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(v);
  if (!n.is_real()) throw std::domain_error("the formula is not real at this point");
  return n;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i];
  return s;
}

}  // namespace

GiNaC::numeric reference_value(const GiNaC::ex& e, const GiNaC::exmap& point, int digits) {
  if (digits < 1 || digits > 1000)
    throw std::domain_error("digits = " + std::to_string(digits) + " is outside [1, 1000]");
  ex s;
  try {
    s = e.subs(point, GiNaC::subs_options::no_pattern);
  } catch (const std::exception& err) {
    // e.g. "power::eval(): division by zero"
    throw std::domain_error(std::string("the formula is undefined at this point (division by zero)"));
  }
  if (GiNaC::is_a<GiNaC::numeric>(s)) {
    const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(s);
    if (!n.is_real()) throw std::domain_error("the formula is not real at this point");
    if (n.is_rational()) return n;  // exact
  }
  std::set<std::string> unbound;
  free_symbol_names(s, unbound);
  if (!unbound.empty())
    throw std::domain_error("no value for " + join(std::vector<std::string>(unbound.begin(), unbound.end())));
  int p1 = digits + 10;
  GiNaC::numeric a = eval_at(s, p1);
  for (;;) {
    const int p2 = 2 * p1;
    const GiNaC::numeric b = eval_at(s, p2);
    // agree to digits+2 significant digits? A float zero from a transcendental function is
    // suspect (acos(1 - 1e-162) is 0 at 50 and at 100 digits): confirm it up to 2000 digits.
    if (b.is_zero() && a.is_zero()) {
      if (p2 > 2000) return b;
    } else {
      DigitsGuard guard(p2);
      const GiNaC::numeric diff = GiNaC::abs(a - b);
      const GiNaC::numeric tol = GiNaC::abs(b) * GiNaC::pow(GiNaC::numeric(10), GiNaC::numeric(-(digits + 2)));
      if (diff <= tol) return b;
    }
    if (p2 > 2000)
      throw std::domain_error("the value could not be determined to " + std::to_string(digits) +
                              " digits (cancellation beyond 2000 digits)");
    p1 = p2;
    a = b;
  }
}

std::vector<std::pair<std::string, GiNaC::numeric>> parse_assignments(const std::string& text) {
  std::vector<std::pair<std::string, GiNaC::numeric>> out;
  std::set<std::string> seen;
  std::stringstream ss(text);
  std::string item;
  auto trim = [](std::string s) {
    const auto b = s.find_first_not_of(" \t");
    const auto e = s.find_last_not_of(" \t");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
  };
  while (std::getline(ss, item, ',')) {
    item = trim(item);
    if (item.empty()) continue;
    const auto eq = item.find('=');
    if (eq == std::string::npos)
      throw std::invalid_argument("--at: expected NAME=VALUE, got '" + item + "'");
    const std::string name = trim(item.substr(0, eq)), value = trim(item.substr(eq + 1));
    if (name.empty()) throw std::invalid_argument("--at: missing name in '" + item + "'");
    GiNaC::numeric v;
    if (!parse_rational(value, v))
      throw std::invalid_argument("--at: value of '" + name + "' is not an exact rational: '" + value +
                                  "' (write e.g. 5/2, -0.125 or 1e-9)");
    if (!seen.insert(name).second) throw std::invalid_argument("--at: '" + name + "' is given twice");
    out.emplace_back(name, v);
  }
  return out;
}

}  // namespace dc::num
