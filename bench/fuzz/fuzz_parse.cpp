// libFuzzer harness: the expression parser alone (no GiNaC), fast enough for millions of inputs.
// The bytes are one relation as written in a claim: parse_relation returns a tree or throws
// InputError; the tree prints (to_text) and the printed form parses again to the same text.
// fuzz_expr continues into the GiNaC conversion (diff, limit, ... carried out).
#include "bench/fuzz/fuzz_common.hpp"
#include "derivations/syntax/expr.hpp"

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
  dc_fuzz::check_round_trip(dc::to_text(r));
  return 0;
}
