// libFuzzer harness: the assumption list of `derivcheck equal --assume` and of a claim's "assume"
// field (parse_assumptions), and the domain syntax of declarations (parse_domain). Both either
// return or throw InputError; a parsed list also builds the claim symbol table (claim_table, which
// checks that the assumptions can hold together: InputError when they cannot).
#include <map>
#include <vector>

#include "bench/fuzz/fuzz_common.hpp"
#include "derivations/core/claims.hpp"
#include "derivations/core/symbols.hpp"

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
  std::map<std::string, dc::DomainAt> domains;
  std::vector<const dc::Node*> ids;
  for (const auto& it : items) {
    if (it.is_constraint) {
      dc::collect_identifiers(it.lhs, ids);
      dc::collect_identifiers(it.rhs, ids);
    } else if (!domains.count(it.name)) {
      domains[it.name] = {it.domain, it.pos};
    }
  }
  try {
    (void)dc::claim_table(ids, domains, items, at);
  } catch (const dc::InputError& e) {
    dc_fuzz::touch(e);
  }
  return 0;
}
