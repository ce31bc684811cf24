// Whole-file checking: load + check every step of each derivations/handout9/*.dc file
// (what `derivcheck check` does per file, without process start-up and printing).
//   build/bench/bench_check --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "derivations/reader/derivation.hpp"
#include "derivations/rules/check.hpp"

namespace {

std::vector<std::string> handout_files() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9"))
    if (e.path().extension() == ".dc") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

void BM_check_file(benchmark::State& state, std::string path) {
  std::size_t steps = 0;
  for (auto _ : state) {
    dc::Derivation d = dc::load_derivation(path);
    dc::CheckSummary s = dc::check_derivation(d);
    steps = s.results.size();
    benchmark::DoNotOptimize(s);
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["per_step"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_check_handout(benchmark::State& state) {
  const auto files = handout_files();
  for (auto _ : state)
    for (const auto& f : files) {
      dc::Derivation d = dc::load_derivation(f);
      benchmark::DoNotOptimize(dc::check_derivation(d));
    }
}

const bool registered = [] {
  for (const auto& f : handout_files())
    benchmark::RegisterBenchmark(("check/" + std::filesystem::path(f).stem().string()).c_str(), BM_check_file, f)
        ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("check/handout9 (all files)", BM_check_handout)->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
