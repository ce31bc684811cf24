// libFuzzer harness: an assumption list as fuzz_assume reads it, then the whole claim symbol table
// (claim_table), which also searches for a point where all assumptions hold together (the
// satisfiability search: up to 2000 sample points, InputError when none is found). Slow (tens of
// executions per second under the sanitizers); tools/fuzz.sh runs it for as long as it is given.
#include <map>
#include <vector>

#include "bench/fuzz/fuzz_common.hpp"
#include "derivations/claims/claims.hpp"
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
