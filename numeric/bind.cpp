// Binding a user's point to a formula of a derivation, and `derivcheck eval`.
#include <algorithm>
#include <set>
#include <sstream>
#include <stdexcept>

#include "numeric/exact.hpp"
#include "numeric/reference.hpp"

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
    if (it == names.end())
      throw std::domain_error("unknown parameter '" + name + "': formula '" + f.label +
                              "' has parameters " + join(names));
    const SymbolInfo* info = d.symbols.find(name);
    if (info && !info->domain.contains(value))
      throw std::domain_error("parameter '" + name + "' = " + exact_text(value) +
                              " is outside its declared domain (" + info->domain.to_string() + ")");
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
    if (!c.holds_at(point))
      throw std::domain_error("the point violates the assumption '" + c.text + "'");
  }
  return point;
}

std::string eval_formula(const Derivation& d, const std::string& label, const std::string& at,
                         int digits) {
  if (digits < 1 || digits > 1000)
    throw std::domain_error("--digits " + std::to_string(digits) + " is outside [1, 1000]");
  const Formula f = formula(d, label);
  const GiNaC::exmap point = bind_point(d, f, parse_assignments(at));
  const GiNaC::numeric v = reference_value(f.expr, point, digits);
  return format_significant(v, digits);
}

}  // namespace dc::num
