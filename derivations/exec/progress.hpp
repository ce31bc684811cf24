// A progress line on stderr for runs longer than a second ("412/1000 steps, 95/s, ETA 6 s"),
// redrawn at most five times a second and erased at the end. Disabled (silent) unless the
// caller enables it — the commands enable it only when stderr is a terminal.
#pragma once
#include <chrono>
#include <string>

namespace dc::exec {

class Progress {
 public:
  Progress(bool enabled, std::string unit);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  // `done` items so far; `fraction` of the whole work done (0..1), or negative when unknown.
  void update(long done, double fraction);

 private:
  bool enabled_;
  bool shown_ = false;
  std::string unit_;
  std::chrono::steady_clock::time_point start_, last_;
};

// Is stderr a terminal? (progress is shown only then)
bool stderr_is_terminal();

}  // namespace dc::exec
