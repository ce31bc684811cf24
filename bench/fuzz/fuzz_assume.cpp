// libFuzzer harness: the assumption list of `derivcheck equal --assume` and of a claim's "assume"
// field (parse_assumptions), and the domain syntax of declarations (parse_domain). Both either
// return or throw InputError. A parsed list then goes through what claim_table does with it short
// of the satisfiability search (fuzz_assume_sat covers that): its symbols are declared with their
// domains (conflicts and empty domains are InputErrors), each constraint's sides convert to GiNaC
// and each constraint passes the constant check (require_possible_assumption: "can never hold").
#include <map>
#include <vector>

#include "bench/fuzz/fuzz_common.hpp"
#include "derivations/claims/claims.hpp"
#include "derivations/decide/satisfiable.hpp"
#include "derivations/symbolic/symbols.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 1024) return 0;
  const std::string text = dc_fuzz::bytes(data, size);
  const dc::SourcePos at{"<assume>", 1, 1};
  try {
    (void)dc::parse_domain(text, at).to_string();
  } catch (const dc::InputError& e) {
    dc_fuzz::touch(e);
  }
  std::vector<dc::AssumptionItem> items;
  try {
    items = dc::parse_assumptions(text, at);
  } catch (const dc::InputError& e) {
    dc_fuzz::touch(e);
    return 0;
  }
  std::map<std::string, dc::Domain> domains;
  std::vector<const dc::Node*> ids;
  for (const auto& it : items) {
    if (it.is_constraint) {
      dc::collect_identifiers(it.lhs, ids);
      dc::collect_identifiers(it.rhs, ids);
    } else {
      domains.emplace(it.name, it.domain);
    }
  }
  dc::SymbolTable table;
  try {
    for (const auto& [name, d] : domains) {
      dc::SymbolInfo info;
      info.name = name;
      info.domain = d;
      table.declare(std::move(info));
    }
    for (const dc::Node* id : ids) {
      if (id->kind != dc::NodeKind::Symbol || dc::is_reserved_name(id->text) || table.find(id->text)) continue;
      dc::SymbolInfo info;
      info.name = id->text;
      table.declare(std::move(info));
    }
  } catch (const dc::InputError& e) {
    dc_fuzz::touch(e);
    return 0;
  }
  for (const auto& it : items) {
    if (!it.is_constraint) continue;
    try {
      dc::Constraint c;
      c.lhs = dc::to_ginac(it.lhs, table);
      c.rhs = dc::to_ginac(it.rhs, table);
      c.op = it.op;
      c.text = it.text;
      c.pos = it.pos;
      dc::require_possible_assumption(c, static_cast<int>(it.text.size()));
    } catch (const dc::InputError& e) {
      dc_fuzz::touch(e);
    } catch (const dc::UndecidedLimit&) {
    }
  }
  return 0;
}
