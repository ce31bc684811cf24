// Time per limit claim on the limit corpus (tests/data/limits.jsonl; docs/performance.md,
// "Limits"). One benchmark per corpus line: the whole claim as `derivcheck claims` checks it
// (parse, Gruntz's algorithm on each side, the Arb sequence witness, the comparison with the
// claimed value).
//
//   bench_limits                     Google Benchmark, one entry per line
//   bench_limits --summary [N]       each line N times (default 5): the median over the lines of
//                                    the per-line median, the mean, the slowest line, and how the
//                                    verdicts compare with the labels
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "derivations/claims/claims.hpp"

namespace {

std::vector<std::string> corpus() {
  std::ifstream in(std::string(DERIVCHECK_SOURCE_DIR) + "/tests/data/limits.jsonl");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(line);
  return lines;
}

double seconds_of(const std::string& line, int n, std::string* verdict) {
  auto t0 = std::chrono::steady_clock::now();
  nlohmann::ordered_json r = dc::check_claim_line(line, n, "limits.jsonl");
  auto t1 = std::chrono::steady_clock::now();
  if (verdict) *verdict = r.value("verdict", "");
  return std::chrono::duration<double>(t1 - t0).count();
}

int summary(int repeats) {
  const auto lines = corpus();
  std::vector<double> medians;
  double slowest = 0;
  std::string slowest_id;
  int right = 0, undecided = 0, wrong = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const auto claim = nlohmann::json::parse(lines[i]);
    std::vector<double> t;
    std::string verdict;
    for (int k = 0; k < repeats; ++k) t.push_back(seconds_of(lines[i], static_cast<int>(i) + 1, &verdict));
    std::sort(t.begin(), t.end());
    const double med = t[t.size() / 2];
    medians.push_back(med);
    if (med > slowest) {
      slowest = med;
      slowest_id = claim.value("id", "");
    }
    const std::string expected = claim.value("expected", "");
    if (verdict == expected) ++right;
    else if (verdict == "undecided") ++undecided;
    else ++wrong;
  }
  std::vector<double> sorted = medians;
  std::sort(sorted.begin(), sorted.end());
  double total = 0;
  for (double m : medians) total += m;
  std::printf("lines %zu  repeats %d\n", lines.size(), repeats);
  std::printf("median per limit  %.2f ms\n", 1e3 * sorted[sorted.size() / 2]);
  std::printf("mean per limit    %.2f ms\n", 1e3 * total / static_cast<double>(medians.size()));
  std::printf("90th percentile   %.2f ms\n", 1e3 * sorted[sorted.size() * 9 / 10]);
  std::printf("slowest           %.2f ms (%s)\n", 1e3 * slowest, slowest_id.c_str());
  std::printf("total             %.2f s\n", total);
  std::printf("verdicts: %d as labelled, %d undecided, %d wrong\n", right, undecided, wrong);
  return wrong == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::strcmp(argv[1], "--summary") == 0) return summary(argc >= 3 ? std::atoi(argv[2]) : 5);
  const auto lines = corpus();
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string id = nlohmann::json::parse(lines[i]).value("id", "line" + std::to_string(i + 1));
    benchmark::RegisterBenchmark(("limit/" + id).c_str(), [line = lines[i], i](benchmark::State& state) {
      for (auto _ : state) benchmark::DoNotOptimize(seconds_of(line, static_cast<int>(i) + 1, nullptr));
    })->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
