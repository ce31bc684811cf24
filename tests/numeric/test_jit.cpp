// The JIT (numeric/jit.hpp) against the tape and against CLN: per operation on wide random
// ranges, special values, lengths around the vector width, every instruction set the host has,
// whole handout formulas, threads, and the fallback to the tape.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <thread>

#include <unistd.h>

#include "numeric/evaluator.hpp"
#include "numeric/reference/exact.hpp"
#include "numeric/jit.hpp"
#include "numeric/reference/reference.hpp"
#include "numeric/charts/chart_data.hpp"
#include "handout.hpp"

using namespace dc::num;
using GiNaC::ex;
using GiNaC::symbol;

namespace {

bool same_bits(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// +-10^[lo, hi] log-uniform (sign random when `sign`)
double logu(std::mt19937_64& rng, double lo, double hi, bool sign = true) {
  const double x = std::pow(10.0, std::uniform_real_distribution<double>(lo, hi)(rng));
  return sign && (rng() & 1) ? -x : x;
}

struct OpCase {
  Op op;
  ex expr;
  double ulps;  // documented bound against the true value (0: bit for bit the tape)
  std::function<std::pair<double, double>(std::mt19937_64&)> point;
};

symbol x("x"), y("y");

std::vector<OpCase> op_cases() {
  auto u = [](double lo, double hi) {
    return [=](std::mt19937_64& r) { return std::pair{std::uniform_real_distribution<double>(lo, hi)(r), 0.0}; };
  };
  auto lg = [](double lo, double hi, bool sign) {
    return [=](std::mt19937_64& r) { return std::pair{logu(r, lo, hi, sign), 0.0}; };
  };
  auto mix = [](auto a, auto b) {
    return [=](std::mt19937_64& r) { return (r() & 1) ? a(r) : b(r); };
  };
  auto two = [](double lo, double hi, bool sign) {
    return [=](std::mt19937_64& r) { return std::pair{logu(r, lo, hi, sign), logu(r, lo, hi, sign)}; };
  };
  return {
      {Op::Add, x + y, 0, two(-300, 300, true)},
      {Op::Sub, x - y, 0, two(-300, 300, true)},
      {Op::Mul, x * y, 0, two(-200, 200, true)},
      {Op::Div, x / y, 0, two(-200, 200, true)},
      {Op::Neg, -x, 0, lg(-300, 300, true)},
      {Op::Sqrt, GiNaC::sqrt(x), 0, lg(-320, 308, false)},
      {Op::Abs, GiNaC::abs(x), 0, lg(-320, 308, true)},
      {Op::Exp, GiNaC::exp(x), 1.0, mix(u(-745, 709.7), lg(-300, 0, true))},
      {Op::Expm1, GiNaC::exp(x) - 1, 1.0, mix(u(-50, 709.7), lg(-300, 0, true))},
      {Op::Log, GiNaC::log(x), 1.0, lg(-320, 308, false)},
      {Op::Log1p, GiNaC::log(1 + x), 1.0, mix(u(-1, 1), lg(-300, 300, false))},
      {Op::Sin, GiNaC::sin(x), 1.0, mix(lg(-300, 6, true), lg(6, 15, true))},
      {Op::Cos, GiNaC::cos(x), 1.0, mix(lg(-300, 6, true), lg(6, 15, true))},
      {Op::Tan, GiNaC::tan(x), 1.0, mix(lg(-300, 6, true), lg(6, 15, true))},
      {Op::Asin, GiNaC::asin(x), 1.0, mix(u(-1, 1), lg(-300, 0, true))},
      {Op::Acos, GiNaC::acos(x), 1.0, mix(u(-1, 1), lg(-300, 0, true))},
      {Op::Atan, GiNaC::atan(x), 1.0, lg(-300, 300, true)},
      {Op::Pow, GiNaC::pow(x, y), 1.0,
       [](std::mt19937_64& r) { return std::pair{logu(r, -10, 10, false), std::uniform_real_distribution<double>(-30, 30)(r)}; }},
      {Op::Hypot, GiNaC::sqrt(GiNaC::pow(x, 2) + GiNaC::pow(y, 2)), 0.5001, two(-300, 300, true)},
  };
}

// the JIT for `p`, failing the test when this build should have one
std::shared_ptr<const JitKernel> jit_of(const Program& p, const std::string& isa = "") {
  std::string why;
  auto k = JitKernel::compile(p, &why, isa);
  INFO(why);
#if DERIVCHECK_TEST_EXPECT_JIT
  REQUIRE(k);
#endif
  return k;
}

std::vector<double> run(const JitKernel& k, const std::vector<std::vector<double>>& cols, std::size_t n) {
  std::vector<const double*> cp;
  for (const auto& c : cols) cp.push_back(c.data());
  std::vector<double> out(n + 9, 12345.0);  // guard after n: must stay untouched
  k(cp.data(), out.data(), n);
  for (std::size_t i = n; i < out.size(); ++i) REQUIRE(out[i] == 12345.0);
  out.resize(n);
  return out;
}

std::vector<double> tape(const Program& p, const std::vector<std::vector<double>>& cols, std::size_t n) {
  std::vector<const double*> cp;
  for (const auto& c : cols) cp.push_back(c.data());
  std::vector<double> out(n);
  Evaluator<double>(p).eval_batch_tape(cp.data(), out.data(), n);
  return out;
}

}  // namespace

TEST_CASE("JIT: every op within its bound on wide random ranges", "[numeric][jit]") {
  if (!jit_enabled()) { WARN("no JIT in this build"); return; }
  std::mt19937_64 rng(11);
  for (const OpCase& c : op_cases()) {
    INFO(op_name(c.op));
    const Program p = compile(c.expr, {x, y});
    REQUIRE(p.count(c.op) == 1);
    auto k = jit_of(p);
    const std::size_t n = 301;  // not a multiple of any width
    std::vector<std::vector<double>> cols(2, std::vector<double>(n));
    for (std::size_t i = 0; i < n; ++i) std::tie(cols[0][i], cols[1][i]) = c.point(rng);
    const auto got = run(*k, cols, n), want = tape(p, cols, n);
    double worst = 0;
    for (std::size_t i = 0; i < n; ++i) {
      INFO("x = " << cols[0][i] << ", y = " << cols[1][i] << ": jit " << got[i] << ", tape " << want[i]);
      if (c.ulps == 0 || !std::isfinite(want[i])) {
        REQUIRE(same_bits(got[i], want[i]));
        continue;
      }
      const GiNaC::exmap at{{x, exact_rational(cols[0][i])}, {y, exact_rational(cols[1][i])}};
      const double e = error_in_ulps(got[i], reference_value(c.expr, at, 25));
      worst = std::max(worst, e);
      REQUIRE(e <= c.ulps);
    }
    if (c.ulps > 0) WARN(op_name(c.op) << ": max error " << worst << " ulp (bound " << c.ulps << ")");
  }
}

TEST_CASE("JIT: special values propagate as in the tape", "[numeric][jit]") {
  if (!jit_enabled()) { WARN("no JIT in this build"); return; }
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> sv = {0.0, -0.0, inf, -inf, nan, 4.9e-324, -4.9e-324, 1.7e308, -1.7e308, 1.0, -1.0, 0.5};
  std::vector<std::vector<double>> cols(2);
  for (double a : sv)
    for (double b : sv) cols[0].push_back(a), cols[1].push_back(b);
  const std::size_t n = cols[0].size();
  for (const OpCase& c : op_cases()) {
    INFO(op_name(c.op));
    const Program p = compile(c.expr, {x, y});
    const auto got = run(*jit_of(p), cols, n), want = tape(p, cols, n);
    for (std::size_t i = 0; i < n; ++i) {
      INFO("x = " << cols[0][i] << ", y = " << cols[1][i] << ": jit " << got[i] << ", tape " << want[i]);
      if (c.ulps == 0 || std::isnan(want[i]) || std::isinf(want[i]) || want[i] == 0) {
        // NaN where the tape has NaN, the same infinity, a zero of the same sign
        REQUIRE(same_bits(got[i], want[i]));
      } else {
        REQUIRE(std::isfinite(got[i]));
        REQUIRE(std::fabs(got[i] - want[i]) <= 2 * std::fabs(want[i]) * 0x1p-52 + 0x1p-1074);
      }
    }
  }
}

namespace {
struct HandoutCase {
  const char* file;
  const char* label;
  bool rational;  // + - * / only: bit for bit the tape
};
const HandoutCase kHandout[] = {{"05_direct_impact.dc", "v1p_general", true},
                                {"05_direct_impact.dc", "energy_loss_general", true},
                                {"06_ballistic_pendulum.dc", "deflection", false},
                                {"07_two_ball_bounce.dc", "v1p_bounce", true},
                                {"03_ladder.dc", "wall_impulse", false}};
}  // namespace

TEST_CASE("JIT: handout formulas at lengths around the width, on every instruction set", "[numeric][jit]") {
  if (!jit_enabled()) { WARN("no JIT in this build"); return; }
  std::mt19937_64 rng(5);
  for (const auto& h : kHandout) {
    INFO(h.file << ":" << h.label);
    const auto& d = dc::test::handout(h.file);
    const auto pf = dc::chart::plain_formula(d, dc::formula(d, h.label).expr);
    const Program p = compile(pf.expr, pf.inputs);
    const std::size_t k = pf.inputs.size(), nmax = 1000;
    std::vector<std::vector<double>> cols(k, std::vector<double>(nmax));
    // points in [0.1, 1): masses, speeds, lengths, angles, e in (0, 1), acos arguments in range
    for (auto& c : cols)
      for (double& v : c) v = std::uniform_real_distribution<double>(0.1, 1.0)(rng);
    const auto want = tape(p, cols, nmax);
    for (const char* isa : {"avx512f", "avx2", "avx", "sse2"}) {
      std::string why;
      auto kern = JitKernel::compile(p, &why, isa);
      if (!kern) {
        WARN(isa << " not tested here: " << why);
        continue;
      }
      INFO(isa << ", W = " << kern->width());
      const std::size_t w = static_cast<std::size_t>(kern->width());
      // around the width, and around the main loop's 4 vectors per iteration
      for (std::size_t n : {std::size_t{0}, std::size_t{1}, w - 1, w, w + 1, 4 * w - 1, 4 * w, 4 * w + 1, 9 * w + 3, nmax}) {
        INFO("n = " << n);
        const auto got = run(*kern, cols, n);
        for (std::size_t i = 0; i < n; ++i) {
          INFO("point " << i << ": jit " << got[i] << ", tape " << want[i]);
          if (h.rational || std::isnan(want[i])) {  // NaN: acos argument out of range
            REQUIRE(same_bits(got[i], want[i]));
          } else {
            // no worse than the tape by more than 3 ulp (SLEEF's 1 ulp for acos; 1 ulp for
            // sin carried through s*sqrt(s): 1.5 ulp; plus the tape's own libm error)
            GiNaC::exmap at;
            for (std::size_t j = 0; j < k; ++j) at[pf.inputs[j]] = exact_rational(cols[j][i]);
            const GiNaC::numeric ref = reference_value(pf.expr, at, 25);
            REQUIRE(error_in_ulps(got[i], ref) <= error_in_ulps(want[i], ref) + 3);
          }
        }
      }
    }
  }
}

namespace {
// Each function of x at `pts` (and at -pts) against CLN at 25 digits, with AVX-512 and AVX2
// where the host has them: every error at most `bound` ulps (below it when `strict`).
void within_ulps_on_both_isas(std::vector<double> pts, const std::vector<ex>& fns, double bound, bool strict) {
  const std::size_t half = pts.size();
  for (std::size_t i = 0; i < half; ++i) pts.push_back(-pts[i]);
  const std::size_t n = pts.size();
  const std::vector<std::vector<double>> cols = {pts, std::vector<double>(n, 0.0)};
  for (const ex& f : fns) {
    INFO(f);
    const Program p = compile(f, {x, y});
    std::vector<GiNaC::numeric> ref(n);
    for (std::size_t i = 0; i < n; ++i) ref[i] = reference_value(f, {{x, exact_rational(pts[i])}}, 25);
    for (const char* isa : {"avx512f", "avx2"}) {
      std::string why;
      auto kern = JitKernel::compile(p, &why, isa);
      if (!kern) {
        WARN(isa << " not tested here: " << why);
        continue;
      }
      INFO(isa);
      const auto got = run(*kern, cols, n);
      double worst = 0;
      for (std::size_t i = 0; i < n; ++i) {
        INFO("x = " << std::hexfloat << pts[i] << ": " << got[i] << std::defaultfloat);
        const double e = error_in_ulps(got[i], ref[i]);
        worst = std::max(worst, e);
        REQUIRE((strict ? e < bound : e <= bound));
      }
      WARN(f << ", " << isa << ": max error " << worst << " ulp on " << n << " points");
    }
  }
}
}  // namespace

TEST_CASE("JIT: inline asin and acos below 0.9 ulp near 1/2, near 1, tiny and random, with AVX-512 and AVX2", "[numeric][jit]") {
  // numeric/jit_module/jit_arcsine.cpp derives 0.9 ulp; SLEEF's bound, which it replaces, is
  // 1 ulp. The points where its two ranges meet (|x| = 1/2), where the square root goes to 0
  // (|x| -> 1: 1 - k 2^-53 and 1 - 2^-j), tiny and subnormal x, and uniform ones.
  if (!jit_enabled()) { WARN("no JIT in this build"); return; }
  std::mt19937_64 rng(91);
  std::vector<double> pts;
  for (int k = 0; k <= 64; ++k) {
    pts.push_back(0.5 + k * 0x1p-54), pts.push_back(0.5 - k * 0x1p-55);
    pts.push_back(1 - k * 0x1p-53), pts.push_back(0.5 + k * 1e-9), pts.push_back(0.5 - k * 1e-9);
  }
  for (int j = 1; j <= 53; ++j) pts.push_back(1 - std::ldexp(1.0, -j)), pts.push_back(std::ldexp(1.0, -j));
  for (int i = 0; i < 400; ++i) pts.push_back(logu(rng, -320, -1, false));
  for (int i = 0; i < 3000; ++i) pts.push_back(std::uniform_real_distribution<double>(0, 1)(rng));
  within_ulps_on_both_isas(pts, {GiNaC::asin(x), GiNaC::acos(x)}, 0.9, true);
}

TEST_CASE("JIT: sin and cos within 1 ulp near multiples of pi/4 and k pi/2, tiny and random up to 1e6, with AVX-512 and AVX2", "[numeric][jit]") {
  // SLEEF's sin and cos (1 ulp documented) at the points where an argument reduction is
  // hardest. Points: next to k pi/4 (where the reduced argument is smallest or the quadrant changes),
  // the double nearest to k pi/2 for large k (the reduction's hardest cancellation), tiny and
  // subnormal x, log-uniform up to 10^6.
  if (!jit_enabled()) { WARN("no JIT in this build"); return; }
  std::mt19937_64 rng(92);
  std::vector<double> pts;
  const double quarter = 0.78539816339744830962;
  for (int k = 1; k <= 64; ++k)
    for (int d = -3; d <= 3; ++d) pts.push_back(std::nextafter(k * quarter, 0.0) + d * std::ldexp(1.0, std::ilogb(k * quarter) - 52));
  for (int i = 0; i < 300; ++i) {
    const double k = std::floor(std::pow(2.0, std::uniform_real_distribution<double>(0, 19.6)(rng)));
    pts.push_back(k * 1.5707963267948966);
  }
  for (int i = 0; i < 300; ++i) pts.push_back(logu(rng, -320, -3, false));
  for (int i = 0; i < 2500; ++i) pts.push_back(logu(rng, -3, 5.72, false));
  for (int i = 0; i < 100; ++i) pts.push_back(logu(rng, 5.72, 6, false));
  pts.push_back(0x1p19), pts.push_back(std::nextafter(0x1p19, 1e9));
  within_ulps_on_both_isas(pts, {GiNaC::sin(x), GiNaC::cos(x)}, 1.0, false);
  // signed zero, inf, NaN and a huge argument
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::vector<double>> sv = {{-0.0, 0.0, inf, -inf, std::nan(""), 1e300}, std::vector<double>(6, 0.0)};
  for (const ex f : {GiNaC::sin(x), GiNaC::cos(x)}) {
    const Program p = compile(f, {x, y});
    const auto got = run(*jit_of(p), sv, 6), want = tape(p, sv, 6);
    for (std::size_t i = 0; i < 5; ++i) REQUIRE(same_bits(got[i], want[i]));
    REQUIRE(std::fabs(got[5] - want[5]) <= 2 * std::fabs(want[5]) * 0x1p-52);
  }
}

TEST_CASE("JIT: a division by a constant is the tape's division, bit for bit, over the whole double range", "[numeric][jit]") {
  // jit_llvm.cpp replaces x / c by a multiplication and two FMAs (Markstein's correction) when
  // RN(1/c) is close enough to 1/c (3, 7, 10, 9.81, ... qualify; the others keep the division)
  // and sends |x| outside [2^-800, 2^800], zeros, inf and NaN to the division itself.
  if (!jit_enabled()) { WARN("no JIT in this build"); return; }
  std::mt19937_64 rng(93);
  std::vector<double> xs;
  for (int i = 0; i < 20000; ++i) {  // random bit patterns: every exponent, every significand
    std::uint64_t bits = rng();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    xs.push_back(v);
  }
  for (int i = 0; i < 20000; ++i) xs.push_back(std::ldexp(std::uniform_real_distribution<double>(1, 2)(rng), static_cast<int>(rng() % 1700) - 850));
  for (int i = 0; i < 2000; ++i) xs.push_back(static_cast<double>(rng() % 100000));  // integers: exact quotients
  for (double e : {0x1p-800, 0x1p800, 0x1.fffffffffffffp-801, 0x1.0000000000001p800, 0x1p-1074, 0x1p1023, 0.0, -0.0,
                   std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), std::nan("")})
    xs.push_back(e), xs.push_back(-e);
  const std::size_t n = xs.size();
  const std::vector<std::vector<double>> cols = {xs, std::vector<double>(n, 0.0)};
  for (double c : {3.0, -3.0, 7.0, 10.0, 9.81, 0.1, 1.5, 6.0, 1e-10, 12345.678, 1.0 / 3.0, 0x1.fffffffffffffp0, 1e300}) {
    INFO("c = " << c);
    const Program p = compile(x / GiNaC::numeric(exact_rational(c)), {x, y});
    REQUIRE(p.count(Op::Div) == 1);
    for (const char* isa : {"avx512f", "avx2"}) {
      std::string why;
      auto kern = JitKernel::compile(p, &why, isa);
      if (!kern) continue;
      INFO(isa);
      const auto got = run(*kern, cols, n), want = tape(p, cols, n);
      std::size_t diff = 0;
      for (std::size_t i = 0; i < n; ++i) diff += !same_bits(got[i], want[i]);
      REQUIRE(diff == 0);
    }
  }
}

TEST_CASE("JIT: one kernel called from two threads at once", "[numeric][jit]") {
  if (!jit_enabled()) { WARN("no JIT in this build"); return; }
  const Program p = compile(GiNaC::sin(x) * GiNaC::exp(y) + x / y, {x, y});
  auto k = jit_of(p);
  const std::size_t n = 100003;
  std::vector<std::vector<double>> a(2, std::vector<double>(n)), b(2, std::vector<double>(n));
  std::mt19937_64 rng(3);
  for (std::size_t i = 0; i < n; ++i)
    a[0][i] = logu(rng, -3, 3), a[1][i] = logu(rng, -3, 2), b[0][i] = logu(rng, -3, 3), b[1][i] = logu(rng, -3, 2);
  const auto ra = run(*k, a, n), rb = run(*k, b, n);
  std::vector<double> ta, tb;
  std::thread t1([&] { ta = run(*k, a, n); }), t2([&] { tb = run(*k, b, n); });
  t1.join(), t2.join();
  CHECK(std::memcmp(ta.data(), ra.data(), n * sizeof(double)) == 0);
  CHECK(std::memcmp(tb.data(), rb.data(), n * sizeof(double)) == 0);
}

TEST_CASE("JIT: Evaluator<double>::eval_batch uses it, DERIVCHECK_JIT=0 falls back to the tape", "[numeric][jit]") {
  const Program p = compile(GiNaC::acos(x / (1 + y)) + GiNaC::log(1 + x * y), {x, y});
  std::mt19937_64 rng(9);
  const std::size_t n = 777;
  std::vector<std::vector<double>> cols(2, std::vector<double>(n));
  for (auto& c : cols)
    for (double& v : c) v = std::uniform_real_distribution<double>(0, 1)(rng);
  std::vector<const double*> cp{cols[0].data(), cols[1].data()};
  const auto want = tape(p, cols, n);
  {
    Evaluator<double> ev(p);
    std::vector<double> out(n);
    ev.eval_batch(cp.data(), out.data(), n);
    CHECK((ev.jit() != nullptr) == jit_enabled());
    if (ev.jit()) CHECK(ev.jit()->isa() == jit_host_isa());
    for (std::size_t i = 0; i < n; ++i) REQUIRE(std::fabs(out[i] - want[i]) <= 4 * std::fabs(want[i]) * 0x1p-53);
  }
  ::setenv("DERIVCHECK_JIT", "0", 1);
  std::string why;
  CHECK(JitKernel::compile(p, &why) == nullptr);
  CHECK(!why.empty());
  CHECK_FALSE(jit_enabled());
  Evaluator<double> ev(p);
  std::vector<double> out(n);
  ev.eval_batch(cp.data(), out.data(), n);
  ::unsetenv("DERIVCHECK_JIT");
  CHECK(ev.jit() == nullptr);
  for (std::size_t i = 0; i < n; ++i) REQUIRE(same_bits(out[i], want[i]));
}

TEST_CASE("JIT: an instruction set the host lacks or does not know is refused", "[numeric][jit]") {
  if (!jit_enabled()) { WARN("no JIT in this build"); return; }
  std::string why;
  CHECK(JitKernel::compile(compile(x + y, {x, y}), &why, "neon") == nullptr);
  CHECK_THAT(why, Catch::Contains("neon"));
}

TEST_CASE("JIT: chart evalpoints runs the JIT, and the tape under DERIVCHECK_JIT=0", "[numeric][jit][cli]") {
  const std::string src = DERIVCHECK_SOURCE_DIR, dir = std::string(std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp");
  const std::string pts = dir + "/derivcheck_test_jit_pts_" + std::to_string(::getpid()) + ".bin",
                    out = dir + "/derivcheck_test_jit_out_" + std::to_string(::getpid()) + ".bin";
  {
    std::mt19937_64 rng(4);
    std::vector<double> v(4 * 37);
    for (double& d : v) d = std::uniform_real_distribution<double>(0.1, 1.0)(rng);
    std::FILE* f = std::fopen(pts.c_str(), "wb");
    REQUIRE(f);
    REQUIRE(std::fwrite(v.data(), sizeof(double), v.size(), f) == v.size());
    std::fclose(f);
  }
  auto run_cli = [&](const std::string& env) {
    const std::string cmd = env + " '" + DERIVCHECK_CLI + "' chart evalpoints '" + src +
                            "/derivations/handout9/07_two_ball_bounce.dc' v1p_bounce --inputs mu,e2,e12,v0 --points-file '" +
                            pts + "' --out-file '" + out + "' --repeats 1";
    std::string text;
    std::FILE* p = ::popen(cmd.c_str(), "r");
    REQUIRE(p);
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) text.append(buf, n);
    REQUIRE(::pclose(p) == 0);
    std::FILE* f = std::fopen(out.c_str(), "rb");
    REQUIRE(f);
    std::vector<double> y(37);
    REQUIRE(std::fread(y.data(), sizeof(double), y.size(), f) == y.size());
    std::fclose(f);
    return std::pair{text, y};
  };
  const auto [jit_text, jit_y] = run_cli("");
  const auto [tape_text, tape_y] = run_cli("DERIVCHECK_JIT=0");
  CHECK_THAT(tape_text, Catch::Contains("(tape)"));
  if (jit_enabled()) CHECK_THAT(jit_text, Catch::Contains("(JIT, " + jit_host_isa() + ")"));
  // v1p_bounce is rational: the JIT and the tape agree bit for bit
  CHECK(std::memcmp(jit_y.data(), tape_y.data(), jit_y.size() * sizeof(double)) == 0);
  std::remove(pts.c_str());
  std::remove(out.c_str());
}

TEST_CASE("JIT: programs whose result is an input or a constant, no inputs, many inputs", "[numeric][jit]") {
  if (!jit_enabled()) { WARN("no JIT in this build"); return; }
  const std::size_t n = 19;  // a tail on every width
  {
    std::vector<std::vector<double>> cols{std::vector<double>(n)};
    for (std::size_t i = 0; i < n; ++i) cols[0][i] = -0.5 * static_cast<double>(i);
    const auto got = run(*jit_of(compile(x, {x})), cols, n);  // the result is input 0
    CHECK(std::memcmp(got.data(), cols[0].data(), n * sizeof(double)) == 0);
  }
  {
    const Program p = compile(ex(3) / 7 + GiNaC::sqrt(ex(2)), {});  // folded to one constant, no inputs
    const auto got = run(*jit_of(p), {}, n), want = tape(p, {}, n);
    for (std::size_t i = 0; i < n; ++i) CHECK(same_bits(got[i], want[i]));
  }
  {
    // 20 inputs: more than the tail's stack buffers hold
    std::vector<symbol> s;
    ex sum = 0;
    for (int j = 0; j < 20; ++j) {
      s.emplace_back("a" + std::to_string(j));
      sum += (j + 1) * s.back() * s.back();
    }
    const Program p = compile(GiNaC::sqrt(sum), s);
    std::vector<std::vector<double>> cols(20, std::vector<double>(n));
    std::mt19937_64 rng(8);
    for (auto& c : cols)
      for (double& v : c) v = logu(rng, -3, 3);
    const auto got = run(*jit_of(p), cols, n), want = tape(p, cols, n);
    for (std::size_t i = 0; i < n; ++i) CHECK(same_bits(got[i], want[i]));
  }
}

TEST_CASE("JIT: a division by a power of two is the tape's division, bit for bit", "[numeric][jit]") {
  // the JIT multiplies by the exact reciprocal 2^-k; that is the same correctly rounded value,
  // subnormal results and the reciprocals of 2^1023 and 2^-1022 included; other divisors divide
  if (!jit_enabled()) { WARN("no JIT in this build"); return; }
  const std::size_t n = 203;
  std::vector<std::vector<double>> cols{std::vector<double>(n)};
  std::mt19937_64 rng(12);
  for (std::size_t i = 0; i < n; ++i) {
    const double mag = logu(rng, -320, 308);
    cols[0][i] = (i % 2 ? -1 : 1) * (i % 17 == 0 ? std::numeric_limits<double>::denorm_min() * static_cast<double>(i) : mag);
  }
  for (const ex& c : {ex(2), ex(-4), GiNaC::pow(ex(2), 1023), GiNaC::pow(ex(2), -1022), ex(GiNaC::numeric(1, 8)), ex(3),
                      ex(GiNaC::numeric(1, 10))}) {
    INFO("x / " << c);
    const Program p = compile(x / c, {x});
    const auto got = run(*jit_of(p), cols, n), want = tape(p, cols, n);
    for (std::size_t i = 0; i < n; ++i) {
      INFO("x = " << cols[0][i]);
      CHECK(same_bits(got[i], want[i]));
    }
  }
}
