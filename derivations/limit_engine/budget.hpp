// The limit engine's outcomes other than a value, and its budgets.
//
// Every computation in derivations/limits/ ends in one of: a value (LimitValue), or one of
// the exceptions below, each carrying the reason shown to the user. Nothing is guessed: a
// question the engine cannot settle (the sign of a parameter expression, whether a series
// coefficient vanishes) throws Undecided with the question in the reason.
#pragma once
#include <ctime>
#include <stdexcept>
#include <string>

#include <ginac/ginac.h>

namespace dc::limits {

// CPU time of this process in seconds. The engine's time caps use CPU time, not the wall
// clock, so a verdict does not depend on how busy the machine is.
inline double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// A limit at +infinity as the engine finds it: a finite value (may contain parameters) or an
// infinity with its sign.
struct LimitValue {
  enum class Kind { Finite, PlusInfinity, MinusInfinity } kind = Kind::Finite;
  GiNaC::ex value;   // Finite only
  bool finite() const { return kind == Kind::Finite; }
  static LimitValue of(const GiNaC::ex& v) { return {Kind::Finite, v}; }
  static LimitValue infinity(int sign) { return {sign > 0 ? Kind::PlusInfinity : Kind::MinusInfinity, 0}; }
};

// The engine cannot decide (with the reason).
struct Undecided : std::runtime_error {
  explicit Undecided(const std::string& why) : std::runtime_error(why) {}
};

// A resource budget ran out: the reason starts with "budget: ".
struct BudgetExceeded : Undecided {
  explicit BudgetExceeded(const std::string& what) : Undecided("budget: " + what) {}
};

// sin or cos of an argument that tends to +-infinity was met: the function oscillates. The
// caller may still decide the limit (a bounded factor times something that tends to 0) or
// show that it does not exist.
struct Oscillates : std::runtime_error {
  explicit Oscillates(const GiNaC::ex& where)
      : std::runtime_error("oscillating subexpression"), what_oscillates(where) {}
  GiNaC::ex what_oscillates;
};

// Certified: the expression has no real value for all x close enough to the point (a log or
// a fractional power of a quantity whose leading term is negative there).
struct NotRealNear : std::runtime_error {
  explicit NotRealNear(const std::string& why) : std::runtime_error(why) {}
};

// Internal: the series was computed to too low an order to show its leading term; the caller
// raises the order.
struct NeedMoreTerms : std::exception {
  const char* what() const noexcept override { return "more series terms needed"; }
};

// Budgets of one limit computation. The counters are deterministic (steps, depth, sizes);
// the CPU-time cap only stops a computation that the counters did not foresee.
struct Budget {
  int max_depth = 40;                 // nested limit computations (limit of a coefficient, ...)
  long max_steps = 60000;             // series operations, limit and sign calls together
  std::size_t max_coeff_nodes = 3000; // tree size of one series coefficient (after normal)
  int max_relative_order = 32;        // the most orders of w kept beyond a series' first term
  int max_terms_per_series = 60;      // terms kept in one series
  double max_seconds = 1.5;           // CPU time (below the CLI's 2 s default task budget)

  // counters
  long steps = 0;
  int depth = 0;
  double start = cpu_seconds();

  void tick(const char* where) {
    if (++steps > max_steps) throw BudgetExceeded(std::string("more than ") + std::to_string(max_steps) +
                                                  " steps (in " + where + ")");
    if ((steps & 63) == 0) {
      double s = cpu_seconds() - start;
      if (s > max_seconds)
        throw BudgetExceeded("more than " + std::to_string(static_cast<int>(max_seconds)) + " s (in " + where + ")");
    }
  }
};

// Nesting guard: counts one level of recursion for as long as it lives.
class DepthGuard {
 public:
  DepthGuard(Budget& b, const char* where) : b_(b) {
    if (++b_.depth > b_.max_depth) {
      --b_.depth;
      throw BudgetExceeded(std::string("recursion deeper than ") + std::to_string(b_.max_depth) + " (in " + where + ")");
    }
  }
  ~DepthGuard() { --b_.depth; }
  DepthGuard(const DepthGuard&) = delete;
  DepthGuard& operator=(const DepthGuard&) = delete;

 private:
  Budget& b_;
};

// Positive symbols for the engine's own variables (t, w, u), created once per process and
// reused: GiNaC orders terms by symbol serial numbers, so creating fresh symbols on every call
// would shift the order of every later expression of the process.
GiNaC::ex pooled_symbol(const std::string& stem, std::size_t index);

// Tree size of an expression, counted up to `cap` (returns cap + 1 when larger).
std::size_t tree_size(const GiNaC::ex& e, std::size_t cap);

}  // namespace dc::limits
