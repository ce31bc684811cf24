// read_files_once (read_once.hpp): a reading child that returns to the caller, and a parent that
// only supervises it.
#include "derivations/exec/read_once.hpp"

#include "derivations/document/document.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <new>

#include "derivations/exec/budget.hpp"
#include "derivations/symbolic/verdict.hpp"

namespace dc::exec {
namespace {

// Messages from the reading child, one byte each ('R' is followed by the file's index, 4 bytes):
// R<i> reading file i; T the time budget ran out; M an allocation failed; D every file read.
int g_report_fd = -1;

void on_read_timer(int) {
  const char t = 'T';
  ssize_t ignored = ::write(g_report_fd, &t, 1);
  (void)ignored;
  _exit(0);
}

void send(int fd, const char* data, std::size_t n) {
  while (n > 0) {
    ssize_t w = ::write(fd, data, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) _exit(0);   // the supervisor is gone
    data += w;
    n -= static_cast<std::size_t>(w);
  }
}

// The child: reads every file not in `failed`, each under the budget, and returns.
std::vector<ReadFile> read_in_child(const std::vector<std::string>& files, const Budget& budget,
                                    const std::map<std::size_t, InputError>& failed, int fd) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  g_report_fd = fd;
  struct sigaction sa {}, old_prof {};
  sigemptyset(&sa.sa_mask);
  sa.sa_handler = on_read_timer;
  sigaction(SIGPROF, &sa, &old_prof);
  rlimit old_as{};
  const bool limit_memory = budget.memory_bytes > 0 && getrlimit(RLIMIT_AS, &old_as) == 0;
#ifdef DERIVCHECK_SANITIZER
  const bool apply_memory_limit = false;   // ASan's shadow memory (see pool.cpp)
#else
  const bool apply_memory_limit = limit_memory;
#endif
  if (apply_memory_limit) {
    rlimit as = old_as;
    rlim_t want = static_cast<rlim_t>(budget.memory_bytes);
    if (as.rlim_max != RLIM_INFINITY && want > as.rlim_max) want = as.rlim_max;
    if (as.rlim_cur == RLIM_INFINITY || want < as.rlim_cur) as.rlim_cur = want;
    setrlimit(RLIMIT_AS, &as);
  }
  itimerval arm{}, disarm{};
  arm.it_value.tv_sec = static_cast<time_t>(budget.cpu_seconds);
  arm.it_value.tv_usec =
      static_cast<suseconds_t>((budget.cpu_seconds - static_cast<double>(arm.it_value.tv_sec)) * 1e6);
  if (arm.it_value.tv_sec == 0 && arm.it_value.tv_usec == 0) arm.it_value.tv_usec = 1000;

  std::vector<ReadFile> out(files.size());
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (auto it = failed.find(i); it != failed.end()) {
      out[i].error = it->second;
      continue;
    }
    char msg[5] = {'R'};
    const std::uint32_t index = static_cast<std::uint32_t>(i);
    std::memcpy(msg + 1, &index, 4);
    send(fd, msg, 5);
    const auto t0 = std::chrono::steady_clock::now();
    setitimer(ITIMER_PROF, &arm, nullptr);
    try {
      out[i].derivation.emplace(load_any(files[i]));
    } catch (const InputError& e) {
      out[i].error = e;
    } catch (const std::bad_alloc&) {
      send(fd, "M", 1);
      _exit(0);
    } catch (const std::exception& e) {
      // Not an input error and not the budget: a library failure while reading. The state of
      // this process is not trusted after it; the supervisor records it and starts afresh.
      send(fd, is_memory_message(e.what()) ? "M" : "E", 1);
      _exit(0);
    }
    setitimer(ITIMER_PROF, &disarm, nullptr);
    out[i].seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  if (apply_memory_limit) setrlimit(RLIMIT_AS, &old_as);
  sigaction(SIGPROF, &old_prof, nullptr);
  send(fd, "D", 1);
  ::close(fd);
  g_report_fd = -1;
  return out;
}

// The parent: waits for the child's verdict on each file; exits with the child's status.
[[noreturn]] void exit_like(int status) {
  if (WIFEXITED(status)) _exit(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) {
    std::signal(WTERMSIG(status), SIG_DFL);
    raise(WTERMSIG(status));
  }
  _exit(kExitInternal);
}

}  // namespace

std::vector<ReadFile> read_files_once(const std::vector<std::string>& files, const Budget& budget) {
  std::map<std::size_t, InputError> failed;
  for (;;) {
    int fds[2];
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("cannot create a pipe for the reading process");
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("cannot fork the reading process");
    if (pid == 0) {
      ::close(fds[0]);
      return read_in_child(files, budget, failed, fds[1]);
    }
    ::close(fds[1]);
    long current = -1;
    char why = 0;        // 'T', 'M', 'E' from the child, 'W' the wall-clock backstop
    bool done = false;
    std::string pending;
    auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(budget.wall_seconds());
    while (!done && !why) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      pollfd p{fds[0], POLLIN, 0};
      const int r = ::poll(&p, 1, static_cast<int>(std::max<long long>(0, left.count())));
      if (r < 0 && errno == EINTR) continue;
      if (r == 0) {   // no message within the backstop: a reading blocked on something
        ::kill(pid, SIGKILL);
        why = 'W';
        break;
      }
      char buf[256];
      const ssize_t n = ::read(fds[0], buf, sizeof buf);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;   // the child ended
      pending.append(buf, static_cast<std::size_t>(n));
      std::size_t k = 0;
      while (k < pending.size()) {
        const char c = pending[k];
        if (c == 'R') {
          if (pending.size() - k < 5) break;
          std::uint32_t index = 0;
          std::memcpy(&index, pending.data() + k + 1, 4);
          current = index;
          deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(budget.wall_seconds());
          k += 5;
        } else {
          if (c == 'D') done = true;
          else why = c;
          ++k;
        }
      }
      pending.erase(0, k);
    }
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (done) exit_like(status);   // the child went on with the command and has finished it
    if (current < 0) exit_like(status);   // it ended before reading anything: nothing to retry
    std::string reason;
    switch (why) {
      case 'T': reason = time_budget_reason(budget); break;
      case 'M': reason = memory_budget_reason(budget); break;
      case 'W': reason = wall_budget_reason(budget); break;
      case 'E': reason = "a symbolic computation failed"; break;
      default:
        reason = WIFSIGNALED(status) ? "the reading ended with " + signal_name(WTERMSIG(status))
                                     : "the reading process ended early";
    }
    const std::string& path = files[static_cast<std::size_t>(current)];
    failed.emplace(static_cast<std::size_t>(current),
                   InputError({path, 0, 0}, "reading this file did not finish: " + reason + "; it was not checked"));
  }
}

}  // namespace dc::exec
