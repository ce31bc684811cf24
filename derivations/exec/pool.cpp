#include "derivations/exec/pool.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cln/malloc.h>
#include <flint/flint.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <iostream>
#include <map>
#include <new>
#include <stdexcept>
#include <vector>

namespace dc::exec {
namespace {

using Clock = std::chrono::steady_clock;

// Frames from worker to parent: one status byte, an 8-byte length, the payload.
constexpr char kDone = 'D', kTime = 'T', kMemory = 'M', kSignal = 'S', kException = 'E';

bool write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    ssize_t w = ::write(fd, p, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

bool read_all(int fd, char* p, std::size_t n) {
  while (n > 0) {
    ssize_t r = ::read(fd, p, n);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    p += r;
    n -= static_cast<std::size_t>(r);
  }
  return true;
}

bool write_frame(int fd, char status, const char* data, std::uint64_t n) {
  char head[9];
  head[0] = status;
  std::memcpy(head + 1, &n, 8);
  return write_all(fd, head, 9) && write_all(fd, data, n);
}

// ---- the worker side ----------------------------------------------------------------------

int g_result_fd = -1;
// Set when an allocation failed during the current task, even if the code that asked for the
// memory caught the failure and went on (a rule reporting "the computation failed"): the task
// then ends as "memory budget exceeded", whatever it returned.
volatile sig_atomic_t g_alloc_failed = 0;
void* (*g_cln_malloc)(size_t) = nullptr;

void* cln_malloc(size_t n) {
  if (void* p = std::malloc(n)) return p;
  g_alloc_failed = 1;
  return g_cln_malloc(n);   // CLN's own hook reports the failure its way
}
void* flint_alloc(size_t n) {
  void* p = std::malloc(n);
  if (!p && n) g_alloc_failed = 1;
  return p;
}
void* flint_calloc(size_t n, size_t size) {
  void* p = std::calloc(n, size);
  if (!p && n && size) g_alloc_failed = 1;
  return p;
}
void* flint_realloc(void* q, size_t n) {
  void* p = std::realloc(q, n);
  if (!p && n) g_alloc_failed = 1;
  return p;
}

// Async-signal-safe: the CPU timer ran out.
void on_cpu_timer(int) {
  write_frame(g_result_fd, kTime, "", 0);
  _exit(0);
}

// Async-signal-safe: a fault (stack overflow, abort from an allocator, ...).
void on_fault(int sig) {
  if (g_alloc_failed) {   // FLINT and GMP abort when an allocation fails
    write_frame(g_result_fd, kMemory, "", 0);
    _exit(0);
  }
  char text[4] = {0, 0, 0, 0};
  int n = 0;
  if (sig >= 10) text[n++] = static_cast<char>('0' + sig / 10);
  text[n++] = static_cast<char>('0' + sig % 10);
  write_frame(g_result_fd, kSignal, text, static_cast<std::uint64_t>(n));
  _exit(70);
}

[[noreturn]] void worker_main(int task_fd, int result_fd, pid_t parent, const Budget& budget, const Handler& handler) {
  g_result_fd = result_fd;
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(0);
  // Output belongs to the parent: a handler never prints, and nothing buffered before the
  // fork may be flushed twice (the worker leaves with _exit).
  int devnull = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (devnull >= 0) ::dup2(devnull, STDOUT_FILENO);
  rlimit core{0, 0};
  setrlimit(RLIMIT_CORE, &core);
#ifndef DERIVCHECK_SANITIZER
  // Under AddressSanitizer the address space cannot be limited (ASan reserves terabytes of
  // shadow memory: every worker would fail its first mmap); the memory budget is not enforced
  // in the sanitizer build (tools/sanitize.sh), the time budget is.
  if (budget.memory_bytes > 0) {
    rlimit as{};
    if (getrlimit(RLIMIT_AS, &as) == 0) {
      rlim_t want = static_cast<rlim_t>(budget.memory_bytes);
      if (as.rlim_max != RLIM_INFINITY && want > as.rlim_max) want = as.rlim_max;
      if (as.rlim_cur == RLIM_INFINITY || want < as.rlim_cur) as.rlim_cur = want;
      setrlimit(RLIMIT_AS, &as);
    }
  }
#endif
  static char alt_stack[1 << 16];
  stack_t ss{};
  ss.ss_sp = alt_stack;
  ss.ss_size = sizeof alt_stack;
  sigaltstack(&ss, nullptr);
  struct sigaction sa {};
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_ONSTACK | SA_RESETHAND;
  sa.sa_handler = on_fault;
  for (int sig : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT}) sigaction(sig, &sa, nullptr);
  sa.sa_handler = on_cpu_timer;
  sa.sa_flags = SA_ONSTACK;
  sigaction(SIGPROF, &sa, nullptr);
  g_cln_malloc = cln::malloc_hook;
  cln::malloc_hook = cln_malloc;
  __flint_set_memory_functions(flint_alloc, flint_calloc, flint_realloc, std::free);
  std::set_new_handler([] {
    g_alloc_failed = 1;
    throw std::bad_alloc();
  });
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);

  const double cpu = budget.cpu_seconds;
  itimerval arm{}, disarm{};
  arm.it_value.tv_sec = static_cast<time_t>(cpu);
  arm.it_value.tv_usec = static_cast<suseconds_t>((cpu - static_cast<double>(arm.it_value.tv_sec)) * 1e6);
  if (arm.it_value.tv_sec == 0 && arm.it_value.tv_usec == 0) arm.it_value.tv_usec = 1000;
  for (;;) {
    std::uint64_t n = 0;
    if (!read_all(task_fd, reinterpret_cast<char*>(&n), 8)) _exit(0);
    std::string task(n, '\0');
    if (n > 0 && !read_all(task_fd, task.data(), n)) _exit(0);
    std::string result;
    char status = kDone;
    setitimer(ITIMER_PROF, &arm, nullptr);
    try {
      result = handler(task);
    } catch (const std::bad_alloc&) {
      status = kMemory;
    } catch (const std::exception& e) {
      status = is_memory_message(e.what()) ? kMemory : kException;
      if (status == kException) result = e.what();
    } catch (...) {
      status = kException;
      result = "unknown exception";
    }
    setitimer(ITIMER_PROF, &disarm, nullptr);
    if (g_alloc_failed) {
      status = kMemory;
      result.clear();
    }
    if (!write_frame(result_fd, status, result.data(), result.size())) _exit(0);
    // After a failed allocation or an escaped exception the worker's state is not trusted.
    if (status != kDone) _exit(0);
  }
}

}  // namespace

// ---- the parent side ----------------------------------------------------------------------

struct Pool::Impl {
  struct Worker {
    pid_t pid = -1;
    int task_fd = -1, result_fd = -1;
    bool busy = false;
    std::size_t task = 0;
    Clock::time_point start;
    std::string buf;
    int tasks_done = 0;
  };
  // A worker is replaced after this many tasks, so whatever GiNaC's caches keep between tasks
  // never accumulates towards the memory budget over a long bank.
  static constexpr int kRecycleAfter = 500;

  int jobs;
  Budget budget;
  Handler handler;
  std::vector<Worker> workers;
  pid_t self = getpid();

  Impl(int j, Budget b, Handler h) : jobs(j < 1 ? 1 : j), budget(b), handler(std::move(h)), workers(static_cast<std::size_t>(jobs)) {}

  ~Impl() {
    for (auto& w : workers) stop(w, true);
  }

  void stop(Worker& w, bool kill_it) {
    if (w.pid <= 0) return;
    ::close(w.task_fd);
    ::close(w.result_fd);
    if (kill_it) ::kill(w.pid, SIGKILL);
    int st = 0;
    while (::waitpid(w.pid, &st, 0) < 0 && errno == EINTR) {
    }
    w = Worker{};
  }

  // Reaps a worker that ended on its own and says how.
  std::string reap(Worker& w) {
    ::close(w.task_fd);
    ::close(w.result_fd);
    int st = 0;
    pid_t r;
    while ((r = ::waitpid(w.pid, &st, 0)) < 0 && errno == EINTR) {
    }
    std::string how = "the worker process ended";
    if (r == w.pid && WIFSIGNALED(st)) how += " by " + signal_name(WTERMSIG(st));
    else if (r == w.pid && WIFEXITED(st)) how += " with status " + std::to_string(WEXITSTATUS(st));
    w = Worker{};
    return how;
  }

  bool spawn(Worker& w) {
    int tp[2], rp[2];
    if (::pipe2(tp, O_CLOEXEC) != 0) return false;
    if (::pipe2(rp, O_CLOEXEC) != 0) {
      ::close(tp[0]);
      ::close(tp[1]);
      return false;
    }
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    pid_t pid = ::fork();
    if (pid < 0) {
      for (int fd : {tp[0], tp[1], rp[0], rp[1]}) ::close(fd);
      return false;
    }
    if (pid == 0) {
      ::close(tp[1]);
      ::close(rp[0]);
      for (auto& other : workers)
        if (other.pid > 0) {
          ::close(other.task_fd);
          ::close(other.result_fd);
        }
      worker_main(tp[0], rp[1], self, budget, handler);
    }
    ::close(tp[0]);
    ::close(rp[1]);
    w = Worker{};
    w.pid = pid;
    w.task_fd = tp[1];
    w.result_fd = rp[0];
    return true;
  }

  // Sends a task; SIGPIPE from a worker that just died is blocked and discarded.
  bool send(Worker& w, const std::string& task) {
    sigset_t pipe_set, old;
    sigemptyset(&pipe_set);
    sigaddset(&pipe_set, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_set, &old);
    std::uint64_t n = task.size();
    bool ok = write_all(w.task_fd, reinterpret_cast<const char*>(&n), 8) && write_all(w.task_fd, task.data(), n);
    if (!ok) {
      timespec zero{0, 0};
      while (sigtimedwait(&pipe_set, nullptr, &zero) > 0) {
      }
    }
    pthread_sigmask(SIG_SETMASK, &old, nullptr);
    return ok;
  }

  TaskOutcome budget_outcome(TaskOutcome::Status s, const std::string& extra = "") const {
    TaskOutcome o;
    o.status = s;
    switch (s) {
      case TaskOutcome::Status::TimeBudget: o.reason = time_budget_reason(budget); break;
      case TaskOutcome::Status::MemoryBudget: o.reason = memory_budget_reason(budget); break;
      case TaskOutcome::Status::WallBudget: o.reason = wall_budget_reason(budget); break;
      default: o.reason = extra; break;
    }
    return o;
  }

  void run(const std::function<bool(std::string&)>& next, const std::function<void(TaskOutcome&&)>& done, std::size_t window) {
    if (window == 0) window = 2048 * static_cast<std::size_t>(jobs);
    std::map<std::size_t, TaskOutcome> ready;
    std::size_t next_index = 0, next_emit = 0;
    std::deque<std::size_t> task_bytes;   // sizes of the tasks next_emit .. next_index - 1
    std::size_t window_bytes = 0;
    bool more = true;
    auto finish = [&](Worker& w, TaskOutcome o) {
      o.seconds = std::chrono::duration<double>(Clock::now() - w.start).count();
      ready.emplace(w.task, std::move(o));
      w.busy = false;
    };
    for (;;) {
      // Dispatch to idle workers while the window allows.
      for (auto& w : workers) {
        if (w.busy) continue;
        std::size_t index;
        std::string task;
        bool room = next_index == next_emit || (next_index - next_emit < window && window_bytes < Pool::kWindowBytes);
        if (more && room) {
          if (!next(task)) {
            more = false;
            continue;
          }
          index = next_index++;
          task_bytes.push_back(task.size());
          window_bytes += task.size();
        } else {
          continue;
        }
        bool ok = false;
        for (int attempt = 0; attempt < 2 && !ok; ++attempt) {
          if (w.pid <= 0 && !spawn(w)) break;
          ok = send(w, task);
          if (!ok) stop(w, true);
        }
        if (!ok) {
          ready.emplace(index, budget_outcome(TaskOutcome::Status::Crashed, "a worker process could not be started"));
          continue;
        }
        w.busy = true;
        w.task = index;
        w.start = Clock::now();
        w.buf.clear();
      }
      while (!ready.empty() && ready.begin()->first == next_emit) {
        done(std::move(ready.begin()->second));
        ready.erase(ready.begin());
        ++next_emit;
        window_bytes -= task_bytes.front();
        task_bytes.pop_front();
      }
      std::vector<pollfd> fds;
      std::vector<Worker*> polled;
      auto now = Clock::now();
      int timeout_ms = 1000;
      for (auto& w : workers) {
        if (!w.busy) continue;
        fds.push_back({w.result_fd, POLLIN, 0});
        polled.push_back(&w);
        double left = budget.wall_seconds() - std::chrono::duration<double>(now - w.start).count();
        timeout_ms = std::min(timeout_ms, std::max(0, static_cast<int>(left * 1000) + 1));
      }
      if (fds.empty()) {
        if (!more && ready.empty()) break;
        continue;
      }
      int pr = ::poll(fds.data(), fds.size(), timeout_ms);
      if (pr < 0 && errno != EINTR) throw std::runtime_error(std::string("poll failed: ") + std::strerror(errno));
      for (std::size_t i = 0; i < fds.size(); ++i) {
        Worker& w = *polled[i];
        if (pr > 0 && (fds[i].revents & (POLLIN | POLLHUP | POLLERR))) {
          char chunk[65536];
          ssize_t r = ::read(w.result_fd, chunk, sizeof chunk);
          if (r < 0 && errno == EINTR) continue;
          if (r > 0) {
            w.buf.append(chunk, static_cast<std::size_t>(r));
            if (w.buf.size() >= 9) {
              std::uint64_t n;
              std::memcpy(&n, w.buf.data() + 1, 8);
              if (w.buf.size() >= 9 + n) {
                char status = w.buf[0];
                std::string payload = w.buf.substr(9, n);
                TaskOutcome o;
                if (status == kDone) {
                  o.payload = std::move(payload);
                } else if (status == kTime) {
                  o = budget_outcome(TaskOutcome::Status::TimeBudget);
                } else if (status == kMemory) {
                  o = budget_outcome(TaskOutcome::Status::MemoryBudget);
                } else if (status == kSignal) {
                  int sig = std::atoi(payload.c_str());
                  o = sig == SIGABRT ? budget_outcome(TaskOutcome::Status::Crashed,
                                                      "the computation was aborted (SIGABRT; an allocation beyond the memory budget " +
                                                          bytes_text(budget.memory_bytes) + " ends this way)")
                      : sig == SIGSEGV ? budget_outcome(TaskOutcome::Status::Crashed,
                                                        "the computation ended with SIGSEGV (stack exhausted by deep recursion, or a fault)")
                                       : budget_outcome(TaskOutcome::Status::Crashed, "the computation ended with " + signal_name(sig));
                } else {
                  o = budget_outcome(TaskOutcome::Status::Crashed, "the computation failed: " + payload);
                }
                finish(w, std::move(o));
                if (status != kDone) reap(w);
                else if (++w.tasks_done >= kRecycleAfter) stop(w, true);
              }
            }
            continue;
          }
          // End of file without a complete answer: the worker died.
          std::size_t task = w.task;
          auto start = w.start;
          std::string how = reap(w);
          TaskOutcome o = budget_outcome(TaskOutcome::Status::Crashed, how + " without an answer");
          o.seconds = std::chrono::duration<double>(Clock::now() - start).count();
          ready.emplace(task, std::move(o));
        }
      }
      // Wall-clock overruns.
      now = Clock::now();
      for (Worker* wp : polled) {
        Worker& w = *wp;
        if (w.busy && std::chrono::duration<double>(now - w.start).count() > budget.wall_seconds()) {
          TaskOutcome o = budget_outcome(TaskOutcome::Status::WallBudget);
          finish(w, std::move(o));
          stop(w, true);
        }
      }
    }
  }
};

Pool::Pool(int jobs, Budget budget, Handler handler) : impl_(std::make_unique<Impl>(jobs, budget, std::move(handler))) {}
Pool::~Pool() = default;

void Pool::run(const std::function<bool(std::string&)>& next, const std::function<void(TaskOutcome&&)>& done,
               std::size_t window) {
  impl_->run(next, done, window);
}

TaskOutcome Pool::run_one(const std::string& task) {
  TaskOutcome out;
  bool given = false;
  impl_->run([&](std::string& t) {
    if (given) return false;
    t = task;
    given = true;
    return true;
  }, [&](TaskOutcome&& o) { out = std::move(o); }, 1);
  return out;
}

int Pool::jobs() const { return impl_->jobs; }
const Budget& Pool::budget() const { return impl_->budget; }

}  // namespace dc::exec
