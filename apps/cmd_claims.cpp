// derivcheck claims FILE.jsonl — batch-check a claim bank, one JSON result per line (docs/cli.md).
#include <iostream>

#include "apps/commands.hpp"
#include "derivations/core/claims.hpp"
#include "derivations/core/io.hpp"

namespace dc::cli {
namespace {

struct ClaimsOptions {
  std::string file;
  bool no_timings = false;
};

int run(const ClaimsOptions& o) {
  // Line by line: a bad line (invalid UTF-8, malformed JSON, wrong field types, an unknown
  // kind, a line over the limit) gets an "error" result and the rest go on.
  InputFile file(o.file);
  LineReader reader(file);
  LineReader::Line line;
  int claims = 0;
  bool refuted = false, undecided = false, malformed = false;
  while (reader.next(line)) {
    if (!line.too_long && line.text.find_first_not_of(" \t") == std::string::npos) continue;
    ++claims;
    nlohmann::ordered_json r =
        line.too_long ? claim_line_error(line.number, o.file,
                                         "the line is " + std::to_string(line.length) + " bytes long; a claim may be at most " +
                                             std::to_string(kMaxInputLineBytes >> 20) + " MiB")
                      : check_claim_line(line.text, line.number, o.file);
    if (o.no_timings) r.erase("seconds");
    std::string verdict = r.value("verdict", "");
    if (verdict == "error") malformed = true;
    else if (verdict == "refuted") refuted = true;
    else if (verdict == "undecided") undecided = true;
    std::cout << json_text(r) << "\n";
  }
  std::cout.flush();
  if (claims == 0)
    throw InputError({o.file, 0, 0}, "no claims (the file is empty or has only blank lines); expected one JSON object per line");
  if (malformed) return kExitInputError;
  if (refuted) return kExitRefuted;
  if (undecided) return kExitUndecided;
  return kExitOk;
}

const CommandRegistrar registrar(
    "claims", "batch-check a JSONL claim bank (one JSON result per line)",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<ClaimsOptions>();
      sub.add_option("file", o->file, "claims, one JSON object per line")->required();
      sub.add_flag("--no-timings", o->no_timings, "omit the measured 'seconds' (byte-identical output)");
      return [o] { return run(*o); };
    });

}  // namespace
}  // namespace dc::cli
