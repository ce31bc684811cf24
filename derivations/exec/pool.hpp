// Supervised worker processes. GiNaC and CLN can be neither interrupted from inside nor run on
// several threads, so every task runs in a worker process forked from this one (before any
// thread exists) and the parent supervises it:
//   - CPU time: the worker arms a CPU-time timer (ITIMER_PROF) for each task; when it fires,
//     the worker reports "time budget exceeded" and exits;
//   - memory: the worker's address space is limited (RLIMIT_AS); an allocation that fails
//     reports "memory budget exceeded" and the worker exits;
//   - wall clock: a task that has not answered after Budget::wall_seconds() is killed;
//   - a worker that dies (stack overflow, a fault) gives that task an abnormal-end outcome.
// A worker that exits is replaced by a fresh fork of the parent, whose state never changes
// while tasks run, so a task's result does not depend on which worker computed it. Results are
// delivered in task order whatever order the workers finish in. A worker is also replaced
// after 500 tasks, so nothing it caches accumulates over a long bank.
#pragma once
#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "derivations/exec/budget.hpp"

namespace dc::exec {

struct TaskOutcome {
  enum class Status { Done, TimeBudget, MemoryBudget, WallBudget, Crashed };
  Status status = Status::Done;
  std::string payload;   // Done: what the handler returned
  std::string reason;    // otherwise: "time budget 2 s exceeded", ...
  double seconds = 0;    // wall time from dispatch to answer (not deterministic)
  bool done() const { return status == Status::Done; }
};

// The work: turns a task (bytes) into a result (bytes). Runs in a worker process; exceptions it
// lets escape become a Crashed outcome (std::bad_alloc: MemoryBudget).
using Handler = std::function<std::string(const std::string& task)>;

class Pool {
 public:
  static constexpr std::size_t kWindowBytes = std::size_t{64} << 20;

  Pool(int jobs, Budget budget, Handler handler);
  ~Pool();
  Pool(const Pool&) = delete;
  Pool& operator=(const Pool&) = delete;

  // Runs tasks until `next` returns false. `done` is called once per task, in task order.
  // At most `window` tasks (0: 2048 per worker) holding at most kWindowBytes of task text are
  // dispatched but not yet delivered, so memory stays bounded however many tasks stream through.
  // The window must be wide: results are delivered in order, so while one slow task runs the
  // other workers go on only as far as the window reaches (64 per worker cost a third of the
  // throughput at 2 jobs on a generated bank; docs/performance.md, "Claim banks").
  void run(const std::function<bool(std::string& task)>& next, const std::function<void(TaskOutcome&&)>& done,
           std::size_t window = 0);

  // One task, supervised (the CLI's `equal` and `eval`).
  TaskOutcome run_one(const std::string& task);

  int jobs() const;
  const Budget& budget() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dc::exec
