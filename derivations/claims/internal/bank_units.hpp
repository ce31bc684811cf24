// Units on a claim-bank line (internal to derivations/claims/). The optional field "units"
// ({"v": "m/s", "m": "kg", "g": "m/s^2", "n": "1"}) gives symbols their units, and the claim's
// sides are compared by dimension before anything is computed: a student's answer with the
// wrong dimension is wrong whatever numbers it gives, and the mismatch is the first evidence
// the line reports. The verdict itself stays the rule's (a mismatch between sides that are
// both zero is not a refutation of the value).
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "derivations/symbolic/symbols.hpp"

namespace dc::claims {

struct BankUnits {
  std::map<std::string, Dimension> of;   // by symbol name
  bool given = false;                    // the line has a "units" field
};

// Reads the field "units". Throws std::invalid_argument with the field error's message.
BankUnits read_units(const nlohmann::json& line);

// The dimensional verdict on `a` against `b` ("lhs" and "rhs", or "d rhs / d var" and "lhs"):
//   - nullopt: the dimensions agree, or the line gives no units;
//   - "dimensions differ: lhs is kg·m/s, rhs is kg·m²/s" when they differ;
//   - "dimensions not checked: no unit for x, y" when a symbol of either side has none;
//   - "dimensions: lhs: cannot add kg and m" when a side is inconsistent in itself.
// `times`: a factor of b's dimension (the variable of an antiderivative: F has the dimension
// of f times x), or nullptr.
std::optional<std::string> dimension_evidence(const BankUnits& units, const SymbolTable& table, const Node& a,
                                              const std::string& a_name, const Node& b, const std::string& b_name,
                                              const Node* times = nullptr);

}  // namespace dc::claims
