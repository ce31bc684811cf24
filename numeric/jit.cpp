// The JIT's host side (numeric/jit.hpp): choosing the instruction set, the switch in the
// environment, loading the JIT module (numeric/jit_internal.hpp) and the padded tail. Code
// generation lives in the module: numeric/jit_module/jit_llvm.cpp.
#include "numeric/jit.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <vector>

#if DERIVCHECK_HAVE_JIT
#include <dlfcn.h>
#include <unistd.h>
#endif

#include "numeric/jit_internal.hpp"

namespace dc::num {

struct JitKernel::Session {
  void* handle = nullptr;
  DerivcheckJitFreeFn free = nullptr;
  ~Session() {
    if (handle && free) free(handle);
  }
};

JitKernel::~JitKernel() = default;

#if DERIVCHECK_HAVE_JIT
namespace {

struct IsaName {
  const char* name;
  int width;
};
constexpr IsaName kIsas[] = {{"avx512f", 8}, {"avx2", 4}, {"avx", 4}, {"sse2", 2}};

bool host_has(const std::string& isa) {
  __builtin_cpu_init();
  if (isa == "avx512f") return __builtin_cpu_supports("avx512f");
  if (isa == "avx2") return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  if (isa == "avx") return __builtin_cpu_supports("avx");
  return isa == "sse2";  // x86-64 baseline
}

// The widest set the host has, or `wanted` (or DERIVCHECK_JIT_ISA) if the host has it.
const IsaName* pick_isa(const std::string& wanted, std::string* why) {
  std::string w = wanted;
  if (w.empty())
    if (const char* e = std::getenv("DERIVCHECK_JIT_ISA")) w = e;
  for (const IsaName& s : kIsas) {
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

// libderivcheck_jit.so, loaded once: $DERIVCHECK_JIT_MODULE, else next to an installed
// executable (PREFIX/bin/x -> PREFIX/LIBDIR/), else the build tree's, else the install prefix's.
struct Module {
  DerivcheckJitBuildFn build = nullptr;
  DerivcheckJitFreeFn free = nullptr;
  std::string why;
};

const Module& module() {
  static const Module m = [] {
    Module r;
    std::vector<std::string> paths;
    if (const char* e = std::getenv("DERIVCHECK_JIT_MODULE")) paths.push_back(e);
    char exe[4096];
    const ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (len > 0) {
      std::string dir(exe, static_cast<std::size_t>(len));
      dir = dir.substr(0, dir.find_last_of('/'));
      paths.push_back(dir + "/../" DERIVCHECK_JIT_MODULE_LIBDIR "/" DERIVCHECK_JIT_MODULE_NAME);
    }
    paths.push_back(DERIVCHECK_JIT_MODULE_BUILD);
    paths.push_back(DERIVCHECK_JIT_MODULE_INSTALL);
    for (const auto& p : paths) {
      // never unloaded: LLVM keeps global state that must outlive every kernel
      void* h = dlopen(p.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!h) {
        if (r.why.empty()) r.why = dlerror();
        continue;
      }
      r.build = reinterpret_cast<DerivcheckJitBuildFn>(dlsym(h, DERIVCHECK_JIT_BUILD_SYMBOL));
      r.free = reinterpret_cast<DerivcheckJitFreeFn>(dlsym(h, DERIVCHECK_JIT_FREE_SYMBOL));
      if (r.build && r.free) return r;
      r.why = p + " lacks " DERIVCHECK_JIT_BUILD_SYMBOL;
    }
    r.build = nullptr;
    r.why = "cannot load the JIT module " DERIVCHECK_JIT_MODULE_NAME ": " + r.why;
    return r;
  }();
  return m;
}

}  // namespace
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
  const IsaName* s = pick_isa("", nullptr);
  return s ? s->name : "";
#else
  return "";
#endif
}

std::shared_ptr<const JitKernel> JitKernel::compile(const Program& p, std::string* why, const std::string& isa) {
#if DERIVCHECK_HAVE_JIT
  if (!jit_enabled()) {
    if (why) *why = "switched off by DERIVCHECK_JIT";
    return nullptr;
  }
  const IsaName* s = pick_isa(isa, why);
  if (!s) return nullptr;
  const Module& m = module();
  if (!m.build) {
    if (why) *why = m.why;
    return nullptr;
  }
  DerivcheckJitResult res;
  if (m.build(&p, s->name, s->width, &res) != 0) {
    if (why) *why = std::string("JIT: ") + res.why;
    return nullptr;
  }
  std::shared_ptr<JitKernel> k(new JitKernel());
  k->session_ = std::make_unique<Session>();
  k->session_->handle = res.session;
  k->session_->free = m.free;
  k->fn_ = reinterpret_cast<Fn>(res.fn);
  k->width_ = s->width;
  k->isa_ = s->name;
  k->n_inputs_ = p.n_inputs();
  k->compile_ms_ = res.compile_ms;
  return k;
#else
  (void)p, (void)isa;
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
