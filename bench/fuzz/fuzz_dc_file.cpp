// libFuzzer harness: the .dc file reader. The bytes are a whole derivation file, read the way
// load_derivation reads one (parse_derivation: text normalisation, statements, declarations,
// rule lines, expressions, label references, symbol resolution). A file that parses is also
// converted to GiNaC step by step (claim_sides, erratum_error), as the checker does before proving;
// the checker catches std::exception there (rules.cpp), so only crashes and sanitizer reports count.
#include <exception>

#include "bench/fuzz/fuzz_common.hpp"
#include "derivations/reader/derivation.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 16384) return 0;  // longer inputs only slow the search; the limits have unit tests
  dc::SourceText src{"fuzz.dc", dc_fuzz::bytes(data, size)};
  dc::Derivation d;
  try {
    d = dc::parse_derivation(std::move(src));
  } catch (const dc::InputError& e) {
    dc_fuzz::touch(e);
    return 0;
  }
  for (const auto& s : d.steps) {
    try {
      if (auto e = dc::erratum_error(d, s)) dc_fuzz::touch(*e);
      (void)dc::claim_sides(d, s);
    } catch (const dc::InputError& e) {
      dc_fuzz::touch(e);
    } catch (const std::exception&) {
    }
  }
  return 0;
}
