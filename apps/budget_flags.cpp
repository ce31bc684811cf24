#include "apps/budget_flags.hpp"

#include "derivations/exec/progress.hpp"

namespace dc::cli {

void BudgetFlags::add_to(CLI::App& sub, bool parallel) {
  if (parallel) {
    sub.add_option("--jobs,-j", jobs, "worker processes (default: every available core)");
    sub.add_flag("--no-progress", no_progress, "no progress line (it is shown only on a terminal anyway)");
  }
  sub.add_option("--step-timeout", step_timeout,
                 "CPU time one " + std::string(parallel ? "step or claim" : "computation") +
                     " may use before it is undecided (default 2s; e.g. 500ms, 10s)");
  sub.add_option("--memory", memory,
                 "memory (address space) of one worker (default min(2G, RAM/(jobs+1)); e.g. 512M, 4G)");
}

exec::RunOptions BudgetFlags::resolve() const {
  exec::RunOptions o;
  if (jobs < 0 || jobs > 1024) throw std::invalid_argument("--jobs must be between 1 and 1024 (0: every core)");
  o.jobs = jobs == 0 ? exec::available_cores() : jobs;
  o.budget = exec::default_budget(o.jobs);
  if (!step_timeout.empty()) o.budget.cpu_seconds = exec::parse_seconds(step_timeout);
  if (!memory.empty()) o.budget.memory_bytes = exec::parse_bytes(memory);
  o.progress = !no_progress && exec::stderr_is_terminal();
  return o;
}

}  // namespace dc::cli

#include <iostream>
#include <sstream>

#include "apps/commands.hpp"
#include "derivations/syntax/source.hpp"
#include "derivations/exec/pool.hpp"

namespace dc::cli {

int run_supervised(const exec::RunOptions& run, const std::function<int(std::ostream&)>& body,
                   const std::function<int(const std::string& reason)>& on_budget) {
  // The answer: one byte exit code, then stdout text, a NUL, stderr text.
  exec::Pool pool(1, run.budget, [&body](const std::string&) -> std::string {
    std::ostringstream out;
    std::string err;
    int code;
    try {
      code = body(out);
    } catch (const InputError& e) {
      code = kExitInputError;
      err = e.format();
    } catch (const std::invalid_argument& e) {
      code = kExitInputError;
      err = std::string("derivcheck: error: ") + e.what() + "\n";
    } catch (const std::domain_error& e) {
      code = kExitInputError;
      err = std::string("derivcheck: error: ") + e.what() + "\n";
    }
    return std::string(1, static_cast<char>(code)) + out.str() + std::string(1, '\0') + err;
  });
  exec::TaskOutcome o = pool.run_one("");
  if (!o.done()) return on_budget(o.reason);
  std::size_t nul = o.payload.find('\0', 1);
  std::cout << o.payload.substr(1, nul - 1);
  std::cout.flush();
  std::cerr << o.payload.substr(nul + 1);
  return static_cast<unsigned char>(o.payload[0]);
}

}  // namespace dc::cli
