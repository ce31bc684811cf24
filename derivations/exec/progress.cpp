#include "derivations/exec/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace dc::exec {

bool stderr_is_terminal() { return isatty(STDERR_FILENO) == 1; }

Progress::Progress(bool enabled, std::string unit)
    : enabled_(enabled), unit_(std::move(unit)), start_(std::chrono::steady_clock::now()), last_(start_) {}

Progress::~Progress() {
  if (shown_) std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
}

void Progress::update(long done, double fraction) {
  if (!enabled_) return;
  auto now = std::chrono::steady_clock::now();
  double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < 1.0 || std::chrono::duration<double>(now - last_).count() < 0.2) return;
  last_ = now;
  shown_ = true;
  char line[160];
  int n = std::snprintf(line, sizeof line, "\r\033[Kderivcheck: %ld %s, %.0f/s", done, unit_.c_str(), done / elapsed);
  if (fraction > 0 && fraction <= 1 && n > 0 && n < static_cast<int>(sizeof line))
    std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), ", %.0f%%, ETA %.0f s", 100 * fraction,
                  elapsed * (1 - fraction) / fraction);
  std::fputs(line, stderr);
  std::fflush(stderr);
}

}  // namespace dc::exec
