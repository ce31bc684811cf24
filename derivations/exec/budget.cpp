#include "derivations/exec/budget.hpp"

#include <csignal>
#include <cstring>

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dc::exec {

int available_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  long n = sysconf(_SC_NPROCESSORS_ONLN);
  return n > 0 ? static_cast<int>(n) : 1;
}

Budget default_budget(int jobs) {
  Budget b;
  const std::uint64_t two_gib = std::uint64_t{2} << 30;
  long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  std::uint64_t share = two_gib;
  if (pages > 0 && page > 0)
    share = static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page) / static_cast<std::uint64_t>(std::max(1, jobs) + 1);
  // Round down to 256 MiB so the printed budget is a plain number.
  const std::uint64_t step = std::uint64_t{256} << 20;
  b.memory_bytes = std::max(step, std::min(two_gib, share) / step * step);
  return b;
}

namespace {

// Splits "1.5GiB" into 1.5 and "gib" (lower case); throws when there is no number.
std::pair<double, std::string> number_and_unit(const std::string& text, const char* what) {
  std::size_t i = 0;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  std::size_t start = i;
  while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.')) ++i;
  if (i == start) throw std::invalid_argument(std::string("expected ") + what + ", got '" + text + "'");
  double v = 0;
  try {
    std::size_t used = 0;
    v = std::stod(text.substr(start, i - start), &used);
    if (used != i - start) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw std::invalid_argument(std::string("expected ") + what + ", got '" + text + "'");
  }
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  std::string unit;
  for (; i < text.size(); ++i) unit += static_cast<char>(std::tolower(static_cast<unsigned char>(text[i])));
  while (!unit.empty() && std::isspace(static_cast<unsigned char>(unit.back()))) unit.pop_back();
  return {v, unit};
}

}  // namespace

double parse_seconds(const std::string& text) {
  const char* what = "a duration such as 2, 2s, 500ms or 1min";
  auto [v, unit] = number_and_unit(text, what);
  double s;
  if (unit.empty() || unit == "s") s = v;
  else if (unit == "ms") s = v / 1000;
  else if (unit == "min" || unit == "m") s = v * 60;
  else throw std::invalid_argument(std::string("expected ") + what + ", got '" + text + "'");
  if (!(s > 0) || !std::isfinite(s) || s > 1e6)
    throw std::invalid_argument("a time budget must be positive and at most 10^6 s, got '" + text + "'");
  return s;
}

std::uint64_t parse_bytes(const std::string& text) {
  const char* what = "a size such as 2G, 2GiB, 512M or a number of bytes";
  auto [v, unit] = number_and_unit(text, what);
  double scale;
  if (unit.empty() || unit == "b") scale = 1;
  else if (unit == "k" || unit == "kb" || unit == "kib") scale = 1024.0;
  else if (unit == "m" || unit == "mb" || unit == "mib") scale = 1024.0 * 1024;
  else if (unit == "g" || unit == "gb" || unit == "gib") scale = 1024.0 * 1024 * 1024;
  else if (unit == "t" || unit == "tb" || unit == "tib") scale = 1024.0 * 1024 * 1024 * 1024;
  else throw std::invalid_argument(std::string("expected ") + what + ", got '" + text + "'");
  double b = v * scale;
  if (!(b >= 64.0 * 1024 * 1024) || b > 1e18)
    throw std::invalid_argument("a memory budget must be at least 64M (the program itself needs that), got '" + text + "'");
  return static_cast<std::uint64_t>(b);
}

std::string seconds_text(double s) {
  std::ostringstream o;
  o << s << " s";
  return o.str();
}

std::string bytes_text(std::uint64_t b) {
  std::ostringstream o;
  const double gib = 1024.0 * 1024 * 1024, mib = 1024.0 * 1024;
  if (b >= (std::uint64_t{1} << 30)) o << static_cast<double>(b) / gib << " GiB";
  else o << static_cast<double>(b) / mib << " MiB";
  return o.str();
}

std::string time_budget_reason(const Budget& b) { return "time budget " + seconds_text(b.cpu_seconds) + " exceeded"; }
std::string memory_budget_reason(const Budget& b) { return "memory budget " + bytes_text(b.memory_bytes) + " exceeded"; }
std::string wall_budget_reason(const Budget& b) {
  return "no answer within the wall-clock backstop of " + seconds_text(b.wall_seconds());
}

std::string signal_name(int sig) {
  switch (sig) {
    case SIGSEGV: return "SIGSEGV";
    case SIGBUS: return "SIGBUS";
    case SIGILL: return "SIGILL";
    case SIGFPE: return "SIGFPE";
    case SIGABRT: return "SIGABRT";
    case SIGKILL: return "SIGKILL";
    default: return "signal " + std::to_string(sig);
  }
}

bool is_memory_message(const char* what) {
  return std::strstr(what, "Out of virtual memory") != nullptr || std::strstr(what, "bad_alloc") != nullptr ||
         std::strstr(what, "Cannot allocate memory") != nullptr;
}

}  // namespace dc::exec
