// Expression parser and to_ginac: throughput on a large input and the time to reject
// pathological inputs (design notes §2: GiNaC's parser segfaults on ~8000 nested parentheses
// and runs away on 2^(10^10)).
//
//   bench_parse --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <string>

#include "derivations/syntax/expr.hpp"
#include "derivations/syntax/source.hpp"
#include "derivations/symbolic/symbols.hpp"

namespace {

const dc::SourcePos kAt{"bench", 1, 1};

// ~100 kB of handout-like terms: the general impact result v1' repeated.
std::string big_expression(std::size_t bytes) {
  const std::string term = "(m1*v1 + m2*v2 - e*m2*(v1 - v2))/(m1 + m2)";
  std::string s = term;
  while (s.size() + term.size() + 3 <= bytes) s += " + " + term;
  return s;
}

dc::SymbolTable impact_table() {
  dc::SymbolTable t;
  for (const char* n : {"m1", "m2", "v1", "v2", "e"}) {
    dc::SymbolInfo info;
    info.name = n;
    info.domain = n[0] == 'm' ? dc::Domain::positive() : dc::Domain::real();
    t.declare(info);
  }
  return t;
}

void expect_error(benchmark::State& state, const std::string& text, const dc::ParseLimits& lim) {
  for (auto _ : state) {
    try {
      dc::Node n = dc::parse_expression(text, kAt, lim);
      benchmark::DoNotOptimize(n);
      state.SkipWithError("no error");
      break;
    } catch (const dc::InputError& e) {
      benchmark::DoNotOptimize(e.pos().col);
    }
  }
}

void BM_Parse100kB(benchmark::State& state) {
  const std::string s = big_expression(100000);
  for (auto _ : state) {
    dc::Node n = dc::parse_expression(s, kAt);
    benchmark::DoNotOptimize(n);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(s.size()));
}
BENCHMARK(BM_Parse100kB)->Unit(benchmark::kMillisecond);

void BM_ParseImpactFormula(benchmark::State& state) {
  const std::string s = "(m1*v1 + m2*v2 - e*m2*(v1 - v2))/(m1 + m2)";
  for (auto _ : state) {
    dc::Node n = dc::parse_expression(s, kAt);
    benchmark::DoNotOptimize(n);
  }
}
BENCHMARK(BM_ParseImpactFormula)->Unit(benchmark::kMicrosecond);

void BM_ToGinac100kB(benchmark::State& state) {
  const std::string s = big_expression(100000);
  const dc::SymbolTable t = impact_table();
  const dc::Node n = dc::parse_expression(s, kAt);
  for (auto _ : state) {
    GiNaC::ex e = dc::to_ginac(n, t);
    benchmark::DoNotOptimize(e);
  }
}
BENCHMARK(BM_ToGinac100kB)->Unit(benchmark::kMillisecond);

void BM_Reject1e5Parens(benchmark::State& state) {
  dc::ParseLimits lim;
  lim.max_length = 300000;
  expect_error(state, std::string(100000, '(') + "x" + std::string(100000, ')'), lim);
}
BENCHMARK(BM_Reject1e5Parens)->Unit(benchmark::kMillisecond);

void BM_Reject20000UnaryMinus(benchmark::State& state) {
  expect_error(state, std::string(20000, '-') + "x", {});
}
BENCHMARK(BM_Reject20000UnaryMinus)->Unit(benchmark::kMillisecond);

void BM_RejectPow2e10(benchmark::State& state) {
  const dc::SymbolTable t;
  const dc::Node n = dc::parse_expression("2^(10^10)", kAt);
  for (auto _ : state) {
    try {
      GiNaC::ex e = dc::to_ginac(n, t);
      benchmark::DoNotOptimize(e);
      state.SkipWithError("no error");
      break;
    } catch (const dc::InputError& e) {
      benchmark::DoNotOptimize(e.pos().col);
    }
  }
}
BENCHMARK(BM_RejectPow2e10)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
