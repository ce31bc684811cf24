// libFuzzer harness: the expression parser (expr.hpp). The bytes are one relation as written in
// a claim. Checked: parse_relation either returns a tree or throws InputError; the tree prints
// (to_text), and the printed form parses again to the same text (the printer is what reports and
// the LaTeX writer rely on); its identifiers are collected and, with every identifier a real
// symbol (as for `derivcheck equal`), each side converts to GiNaC or fails with an InputError /
// UndecidedLimit.
#include <exception>
#include <vector>

#include "bench/fuzz/fuzz_common.hpp"
#include "derivations/claims/claims.hpp"
#include "derivations/syntax/expr.hpp"
#include "derivations/symbolic/symbols.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return 0;
  const std::string text = dc_fuzz::bytes(data, size);
  dc::Relation r;
  try {
    r = dc::parse_relation(text, dc::SourcePos{"<fuzz>", 1, 1});
  } catch (const dc::InputError& e) {
    dc_fuzz::touch(e);
    return 0;
  }
  // Round trip: the printed form is the author's tree with the parentheses it needs.
  dc_fuzz::check_round_trip(dc::to_text(r));
  std::vector<const dc::Node*> ids;
  for (const auto& side : r.sides) dc::collect_identifiers(side, ids);
  dc::SymbolTable table;
  try {
    table = dc::claim_table(ids, {}, {}, dc::SourcePos{"<fuzz>", 1, 1});
  } catch (const dc::InputError& e) {
    dc_fuzz::touch(e);
    return 0;
  }
  for (const auto& side : r.sides) {
    try {
      (void)dc::to_ginac(side, table);
    } catch (const dc::InputError& e) {
      dc_fuzz::touch(e);
    } catch (const dc::UndecidedLimit&) {
    }
  }
  return 0;
}
