// An in-process JIT for compiled programs (numeric/evaluator.hpp): the tape becomes one machine
// function that walks the points W at a time in SIMD registers (docs/numeric.md, "The JIT").
//
//   - LLVM 14 ORC (LLJIT), target machine = the host CPU with its features;
//   - W = 8 with AVX-512F, 4 with AVX2+FMA or AVX, 2 otherwise (SSE2), chosen at run time;
//   - + - * / and negation are IEEE operations on <W x double> in the tape's order, no
//     contraction into FMA and no fast-math: bit for bit what the tape computes;
//   - sqrt and abs are LLVM intrinsics (correctly rounded / exact);
//   - exp expm1 log log1p sin cos tan asin acos atan pow are SLEEF 3.5 vector functions of the
//     1.0-ulp family (u10), hypot the 0.5-ulp one (u05) -- see kSleefUlps in jit.cpp;
//   - a tail of n mod W points is evaluated on a padded copy.
//
// LLVM and SLEEF live in a separate module, libderivcheck_jit.so (numeric/jit_module/), that
// the first JitKernel::compile loads with dlopen: programs that never compile a kernel do not
// pay for mapping libLLVM at start-up (nor in every fork).
//
// When derivcheck was built without LLVM/SLEEF (CMake option DERIVCHECK_JIT), on a non-x86-64
// CPU, when the environment variable DERIVCHECK_JIT is "0"/"off", when the module cannot be
// loaded ($DERIVCHECK_JIT_MODULE names it explicitly), or when compilation fails,
// JitKernel::compile returns nullptr (with the reason) and callers use the tape interpreter.
#pragma once
#include <cstddef>
#include <memory>
#include <string>

namespace dc::num {

struct Program;

class JitKernel {
 public:
  // nullptr (and the reason in *why) when the JIT is unavailable, disabled or fails. `isa`
  // forces an instruction set at most as wide as the host's: "avx512f", "avx2", "avx", "sse2"
  // (empty: the widest the host has, or the environment variable DERIVCHECK_JIT_ISA).
  static std::shared_ptr<const JitKernel> compile(const Program& p, std::string* why = nullptr,
                                                  const std::string& isa = "");

  // columns[i] points at n values of input i; writes n results to out. Thread-safe: the
  // function keeps no state, so many threads may call one kernel at once.
  void operator()(const double* const* columns, double* out, std::size_t n) const;

  int width() const { return width_; }               // W, doubles per vector
  const std::string& isa() const { return isa_; }    // "avx512f", "avx2", "avx", "sse2"
  double compile_ms() const { return compile_ms_; }  // IR generation + LLVM codegen + linking
  std::size_t n_inputs() const { return n_inputs_; }

  ~JitKernel();
  JitKernel(const JitKernel&) = delete;
  JitKernel& operator=(const JitKernel&) = delete;

  struct Session;  // the module's LLJIT instance owning the code (jit.cpp)

 private:
  JitKernel() = default;
  using Fn = void (*)(const double* const*, double*, std::size_t);
  Fn fn_ = nullptr;
  int width_ = 1;
  std::string isa_;
  double compile_ms_ = 0;
  std::size_t n_inputs_ = 0;
  std::unique_ptr<Session> session_;
};

// True when this build has the JIT and the environment does not switch it off.
bool jit_enabled();
// The instruction set JitKernel::compile would pick here ("" without the JIT).
std::string jit_host_isa();

}  // namespace dc::num
