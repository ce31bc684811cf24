// Time per claim for each stage of the prove_equal cascade (see docs/performance.md,
// "Checker cascade"). Each benchmark is one claim decided by the named stage, so its time is
// the cost of reaching and running that stage; the probe is also timed alone (symbolic stages
// off) at 50 and 100 digits.
#include <benchmark/benchmark.h>

#include <string>

#include "derivations/calculus/limit_entry.hpp"
#include "derivations/decide/prove.hpp"

using namespace dc;
using GiNaC::ex;

namespace {

struct Handout {
  SymbolTable t;
  ex m1, m2, v1, v2, e, z, x, ue, mr, m0, g, tt, m, M, v0, L;
  void add(const std::string& name, Domain d, ex& out) {
    SymbolInfo info;
    info.name = name;
    info.domain = std::move(d);
    out = t.declare(info).sym;
  }
  Handout() {
    add("m1", Domain::positive(), m1);
    add("m2", Domain::positive(), m2);
    add("v1", Domain::real(), v1);
    add("v2", Domain::real(), v2);
    add("e", Domain::interval(0, false, 1, false), e);
    add("z", Domain::interval(0, false, 1, false), z);
    add("x", Domain::positive(), x);
    add("u_e", Domain::positive(), ue);
    add("m_r", Domain::positive(), mr);
    add("m0", Domain::positive(), m0);
    add("g", Domain::positive(), g);
    add("t", Domain::nonnegative(), tt);
    add("m", Domain::positive(), m);
    add("M", Domain::positive(), M);
    add("v0", Domain::positive(), v0);
    add("L", Domain::positive(), L);
  }
  ex v1p() const { return ((m1 - e * m2) * v1 + (1 + e) * m2 * v2) / (m1 + m2); }
  ex v2p() const { return ((m2 - e * m1) * v2 + (1 + e) * m1 * v1) / (m1 + m2); }
  // general energy loss: T_before - T_after = (1 - e^2)/2 m1 m2/(m1+m2) (v1 - v2)^2
  std::pair<ex, ex> delta_T() const {
    ex h = GiNaC::numeric(1, 2);
    ex T0 = h * m1 * v1 * v1 + h * m2 * v2 * v2;
    ex T1 = h * m1 * GiNaC::pow(v1p(), 2) + h * m2 * GiNaC::pow(v2p(), 2);
    return {T0 - T1, (1 - e * e) / 2 * m1 * m2 / (m1 + m2) * GiNaC::pow(v1 - v2, 2)};
  }
};

Handout& H() {
  static Handout h;
  return h;
}

void run(benchmark::State& state, const ex& l, const ex& r, const ProveOptions& opt, VerdictKind expect) {
  for (auto _ : state) {
    Verdict v = prove_equal(l, r, H().t, opt);
    if (v.kind != expect) {
      state.SkipWithError(("unexpected verdict: " + v.detail).c_str());
      break;
    }
    benchmark::DoNotOptimize(v);
  }
}

ProveOptions probe_only(int digits) {
  ProveOptions o;
  o.symbolic = false;
  o.digits = digits;
  return o;
}

// Stage 1: normal
void BM_normal_momentum(benchmark::State& s) {
  auto& h = H();
  run(s, h.m1 * h.v1 + h.m2 * h.v2, h.m1 * h.v1p() + h.m2 * h.v2p(), {}, VerdictKind::Proved);
}
void BM_normal_deltaT(benchmark::State& s) {
  auto [l, r] = H().delta_T();
  run(s, l, r, {}, VerdictKind::Proved);
}
// Stage 2: transcendental rules (rocket: -u_e ln(m_r/m0) - g t = u_e ln(m0/m_r) - g t)
void BM_expand_transcendental_rocket(benchmark::State& s) {
  auto& h = H();
  run(s, -h.ue * GiNaC::log(h.mr / h.m0) - h.g * h.tt, h.ue * GiNaC::log(h.m0 / h.mr) - h.g * h.tt, {},
      VerdictKind::Proved);
}
// Stage 3: side relations
void BM_side_relations_trig(benchmark::State& s) {
  auto& h = H();
  ex sx = GiNaC::sin(h.x), cx = GiNaC::cos(h.x);
  run(s, GiNaC::pow(sx, 4) - GiNaC::pow(cx, 4), GiNaC::pow(sx, 2) - GiNaC::pow(cx, 2), {}, VerdictKind::Proved);
}
// Stage 4 inside the cascade: stages 1-3 fail, the probe decides
void BM_cascade_probe_acos(benchmark::State& s) {
  auto& h = H();
  run(s, GiNaC::acos(1 - 2 * h.z * h.z), 2 * GiNaC::asin(h.z), {}, VerdictKind::HoldsNumerically);
}
void BM_cascade_refute_sign_slip(benchmark::State& s) {
  auto& h = H();
  ex wrong = ((h.m1 + h.e * h.m2) * h.v1 + (1 + h.e) * h.m2 * h.v2) / (h.m1 + h.m2);
  run(s, h.v1p(), wrong, {}, VerdictKind::Refuted);
}
void BM_cascade_refute_ramanujan(benchmark::State& s) {
  run(s, GiNaC::exp(GiNaC::Pi * GiNaC::sqrt(ex(163))), GiNaC::pow(ex(640320), 3) + 744, {}, VerdictKind::Refuted);
}
// The probe alone at 50 and 100 digits (6 points)
void BM_probe_acos(benchmark::State& s) {
  auto& h = H();
  run(s, GiNaC::acos(1 - 2 * h.z * h.z), 2 * GiNaC::asin(h.z), probe_only(static_cast<int>(s.range(0))),
      VerdictKind::HoldsNumerically);
}
void BM_probe_pendulum(benchmark::State& s) {
  // ballistic pendulum: theta = acos(1 - (m/(M+m))^2 v0^2/(2 L g)) against the half-angle form
  // 2 asin(m v0/(2 (M+m) sqrt(L g))) (true where the asin argument is <= 1; other points are
  // rejected by the real-domain guard)
  auto& h = H();
  ex theta = GiNaC::acos(1 - GiNaC::pow(h.m / (h.M + h.m), 2) * h.v0 * h.v0 / (2 * h.L * h.g));
  ex half = 2 * GiNaC::asin(h.m * h.v0 / (2 * (h.M + h.m) * GiNaC::sqrt(h.L * h.g)));
  run(s, theta, half, probe_only(static_cast<int>(s.range(0))), VerdictKind::HoldsNumerically);
}
void BM_probe_deltaT(benchmark::State& s) {
  auto [l, r] = H().delta_T();
  run(s, l, r, probe_only(static_cast<int>(s.range(0))), VerdictKind::HoldsNumerically);
}
// The limit helper: the wall limit m2 -> oo
void BM_limit_wall(benchmark::State& s) {
  auto& h = H();
  ex f = (h.m1 - h.m2) * h.v1 / (h.m1 + h.m2);
  const auto& m2 = GiNaC::ex_to<GiNaC::symbol>(h.m2);
  for (auto _ : s) {
    LimitResult r = compute_limit(f, m2, 0, +1, h.t);
    if (!r.ok) {
      s.SkipWithError(r.reason.c_str());
      break;
    }
    benchmark::DoNotOptimize(r);
  }
}

}  // namespace

BENCHMARK(BM_normal_momentum)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_normal_deltaT)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_expand_transcendental_rocket)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_side_relations_trig)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_cascade_probe_acos)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_cascade_refute_sign_slip)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_cascade_refute_ramanujan)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_probe_acos)->Arg(50)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_probe_pendulum)->Arg(50)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_probe_deltaT)->Arg(50)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_limit_wall)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
