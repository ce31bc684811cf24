// derivcheck merge RESULTS.jsonl... — joins the results of `claims --shard K/N` runs into line
// order (docs/cli.md, "Beyond one machine").
#include <iostream>

#include "apps/commands.hpp"
#include "derivations/exec/batch.hpp"

namespace dc::cli {
namespace {

struct MergeOptions {
  std::vector<std::string> files;
};

int run(const MergeOptions& o) { return exec::merge_claim_results(o.files, std::cout).exit_code(); }

const CommandRegistrar registrar(
    "merge", "merge the results of sharded `claims --shard K/N` runs into one, in line order",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<MergeOptions>();
      sub.add_option("files", o->files, "the shards' result files (JSONL, as `claims` writes them)")->required();
      return [o] { return run(*o); };
    });

}  // namespace
}  // namespace dc::cli
