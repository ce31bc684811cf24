// Binding a user's point to a formula of a derivation, and `derivcheck eval`.
#include <algorithm>
#include <set>
#include <sstream>
#include <stdexcept>

#include "numeric/reference/exact.hpp"
#include "numeric/reference/reference.hpp"
#include "derivations/kernel/ball.hpp"
#include "derivations/kernel/sample.hpp"

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

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i];
  return s;
}

std::string exact_text(const GiNaC::numeric& v) {
  std::ostringstream os;
  os << v;  // exact rationals print deterministically: "3/2"
  return os.str();
}

}  // namespace

GiNaC::exmap bind_point(const Derivation& d, const Formula& f,
                        const std::vector<std::pair<std::string, GiNaC::numeric>>& values) {
  std::vector<std::string> names;
  for (const auto& s : f.params) names.push_back(s.get_name());
  GiNaC::exmap point;
  std::set<std::string> bound;
  for (const auto& [name, value] : values) {
    auto it = std::find(names.begin(), names.end(), name);
    const SymbolInfo* info = d.symbols.find(name);
    if (it == names.end() && !(info && !info->is_function))
      throw std::domain_error("unknown parameter '" + name + "': formula '" + f.label +
                              "' has parameters " + join(names));
    if (info && !info->domain.contains(value))
      throw std::domain_error("parameter '" + name + "' = " + exact_text(value) +
                              " is outside its declared domain (" + info->domain.to_string() + ")");
    if (it == names.end()) {
      // a declared symbol that cancelled out of the formula ((m*v^2)/(m*v) has no m): its
      // value is checked against its domain and the assumptions, and changes nothing
      point[info->sym] = value;
      continue;
    }
    // the table's symbol (a possymbol for positive symbols), not the sliced copy in f.params
    point[info ? info->sym : GiNaC::ex(f.params[static_cast<std::size_t>(it - names.begin())])] = value;
    bound.insert(name);
  }
  std::vector<std::string> missing;
  for (const auto& n : names)
    if (!bound.count(n)) missing.push_back(n);
  if (!missing.empty())
    throw std::domain_error("missing value for parameter" + std::string(missing.size() > 1 ? "s " : " ") +
                            join(missing) + " of formula '" + f.label + "' (give --at " + missing[0] + "=...)");
  for (const Constraint& c : d.symbols.constraints()) {
    const ex l = c.lhs.subs(point), r = c.rhs.subs(point);
    std::set<std::string> rest;
    free_symbol_names(l, rest);
    free_symbol_names(r, rest);
    if (!rest.empty()) continue;  // involves symbols outside this formula
    if (!kernel::holds_at(c, point))
      throw std::domain_error("the point violates the assumption '" + c.text + "'");
  }
  return point;
}

std::optional<kernel::Ball> enclose_formula(const GiNaC::ex& e, const GiNaC::exmap& point, long prec,
                                            std::string* why) {
  kernel::Ball b = kernel::enclose_at(e, &point, prec);
  if (b.status == kernel::BallStatus::NotReal)
    throw std::domain_error("the formula has no real value at this point (" + b.why + ")");
  if (b.status == kernel::BallStatus::Pole)
    throw std::domain_error("the formula is undefined at this point (" + b.why + ")");
  if (b.status != kernel::BallStatus::Value) {
    if (why) *why = b.why;
    return std::nullopt;
  }
  return b;
}

std::string eval_formula(const Derivation& d, const std::string& label, const std::string& at,
                         int digits) {
  if (digits < 1 || digits > 1000)
    throw std::domain_error("--digits " + std::to_string(digits) + " is outside [1, 1000]");
  const Formula f = formula(d, label);
  const GiNaC::exmap point = bind_point(d, f, parse_assignments(at));
  // Certified: Arb encloses the value; the precision is raised until both ends of the
  // enclosure round to the same `digits` significant digits, which are then exactly the
  // correctly rounded value. No float of limited exponent range takes part, so a huge or tiny
  // value is never printed as a wrong finite number.
  const long want_bits = static_cast<long>(digits * 3.33) + 16;
  std::string why = "the enclosure did not narrow";
  for (long prec = want_bits + 48; prec <= (1L << 18); prec *= 2) {
    std::optional<kernel::Ball> enclosed = enclose_formula(f.expr, point, prec, &why);
    if (!enclosed) continue;
    const kernel::Ball& b = *enclosed;
    GiNaC::numeric lo, hi;
    if (!b.exact_bounds(lo, hi)) {   // beyond 2^(2^20): shown as 10^(x) once x is known well
      if (b.rel_accuracy_bits() >= 48) return b.text(digits);
      why = "a value beyond 2^(2^20) not yet enclosed tightly";
      continue;
    }
    std::string a = format_significant(lo, digits), c = format_significant(hi, digits);
    if (a == c) return a;
    why = "the value lies in [" + format_significant(lo, 5) + ", " + format_significant(hi, 5) + "]";
  }
  throw std::range_error("the value could not be certified to " + std::to_string(digits) +
                         " digits within the precision cap (" + why + "); it may be exactly 0");
}

}  // namespace dc::num
