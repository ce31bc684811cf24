// asin and acos emitted inline into a JIT kernel (numeric/jit_module/jit_llvm.cpp), in place of
// a call to SLEEF: a 0.9-ulp bound (SLEEF's is 1 ulp), no use of the divider, which the
// formula's own divisions need, and instructions that interleave with the rest of the formula. Needs fused multiply-add (the sqrt residual is
// computed exactly with it); without FMA the kernel keeps calling SLEEF.
#pragma once

#include <llvm/IR/IRBuilder.h>

namespace dc::num::jitir {

// asin(x) (acos == false) or acos(x) for a vector of doubles, error below 0.9 ulp (derivation
// in the .cpp); NaN for |x| > 1 and for NaN.
llvm::Value* emit_arcsine(llvm::IRBuilder<>& b, llvm::Value* x, bool acos);

}  // namespace dc::num::jitir
