// The flags every command that computes shares: --jobs, --step-timeout, --memory
// (docs/cli.md, "Budgets and jobs").
#pragma once
#include <string>

#include <CLI/CLI.hpp>

#include "derivations/exec/batch.hpp"

namespace dc::cli {

struct BudgetFlags {
  int jobs = 0;               // 0: every available core
  std::string step_timeout;   // "" : the default
  std::string memory;
  bool no_progress = false;
  // Adds the flags; `parallel`: the command runs many tasks (adds --jobs and --no-progress).
  void add_to(CLI::App& sub, bool parallel);
  // The options in force (std::invalid_argument for a malformed value).
  exec::RunOptions resolve() const;
};

}  // namespace dc::cli

namespace dc::cli {

// Runs `body` (which prints to the stream it is given and returns the exit code) in one
// supervised worker under the budget, then prints what it printed. Input errors thrown by the
// body print as usual (exit 2). When the budget runs out, `on_budget(reason)` prints instead
// and gives the exit code.
int run_supervised(const exec::RunOptions& run, const std::function<int(std::ostream&)>& body,
                   const std::function<int(const std::string& reason)>& on_budget);

}  // namespace dc::cli
