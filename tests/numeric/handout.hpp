// The handout derivation files, loaded once per test binary.
#pragma once
#include <map>
#include <string>

#include "derivations/core/derivation.hpp"

namespace dc::test {

inline const std::string kHandoutDir = std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9/";

inline const dc::Derivation& handout(const std::string& file) {
  static std::map<std::string, dc::Derivation> cache;
  auto it = cache.find(file);
  if (it == cache.end()) it = cache.emplace(file, dc::load_derivation(kHandoutDir + file)).first;
  return it->second;
}

}  // namespace dc::test
