// libFuzzer harness: one line of a claim bank (`derivcheck claims`), dc::check_claim_line, which
// must never throw (a malformed line is a result with "error"). Valid claims are proved, so this
// is the slow harness: the probe runs with fewer points at lower precision (ProveOptions below);
// it is still the same code path. Every result must serialise as JSON text.
#include "bench/fuzz/fuzz_common.hpp"
#include "derivations/claims/claims.hpp"
#include "derivations/syntax/io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 2048) return 0;
  std::string line = dc_fuzz::bytes(data, size);
  if (line.find('\n') != std::string::npos) return 0;  // the bank reader splits lines first
  dc::ProveOptions opt;
  opt.digits = 30;
  opt.max_terms = 20000;
  nlohmann::ordered_json out = dc::check_claim_line(line, 1, "fuzz.jsonl", opt);
  if (!out.contains("verdict")) dc_fuzz::fail("claim result without a verdict", line, dc::json_text(out));
  (void)dc::json_text(out);
  return 0;
}
