// derivcheck check FILE|DIR... — checks every step of derivation files (docs/cli.md).
#include <algorithm>
#include <filesystem>
#include <iostream>

#include "apps/budget_flags.hpp"
#include "apps/commands.hpp"
#include "derivations/syntax/io.hpp"
#include "derivations/report/report.hpp"

namespace dc::cli {
namespace {

struct CheckOptions {
  std::vector<std::string> inputs;
  bool json = false, strict = false, quiet = false, timings = false;
  BudgetFlags budget;
};

int run(const CheckOptions& o) {
  // Every step in a worker process under the budget, on --jobs workers; the report is the same
  // for any number of jobs.
  // Each file is read once, in a child process that carries on with the command (read_once.hpp).
  exec::RunOptions run = o.budget.resolve();
  run.read_once = true;
  std::vector<FileReport> reports = exec::check_files(dc::derivation_files(o.inputs), run);
  ReportOptions ro;
  ro.timings = o.timings;
  ro.quiet = o.quiet;
  ro.strict = o.strict;
  if (o.json) std::cout << json_text(to_json(reports, ro), 2) << "\n";
  else std::cout << format_text(reports, ro);
  std::cout.flush();
  return totals(reports).exit_code(o.strict);
}

const CommandRegistrar registrar(
    "check", "check every step of derivation files (a directory means its *.dc files)",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<CheckOptions>();
      sub.add_option("inputs", o->inputs, "derivation files or directories")->required();
      sub.add_flag("--json", o->json, "machine-readable report (stable key order)");
      sub.add_flag("--strict", o->strict, "reported errata count as failures (exit code 1)");
      sub.add_flag("--quiet", o->quiet, "print only steps that do not hold, errors and the summary");
      sub.add_flag("--timings", o->timings, "print the time of each step (not deterministic)");
      o->budget.add_to(sub, true);
      return [o] { return run(*o); };
    });

}  // namespace
}  // namespace dc::cli
