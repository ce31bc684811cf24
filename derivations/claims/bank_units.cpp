// Units on a claim-bank line (internal/bank_units.hpp).
#include "derivations/claims/internal/bank_units.hpp"

#include <stdexcept>
#include <tuple>

namespace dc::claims {

BankUnits read_units(const nlohmann::json& line) {
  BankUnits out;
  if (!line.contains("units")) return out;
  const auto& u = line.at("units");
  if (!u.is_object()) throw std::invalid_argument("field 'units' must be an object {\"name\": \"unit\"}");
  out.given = true;
  for (auto it = u.begin(); it != u.end(); ++it) {
    if (!it.value().is_string())
      throw std::invalid_argument("the unit of '" + it.key() + "' must be a string such as \"m/s\"");
    const std::string text = it.value().get<std::string>();
    try {
      out.of[it.key()] = parse_dimension(parse_expression(text, SourcePos{"<units>", 1, 1}));
    } catch (const InputError& e) {
      throw std::invalid_argument("in field 'units', the unit of '" + it.key() + "' (column " +
                                  std::to_string(e.pos().col) + "): " + e.message());
    }
  }
  return out;
}

namespace {

// The table's symbols with the line's units (the others without a dimension).
SymbolTable dimension_table(const BankUnits& units, const SymbolTable& table, std::vector<std::string>& missing,
                            const std::vector<const Node*>& nodes) {
  SymbolTable out;
  for (const SymbolInfo& s : table.all()) {
    if (s.is_function) continue;
    SymbolInfo info;
    info.name = s.name;
    auto it = units.of.find(s.name);
    if (it != units.of.end()) {
      info.dimension = it->second;
      info.has_dimension = true;
    }
    out.declare(std::move(info));
  }
  for (const Node* n : nodes) {
    std::vector<const Node*> ids;
    collect_identifiers(*n, ids);
    for (const Node* id : ids) {
      if (id->kind != NodeKind::Symbol || !table.find(id->text) || table.find(id->text)->is_function) continue;
      if (units.of.count(id->text)) continue;
      bool seen = false;
      for (const auto& m : missing) seen = seen || m == id->text;
      if (!seen) missing.push_back(id->text);
    }
  }
  return out;
}

}  // namespace

std::optional<std::string> dimension_evidence(const BankUnits& units, const SymbolTable& table, const Node& a,
                                              const std::string& a_name, const Node& b, const std::string& b_name,
                                              const Node* times) {
  if (!units.given) return std::nullopt;
  std::vector<std::string> missing;
  std::vector<const Node*> nodes{&a, &b};
  if (times) nodes.push_back(times);
  const SymbolTable dims = dimension_table(units, table, missing, nodes);
  if (!missing.empty()) {
    std::string list;
    for (std::size_t i = 0; i < missing.size(); ++i) list += (i ? ", " : "") + missing[i];
    return "dimensions not checked: no unit for " + list;
  }
  Dimension da, db;
  for (const auto& [node, name, out] : {std::tuple{&a, &a_name, &da}, std::tuple{&b, &b_name, &db}}) {
    try {
      *out = dimension_of(*node, dims);
    } catch (const InputError& e) {
      return "dimensions: " + *name + ": " + e.message();
    }
  }
  if (times) {
    try {
      db = db * dimension_of(*times, dims);
    } catch (const InputError& e) {
      return "dimensions: " + e.message();
    }
  }
  if (da == db || is_literal_zero(a) || is_literal_zero(b)) return std::nullopt;
  return "dimensions differ: " + a_name + " is " + da.to_string() + ", " + b_name + " is " + db.to_string();
}

}  // namespace dc::claims
