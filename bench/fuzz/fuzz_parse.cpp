// libFuzzer harness: the expression parser alone (no GiNaC), fast enough for millions of inputs.
// The bytes are one relation as written in a claim: parse_relation returns a tree or throws
// InputError; the tree prints (to_text) and the printed form parses again to the same text.
// fuzz_expr continues into the GiNaC conversion (diff, limit, ... carried out).
#include "bench/fuzz/fuzz_common.hpp"
#include "derivations/core/expr.hpp"

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
  const std::string printed = dc::to_text(r);
  dc::ParseLimits relaxed;   // the printed form may nest deeper (added parentheses)
  relaxed.max_depth = 1000;
  relaxed.max_tree_depth = 20000;
  relaxed.max_length = 1000000;
  try {
    dc::Relation again = dc::parse_relation(printed, dc::SourcePos{"<printed>", 1, 1}, relaxed);
    if (dc::to_text(again) != printed) dc_fuzz::fail("to_text(parse(to_text(r))) != to_text(r)", printed, dc::to_text(again));
  } catch (const dc::InputError& e) {
    dc_fuzz::fail("to_text(r) does not parse", printed, e.format());
  }
  return 0;
}
