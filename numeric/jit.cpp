// The JIT's host side (numeric/jit.hpp): choosing the instruction set, the SLEEF functions for
// it, the switch in the environment, and the padded tail. Code generation: jit_llvm.cpp.
#include "numeric/jit.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "numeric/jit_internal.hpp"

#if DERIVCHECK_HAVE_JIT
// SLEEF 3.5.1 (libsleef3), one symbol per function and instruction set; the names are checked
// against `nm -D libsleef.so`. u10: max error 1.0 ulp; u05: 0.5001 ulp (SLEEF's documentation;
// the tests in tests/numeric/test_jit.cpp measure them against CLN on wide ranges).
#define DC_SLEEF_FNS(X, V, ISA)                                                                 \
  X(exp, V, u10, ISA) X(expm1, V, u10, ISA) X(log, V, u10, ISA) X(log1p, V, u10, ISA)           \
  X(sin, V, u10, ISA) X(cos, V, u10, ISA) X(tan, V, u10, ISA) X(asin, V, u10, ISA)              \
  X(acos, V, u10, ISA) X(atan, V, u10, ISA) X(pow, V, u10, ISA) X(hypot, V, u05, ISA)
#define DC_SLEEF_DECL(f, V, U, ISA) extern "C" void Sleef_##f##V##_##U##ISA();
DC_SLEEF_FNS(DC_SLEEF_DECL, d8, avx512f)
DC_SLEEF_FNS(DC_SLEEF_DECL, d4, avx2)
DC_SLEEF_FNS(DC_SLEEF_DECL, d4, avx)
DC_SLEEF_FNS(DC_SLEEF_DECL, d2, sse2)
#define DC_SLEEF_ENTRY(f, V, U, ISA) \
  {#f, "Sleef_" #f #V "_" #U #ISA, reinterpret_cast<void*>(&Sleef_##f##V##_##U##ISA)},
#endif

namespace dc::num {

#if DERIVCHECK_HAVE_JIT

namespace jitdetail {
namespace {
const std::vector<IsaSpec>& isa_table() {
  static const std::vector<IsaSpec> t = {
      {"avx512f", 8, {{DC_SLEEF_FNS(DC_SLEEF_ENTRY, d8, avx512f)}}},
      {"avx2", 4, {{DC_SLEEF_FNS(DC_SLEEF_ENTRY, d4, avx2)}}},
      {"avx", 4, {{DC_SLEEF_FNS(DC_SLEEF_ENTRY, d4, avx)}}},
      {"sse2", 2, {{DC_SLEEF_FNS(DC_SLEEF_ENTRY, d2, sse2)}}},
  };
  return t;
}

bool host_has(const std::string& isa) {
  __builtin_cpu_init();
  if (isa == "avx512f") return __builtin_cpu_supports("avx512f");
  if (isa == "avx2") return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  if (isa == "avx") return __builtin_cpu_supports("avx");
  return isa == "sse2";  // x86-64 baseline
}
}  // namespace

const IsaSpec* pick_isa(const std::string& wanted, std::string* why) {
  std::string w = wanted;
  if (w.empty())
    if (const char* e = std::getenv("DERIVCHECK_JIT_ISA")) w = e;
  for (const IsaSpec& s : isa_table()) {
    if (!w.empty() && s.name != w) continue;
    if (host_has(s.name)) return &s;
    if (!w.empty()) {
      if (why) *why = "the host CPU lacks " + w;
      return nullptr;
    }
  }
  if (why) *why = w.empty() ? "no instruction set" : "unknown instruction set '" + w + "'";
  return nullptr;
}
}  // namespace jitdetail
#else
struct JitKernel::Session {};
JitKernel::~JitKernel() = default;
#endif

bool jit_enabled() {
#if DERIVCHECK_HAVE_JIT
  const char* e = std::getenv("DERIVCHECK_JIT");
  if (!e) return true;
  const std::string v = e;
  return !(v == "0" || v == "off" || v == "OFF" || v == "no" || v == "tape");
#else
  return false;
#endif
}

std::string jit_host_isa() {
#if DERIVCHECK_HAVE_JIT
  const jitdetail::IsaSpec* s = jitdetail::pick_isa("", nullptr);
  return s ? s->name : "";
#else
  return "";
#endif
}

std::shared_ptr<const JitKernel> JitKernel::compile(const Program& p, std::string* why,
                                                    const std::string& isa) {
#if DERIVCHECK_HAVE_JIT
  if (!jit_enabled()) {
    if (why) *why = "switched off by DERIVCHECK_JIT";
    return nullptr;
  }
  const jitdetail::IsaSpec* s = jitdetail::pick_isa(isa, why);
  if (!s) return nullptr;
  return JitBuilder::build(p, *s, why);
#else
  if (why) *why = "derivcheck was built without the JIT (DERIVCHECK_JIT=OFF)";
  return nullptr;
#endif
}

void JitKernel::operator()(const double* const* columns, double* out, std::size_t n) const {
  const std::size_t w = static_cast<std::size_t>(width_), main = n - n % w, rem = n - main;
  if (main) fn_(columns, out, main);
  if (!rem) return;
  // The last n mod W points: copied into W-wide buffers, padded by repeating the last point
  // (a point the caller gave, so the padding lanes raise nothing the real ones do not).
  constexpr std::size_t kMaxW = 8, kStackInputs = 16;
  double stack_buf[kStackInputs * kMaxW];
  const double* stack_cols[kStackInputs];
  std::vector<double> heap_buf;
  std::vector<const double*> heap_cols;
  double* buf = stack_buf;
  const double** cols = stack_cols;
  if (n_inputs_ > kStackInputs) {
    heap_buf.resize(n_inputs_ * kMaxW);
    heap_cols.resize(n_inputs_);
    buf = heap_buf.data();
    cols = heap_cols.data();
  }
  for (std::size_t j = 0; j < n_inputs_; ++j) {
    double* b = buf + j * kMaxW;
    for (std::size_t l = 0; l < w; ++l) b[l] = columns[j][main + std::min(l, rem - 1)];
    cols[j] = b;
  }
  double o[kMaxW];
  fn_(cols, o, w);
  std::memcpy(out + main, o, rem * sizeof(double));
}

}  // namespace dc::num
