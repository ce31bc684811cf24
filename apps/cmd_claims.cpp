// derivcheck claims FILE.jsonl — batch-check a claim bank, one JSON result per line (docs/cli.md).
#include <iostream>

#include "apps/budget_flags.hpp"
#include "apps/commands.hpp"

namespace dc::cli {
namespace {

struct ClaimsOptions {
  std::string file;
  std::string shard = "1/1";
  bool no_timings = false;
  BudgetFlags budget;
};

int run(const ClaimsOptions& o) {
  // Line by line on worker processes: a bad line (invalid UTF-8, malformed JSON, wrong field
  // types, an unknown kind, a line over the limit) gets an "error" result, a line over its
  // budget an "undecided" one, and the rest go on; results come out in line order.
  exec::RunOptions run = o.budget.resolve();
  exec::Shard shard = exec::parse_shard(o.shard);
  return exec::check_claims(o.file, shard, !o.no_timings, run, std::cout).exit_code();
}

const CommandRegistrar registrar(
    "claims", "batch-check a JSONL claim bank (one JSON result per line)",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<ClaimsOptions>();
      sub.add_option("file", o->file, "claims, one JSON object per line")->required();
      sub.add_flag("--no-timings", o->no_timings, "omit the measured 'seconds' (byte-identical output)");
      sub.add_option("--shard", o->shard,
                     "K/N: check only the lines n with (n-1) mod N = K-1; `derivcheck merge` joins the shards' results");
      o->budget.add_to(sub, true);
      return [o] { return run(*o); };
    });

}  // namespace
}  // namespace dc::cli
