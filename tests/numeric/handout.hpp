// The handout derivation files, loaded once per test binary.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "derivations/reader/derivation.hpp"
#include "numeric/evaluator.hpp"

namespace dc::test {

inline const std::string kHandoutDir = std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9/";

inline const dc::Derivation& handout(const std::string& file) {
  static std::map<std::string, dc::Derivation> cache;
  auto it = cache.find(file);
  if (it == cache.end()) it = cache.emplace(file, dc::load_derivation(kHandoutDir + file)).first;
  return it->second;
}

// A formula over plain symbols of its parameters' names (Formula::params are sliced copies: see
// derivation.hpp), or nothing when it does not compile to a tape (abstract functions).
struct PlainFormula {
  GiNaC::ex expr;
  std::vector<GiNaC::symbol> xs;
};
inline std::optional<PlainFormula> compilable_plain(const dc::Derivation& d, const dc::Formula& f) {
  PlainFormula p;
  GiNaC::exmap to_plain;
  for (const auto& s : f.params) {
    p.xs.emplace_back(s.get_name());
    to_plain[d.symbols.find(s.get_name())->sym] = p.xs.back();
  }
  p.expr = f.expr.subs(to_plain);
  try {
    (void)dc::num::compile(p.expr, p.xs);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  return p;
}

}  // namespace dc::test
