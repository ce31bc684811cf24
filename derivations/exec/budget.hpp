// Per-task budgets: how much CPU time and memory one step or claim may use before it is given
// up as *undecided* (docs/cli.md, "Budgets"). The numbers are enforced by exec::Pool, which
// runs every task in a forked worker process.
#pragma once
#include <cstdint>
#include <string>

namespace dc::exec {

struct Budget {
  double cpu_seconds = 2.0;          // CPU time of one task (user + system) in its worker
  std::uint64_t memory_bytes = 0;    // address-space limit of a worker (RLIMIT_AS); 0: none
  // Wall-clock backstop: a task that has not answered after this long is killed even if its
  // CPU clock has not run out (a worker blocked on something that is not CPU).
  double wall_seconds() const { return 4 * cpu_seconds + 10; }
};

// Defaults: 2 s of CPU; memory min(2 GiB, physical memory / (jobs + 1)) — so that `jobs`
// workers at their limit still leave the machine usable.
Budget default_budget(int jobs);

// The number of cores this process may run on (sched_getaffinity), at least 1.
int available_cores();

// "2", "2s", "1.5s", "500ms", "1min" -> seconds. Throws std::invalid_argument naming the text.
double parse_seconds(const std::string& text);
// "2G", "2GB", "2GiB", "512M", "100000K", "3145728000" (bytes) -> bytes (binary units).
std::uint64_t parse_bytes(const std::string& text);

// "2 s", "0.5 s"; "2 GiB", "512 MiB" — as the reasons print them.
std::string seconds_text(double s);
std::string bytes_text(std::uint64_t b);

// The reasons a budget stop prints, the same for a task of the pool and for reading a file:
// "time budget 2 s exceeded", "memory budget 2 GiB exceeded", "no answer within the wall-clock
// backstop of 18 s".
std::string time_budget_reason(const Budget& b);
std::string memory_budget_reason(const Budget& b);
std::string wall_budget_reason(const Budget& b);
// "SIGSEGV", ..., else "signal N".
std::string signal_name(int sig);
// Does an exception's text say that an allocation failed (CLN, GMP, std::bad_alloc)?
bool is_memory_message(const char* what);

}  // namespace dc::exec
