// The boundary between numeric/jit.cpp (in derivcheck_numeric) and the JIT module
// libderivcheck_jit.so (numeric/jit_module/, linked with LLVM and SLEEF), which jit.cpp loads
// with dlopen on the first compilation: a process that never evaluates a batch never maps
// libLLVM (about 6 ms of dynamic loading and 50 MB of mappings, also paid again by every fork).
// Not a public header.
#pragma once
#include <cstddef>

#include "numeric/evaluator.hpp"

extern "C" {

struct DerivcheckJitResult {
  void* fn = nullptr;       // void(const double* const*, double*, size_t), n a multiple of W
  void* session = nullptr;  // owns the code; released by derivcheck_jit_free
  double compile_ms = 0;
  char why[512] = {};       // the reason when it fails
};

// Compiles `p` for instruction set `isa` ("avx512f", "avx2", "avx", "sse2"; the caller has
// checked that the host has it). Returns 0 on success.
typedef int (*DerivcheckJitBuildFn)(const dc::num::Program* p, const char* isa, int width, DerivcheckJitResult* out);
typedef void (*DerivcheckJitFreeFn)(void* session);

}  // extern "C"

#define DERIVCHECK_JIT_BUILD_SYMBOL "derivcheck_jit_build"
#define DERIVCHECK_JIT_FREE_SYMBOL "derivcheck_jit_free"
