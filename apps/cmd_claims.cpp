// derivcheck claims FILE.jsonl — batch-check a claim bank, one JSON result per line (docs/cli.md).
#include <iostream>
#include <sstream>

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
  std::string text = read_file(o.file);
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  bool refuted = false, undecided = false, malformed = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    nlohmann::ordered_json r = check_claim_line(line, line_no, o.file);
    if (o.no_timings) r.erase("seconds");
    std::string verdict = r.value("verdict", "");
    if (verdict == "error") malformed = true;
    else if (verdict == "refuted") refuted = true;
    else if (verdict == "undecided") undecided = true;
    std::cout << r.dump() << "\n";
  }
  std::cout.flush();
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
