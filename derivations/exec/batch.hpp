// The batch commands on worker processes: `check` (every step of every file) and `claims`
// (every line of a claim bank), each task under its budget, on `jobs` workers, results in
// input order — byte-identical output for any number of jobs (docs/cli.md, "Budgets and jobs").
#pragma once
#include <ostream>
#include <string>
#include <vector>

#include "derivations/report/report.hpp"
#include "derivations/exec/budget.hpp"

namespace dc::exec {

struct RunOptions {
  int jobs = 1;
  Budget budget;
  bool progress = false;   // a progress line on stderr (the caller checks it is a terminal)
  // check_files reads each file once, in a child process that then carries on with the command
  // while this process only supervises it (read_once.hpp; the CLI). Without it, each file is
  // read in a worker under the budget and again here, and check_files returns in this process
  // (library callers, tests).
  bool read_once = false;
  ProveOptions prove;
};

// Reads every file (each read under the budget) and checks every step, each in a worker under
// the budget. A step over its budget gets the verdict undecided with the reason; a file whose
// reading exceeds it is an input error naming the budget.
std::vector<FileReport> check_files(const std::vector<std::string>& files, const RunOptions& opt);

// `claims --shard K/N`: the lines whose number n has (n - 1) mod N == K - 1.
struct Shard {
  int index = 1, count = 1;
  bool takes(int line_no) const { return (line_no - 1) % count == index - 1; }
};
// "K/N" with 1 <= K <= N; std::invalid_argument otherwise.
Shard parse_shard(const std::string& text);

struct ClaimsTally {
  long claims = 0;
  bool refuted = false, undecided = false, malformed = false;
  void count(const std::string& verdict);
  int exit_code() const;   // 2 malformed line, 1 refuted, 3 undecided, else 0
};

// Streams the claim bank: one JSON result per non-blank line of the shard, written to `out` as
// soon as every earlier line's result is known. Bounded memory whatever the bank's length.
ClaimsTally check_claims(const std::string& file, const Shard& shard, bool timings, const RunOptions& opt,
                         std::ostream& out);

// `merge`: the results of the shards of one bank (each file sorted by line, as `claims`
// writes them) merged into line order: byte-identical to the unsharded run's output.
ClaimsTally merge_claim_results(const std::vector<std::string>& files, std::ostream& out);

}  // namespace dc::exec
