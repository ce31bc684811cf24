// The fast evaluator against a hand-written C++ function of the same formula, and GiNaC evalf,
// in one run. Formula: the general impact v'1 = (m1 v1 + m2 v2 - e m2 (v1 - v2))/(m1 + m2),
// loaded by label from derivations/handout9/05_direct_impact.dc (v1p_general).
// Throughput = items_per_second (evaluations per second). Figures: docs/performance.md.
// The JIT (numeric/jit.hpp) on the same points, at each vector width the host has, and on
// Example 9.5's deflection (acos, sqrt: SLEEF against libm); BM_jit_compile* is what a user
// pays once per formula.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "derivations/reader/derivation.hpp"
#include "derivations/decide/prove.hpp"
#include "numeric/compensated.hpp"
#include "numeric/evaluator.hpp"
#include "numeric/jit.hpp"

namespace {

constexpr std::size_t kPoints = 4096;

struct Data {
  dc::Formula f;
  std::vector<GiNaC::ex> syms;  // the table's symbols (possymbols), for subs
  dc::num::Program prog;
  Eigen::ArrayXXd in;  // columns m1, m2, v1, v2, e (the formula's parameter order)
  Data() {
    static const dc::Derivation d =
        dc::load_derivation(std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9/05_direct_impact.dc");
    f = dc::formula(d, "v1p_general");
    prog = dc::num::compile(f.expr, f.params);
    std::vector<std::string> names;
    for (const auto& s : f.params) {
      names.push_back(s.get_name());
      syms.push_back(d.symbols.find(s.get_name())->sym);
    }
    if (names != std::vector<std::string>{"m1", "m2", "v1", "v2", "e"}) throw std::runtime_error("unexpected parameter order");
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0.1, 10.0);
    in.resize(kPoints, 5);
    for (std::size_t i = 0; i < kPoints; ++i) {
      in(i, 0) = u(rng);
      in(i, 1) = u(rng);
      in(i, 2) = u(rng) + 10;
      in(i, 3) = u(rng);
      in(i, 4) = u(rng) / 10;
    }
  }
};

const Data& data() {
  static const Data d;
  return d;
}

// (9.6)/(9.7) solved: the hand-written reference implementation
inline double v1p_hand(double m1, double m2, double v1, double v2, double e) {
  return (m1 * v1 + m2 * v2 - e * m2 * (v1 - v2)) / (m1 + m2);
}

void BM_hand_written(benchmark::State& st) {
  const auto& D = data();
  const double *m1 = D.in.col(0).data(), *m2 = D.in.col(1).data(), *v1 = D.in.col(2).data(),
               *v2 = D.in.col(3).data(), *e = D.in.col(4).data();
  std::vector<double> out(kPoints);
  for (auto _ : st) {
    for (std::size_t i = 0; i < kPoints; ++i) out[i] = v1p_hand(m1[i], m2[i], v1[i], v2[i], e[i]);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * kPoints));
}

// The same loop, with the compiler prevented from vectorising across points (one call at a
// time, as a scalar library function would be used).
void BM_hand_written_scalar(benchmark::State& st) {
  const auto& D = data();
  std::vector<double> out(kPoints);
  for (auto _ : st) {
    for (std::size_t i = 0; i < kPoints; ++i) {
      double a = D.in(i, 0), b = D.in(i, 1), c = D.in(i, 2), d = D.in(i, 3), e = D.in(i, 4);
      benchmark::DoNotOptimize(a);
      out[i] = v1p_hand(a, b, c, d, e);
    }
    benchmark::DoNotOptimize(out.data());
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * kPoints));
}

void BM_tape_scalar(benchmark::State& st) {
  const auto& D = data();
  dc::num::Evaluator<double> ev(D.prog);
  std::vector<double> out(kPoints);
  double x[5];
  for (auto _ : st) {
    for (std::size_t i = 0; i < kPoints; ++i) {
      for (int j = 0; j < 5; ++j) x[j] = D.in(static_cast<Eigen::Index>(i), j);
      out[i] = ev(x);
    }
    benchmark::DoNotOptimize(out.data());
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * kPoints));
}

void BM_tape_batch(benchmark::State& st) {
  const auto& D = data();
  dc::num::Evaluator<double> ev(D.prog);
  std::vector<const double*> cols;
  for (Eigen::Index j = 0; j < D.in.cols(); ++j) cols.push_back(D.in.col(j).data());
  Eigen::ArrayXd out(kPoints);
  for (auto _ : st) {
    ev.eval_batch_tape(cols.data(), out.data(), kPoints);
    benchmark::DoNotOptimize(out.data());
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * kPoints));
}

// The JIT kernel for the instruction set `isa` ("" = the host's widest); skipped where the host
// lacks it or the build has no JIT.
void run_jit(benchmark::State& st, const dc::num::Program& prog, const Eigen::ArrayXXd& in, const char* isa) {
  std::string why;
  const auto k = dc::num::JitKernel::compile(prog, &why, isa);
  if (!k) {
    st.SkipWithError(why.c_str());
    return;
  }
  std::vector<const double*> cols;
  for (Eigen::Index j = 0; j < in.cols(); ++j) cols.push_back(in.col(j).data());
  Eigen::ArrayXd out(in.rows());
  for (auto _ : st) {
    (*k)(cols.data(), out.data(), static_cast<std::size_t>(in.rows()));
    benchmark::DoNotOptimize(out.data());
  }
  st.SetLabel(k->isa() + ", W=" + std::to_string(k->width()));
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * in.rows()));
}

void BM_jit_batch(benchmark::State& st) { run_jit(st, data().prog, data().in, ""); }
void BM_jit_batch_avx2(benchmark::State& st) { run_jit(st, data().prog, data().in, "avx2"); }
void BM_jit_batch_sse2(benchmark::State& st) { run_jit(st, data().prog, data().in, "sse2"); }

void BM_jit_compile(benchmark::State& st) {
  const auto& D = data();
  for (auto _ : st) {
    auto k = dc::num::JitKernel::compile(D.prog);
    if (!k) {
      st.SkipWithError("no JIT");
      return;
    }
    benchmark::DoNotOptimize(k.get());
  }
}

// A handout formula on 4096 points drawn from [0.5, 2) per input, redrawn where the value is
// not finite (Example 9.5's acos argument outside [-1, 1])
struct Loaded {
  dc::num::Program prog;
  Eigen::ArrayXXd in;
  Loaded(const char* file, const char* label) {
    const dc::Derivation d = dc::load_derivation(std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9/" + file);
    const dc::Formula f = dc::formula(d, label);
    prog = dc::num::compile(f.expr, f.params);
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(0.5, 2.0);
    in.resize(kPoints, static_cast<Eigen::Index>(f.params.size()));
    for (Eigen::Index i = 0; i < in.rows(); ++i)
      for (Eigen::Index j = 0; j < in.cols(); ++j) in(i, j) = u(rng);
    dc::num::Evaluator<double> ev(prog);
    Eigen::ArrayXd out;
    ev.eval_batch(in, out);
    for (Eigen::Index i = 0; i < in.rows(); ++i)
      while (!std::isfinite(out(i))) {
        for (Eigen::Index j = 0; j < in.cols(); ++j) in(i, j) = u(rng);
        std::vector<double> x(in.cols());
        for (Eigen::Index j = 0; j < in.cols(); ++j) x[static_cast<std::size_t>(j)] = in(i, j);
        out(i) = ev(x);
      }
  }
};
// Example 9.5: theta = acos(1 - (m/(M+m))^2 v0^2/(2 L g))
const Loaded& deflection() {
  static const Loaded d("06_ballistic_pendulum.dc", "deflection");
  return d;
}
// Example 9.3: J_w = m sin(theta0) sqrt(g l sin(theta0))/3 (sin, sqrt)
const Loaded& wall_impulse() {
  static const Loaded d("03_ladder.dc", "wall_impulse");
  return d;
}

void BM_tape_batch_deflection(benchmark::State& st) {
  const auto& D = deflection();
  dc::num::Evaluator<double> ev(D.prog);
  std::vector<const double*> cols;
  for (Eigen::Index j = 0; j < D.in.cols(); ++j) cols.push_back(D.in.col(j).data());
  Eigen::ArrayXd out(kPoints);
  for (auto _ : st) {
    ev.eval_batch_tape(cols.data(), out.data(), kPoints);
    benchmark::DoNotOptimize(out.data());
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * kPoints));
}
void BM_jit_batch_deflection(benchmark::State& st) { run_jit(st, deflection().prog, deflection().in, ""); }
void BM_jit_batch_deflection_avx2(benchmark::State& st) { run_jit(st, deflection().prog, deflection().in, "avx2"); }
void BM_jit_batch_wall_impulse(benchmark::State& st) { run_jit(st, wall_impulse().prog, wall_impulse().in, ""); }
void BM_jit_batch_wall_impulse_avx2(benchmark::State& st) { run_jit(st, wall_impulse().prog, wall_impulse().in, "avx2"); }
void BM_jit_compile_deflection(benchmark::State& st) {
  for (auto _ : st) {
    auto k = dc::num::JitKernel::compile(deflection().prog);
    if (!k) {
      st.SkipWithError("no JIT");
      return;
    }
    benchmark::DoNotOptimize(k.get());
  }
}

void BM_tape_batch_long_double(benchmark::State& st) {
  const auto& D = data();
  dc::num::Evaluator<long double> ev(D.prog);
  const Eigen::Array<long double, Eigen::Dynamic, Eigen::Dynamic> in = D.in.cast<long double>();
  Eigen::Array<long double, Eigen::Dynamic, 1> out(kPoints);
  for (auto _ : st) {
    ev.eval_batch(in, out);
    benchmark::DoNotOptimize(out.data());
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * kPoints));
}

// the same tape in double-double (compensated.hpp): what FormulaEvaluator's Auto mode runs for
// v'1, whose value crosses zero in the domain
void BM_tape_batch_compensated(benchmark::State& st) {
  const auto& D = data();
  dc::num::CompensatedEvaluator ev(D.prog);
  Eigen::ArrayXd out(kPoints);
  for (auto _ : st) {
    ev.eval_batch(D.in, out);
    benchmark::DoNotOptimize(out.data());
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * kPoints));
}

void BM_tape_scalar_compensated(benchmark::State& st) {
  const auto& D = data();
  dc::num::CompensatedEvaluator ev(D.prog);
  std::vector<double> x(5);
  std::size_t i = 0;
  for (auto _ : st) {
    for (int j = 0; j < 5; ++j) x[static_cast<std::size_t>(j)] = D.in(static_cast<Eigen::Index>(i), j);
    benchmark::DoNotOptimize(ev(x.data()));
    i = (i + 1) % kPoints;
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations()));
}

void BM_ginac_evalf(benchmark::State& st) {
  const auto& D = data();
  dc::DigitsGuard guard(15);
  std::size_t i = 0;
  for (auto _ : st) {
    GiNaC::exmap m;
    for (int j = 0; j < 5; ++j) m[D.syms[static_cast<std::size_t>(j)]] = D.in(static_cast<Eigen::Index>(i % kPoints), j);
    benchmark::DoNotOptimize(GiNaC::evalf(D.f.expr.subs(m)));
    ++i;
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations()));
}

void BM_compile(benchmark::State& st) {
  const auto& D = data();
  for (auto _ : st) benchmark::DoNotOptimize(dc::num::compile(D.f.expr, D.f.params));
}

}  // namespace

BENCHMARK(BM_hand_written);
BENCHMARK(BM_hand_written_scalar);
BENCHMARK(BM_tape_scalar);
BENCHMARK(BM_tape_batch);
BENCHMARK(BM_jit_batch);
BENCHMARK(BM_jit_batch_avx2);
BENCHMARK(BM_jit_batch_sse2);
BENCHMARK(BM_tape_batch_deflection);
BENCHMARK(BM_jit_batch_deflection);
BENCHMARK(BM_jit_batch_deflection_avx2);
BENCHMARK(BM_jit_batch_wall_impulse);
BENCHMARK(BM_jit_batch_wall_impulse_avx2);
BENCHMARK(BM_tape_batch_long_double);
BENCHMARK(BM_tape_batch_compensated);
BENCHMARK(BM_tape_scalar_compensated);
BENCHMARK(BM_ginac_evalf);
BENCHMARK(BM_compile);
BENCHMARK(BM_jit_compile)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_jit_compile_deflection)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
