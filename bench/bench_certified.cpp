// The certified automatic mode's fast stages against plain double, on the handout formulas that
// bench/peers times: per point, the long double tape with a running error bound
// (numeric/certified/certified_fast.hpp) against the double tape; over a batch, the double-double stage
// with its long double fallback (numeric/certified/certified_batch.hpp) against the double tape's batch
// and the JIT (the default fast path). Points: seeded, uniform in [0.5, 5] for every parameter (e in
// [0.05, 0.95]), kept where the double tape gives a finite value. The counter `escalated` is the
// fraction of points where the fast stages cannot decide the rounding and the Arb enclosure would
// take over (the benchmark times the fast stages only); `long_double` the fraction the batch's
// second stage decided. Figures: docs/performance.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "derivations/reader/derivation.hpp"
#include "numeric/certified/certified_batch.hpp"
#include "numeric/certified/certified_fast.hpp"
#include "numeric/evaluator.hpp"

namespace {

constexpr std::size_t kPoints = 2048;

struct Case {
  const char* file;
  const char* label;
};
const Case kCases[] = {
    {"05_direct_impact.dc", "v1p_general"},   {"05_direct_impact.dc", "energy_loss_general"},
    {"06_ballistic_pendulum.dc", "deflection"}, {"07_two_ball_bounce.dc", "v1p_bounce"},
    {"03_ladder.dc", "wall_impulse"},         {"09_rocket.dc", "velocity_symbols"},
};

struct Data {
  dc::num::Program prog;
  std::size_t k = 0;
  std::vector<double> pts;   // row-major kPoints x k
  std::vector<std::vector<double>> cols;   // the same points as columns
  explicit Data(const Case& c) {
    const dc::Derivation d =
        dc::load_derivation(std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9/" + c.file);
    const dc::Formula f = dc::formula(d, c.label);
    prog = dc::num::compile(f.expr, f.params);
    k = f.params.size();
    const dc::num::Evaluator<double> ev(prog);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0.5, 5.0), ue(0.05, 0.95);
    std::vector<double> x(k);
    while (pts.size() < kPoints * k) {
      for (std::size_t j = 0; j < k; ++j) x[j] = f.params[j].get_name() == "e" ? ue(rng) : u(rng);
      if (std::isfinite(ev(x.data()))) pts.insert(pts.end(), x.begin(), x.end());
    }
    cols.assign(k, std::vector<double>(kPoints));
    for (std::size_t i = 0; i < kPoints; ++i)
      for (std::size_t j = 0; j < k; ++j) cols[j][i] = pts[i * k + j];
  }
  std::vector<const double*> columns() const {
    std::vector<const double*> c;
    for (const auto& v : cols) c.push_back(v.data());
    return c;
  }
};

const Data& data(std::size_t i) {
  static std::vector<std::unique_ptr<Data>> cache(std::size(kCases));
  if (!cache[i]) cache[i] = std::make_unique<Data>(kCases[i]);
  return *cache[i];
}

void BM_plain_double(benchmark::State& st) {
  const Data& D = data(static_cast<std::size_t>(st.range(0)));
  st.SetLabel(kCases[st.range(0)].label);
  const dc::num::Evaluator<double> ev(D.prog);
  double acc = 0;
  for (auto _ : st) {
    for (std::size_t i = 0; i < kPoints; ++i) acc += ev(D.pts.data() + i * D.k);
    benchmark::DoNotOptimize(acc);
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * kPoints));
}

void BM_certified_fast(benchmark::State& st) {
  const Data& D = data(static_cast<std::size_t>(st.range(0)));
  st.SetLabel(kCases[st.range(0)].label);
  const dc::num::CertifiedTape tape(D.prog);
  double acc = 0;
  std::size_t escalated = 0, total = 0;
  for (auto _ : st) {
    for (std::size_t i = 0; i < kPoints; ++i) {
      const dc::num::FastCertified r = tape(D.pts.data() + i * D.k);
      acc += r.value;
      escalated += r.decided ? 0 : 1;
    }
    total += kPoints;
    benchmark::DoNotOptimize(acc);
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * kPoints));
  st.counters["escalated"] = total ? static_cast<double>(escalated) / static_cast<double>(total) : 0;
}

// plain double over the batch: the tape's block loop, and the JIT (eval_batch)
void BM_plain_double_batch(benchmark::State& st, bool jit) {
  const Data& D = data(static_cast<std::size_t>(st.range(0)));
  st.SetLabel(std::string(kCases[st.range(0)].label) + (jit ? " (JIT)" : " (tape)"));
  dc::num::Evaluator<double> ev(D.prog);
  const std::vector<const double*> cols = D.columns();
  std::vector<double> out(kPoints);
  if (jit) ev.eval_batch(cols.data(), out.data(), kPoints);   // compiles outside the timing
  for (auto _ : st) {
    if (jit) ev.eval_batch(cols.data(), out.data(), kPoints);
    else ev.eval_batch_tape(cols.data(), out.data(), kPoints);
    benchmark::DoNotOptimize(out.data());
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * kPoints));
}
void BM_plain_double_tape_batch(benchmark::State& st) { BM_plain_double_batch(st, false); }
void BM_plain_double_jit(benchmark::State& st) { BM_plain_double_batch(st, true); }

void BM_certified_batch(benchmark::State& st) {
  const Data& D = data(static_cast<std::size_t>(st.range(0)));
  st.SetLabel(kCases[st.range(0)].label);
  const dc::num::CertifiedBatch batch(D.prog);
  const std::vector<const double*> cols = D.columns();
  std::vector<double> out(kPoints);
  std::vector<dc::num::CertifiedStage> stage(kPoints);
  dc::num::CertifiedBatchStats s;
  for (auto _ : st) {
    s = batch.eval({cols.data()}, kPoints, out.data(), stage.data());
    benchmark::DoNotOptimize(out.data());
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * kPoints));
  st.counters["long_double"] = static_cast<double>(s.long_double) / kPoints;
  st.counters["escalated"] = static_cast<double>(s.undecided) / kPoints;
}

}  // namespace

BENCHMARK(BM_plain_double)->DenseRange(0, std::size(kCases) - 1);
BENCHMARK(BM_certified_fast)->DenseRange(0, std::size(kCases) - 1);
BENCHMARK(BM_plain_double_tape_batch)->DenseRange(0, std::size(kCases) - 1);
BENCHMARK(BM_plain_double_jit)->DenseRange(0, std::size(kCases) - 1);
BENCHMARK(BM_certified_batch)->DenseRange(0, std::size(kCases) - 1);
BENCHMARK_MAIN();
