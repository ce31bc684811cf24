// sin and cos emitted inline into a JIT kernel (numeric/jit_module/jit_llvm.cpp) for arguments
// up to 2^19 in magnitude, in place of a call to SLEEF; needs fused multiply-add. Lanes beyond
// (and inf, NaN) are marked for the caller, which takes SLEEF's value there.
#pragma once

#include <llvm/IR/IRBuilder.h>

namespace dc::num::jitir {

struct InlineResult {
  llvm::Value* value;    // the function where `outside` is false
  llvm::Value* outside;  // <W x i1>: lanes the inline code does not cover
};

// sin(x) (cos == false) or cos(x) for a vector of doubles, error below 0.9 ulp where |x| <= 2^19
// (derivation in the .cpp).
InlineResult emit_sincos(llvm::IRBuilder<>& b, llvm::Value* x, bool cos);

}  // namespace dc::num::jitir
