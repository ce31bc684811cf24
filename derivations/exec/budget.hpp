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

}  // namespace dc::exec
