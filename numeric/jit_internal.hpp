// Shared by numeric/jit.cpp and numeric/jit_llvm.cpp; not a public header.
#pragma once
#include <array>
#include <memory>
#include <string>

#include "numeric/evaluator.hpp"
#include "numeric/jit.hpp"

namespace dc::num {
namespace jitdetail {

struct SleefFn {
  const char* op;      // "exp", ... (op_name of the Op)
  const char* symbol;  // "Sleef_expd8_u10avx512f"
  void* address;
};

// One instruction set: its vector width and the SLEEF function for each transcendental Op.
struct IsaSpec {
  std::string name;
  int width;
  std::array<SleefFn, 12> fns;  // exp expm1 log log1p sin cos tan asin acos atan pow hypot
};

// The widest instruction set the host has, or `wanted` if the host has it (nullptr and a
// reason otherwise).
const IsaSpec* pick_isa(const std::string& wanted, std::string* why);

}  // namespace jitdetail

struct JitBuilder {
  static std::shared_ptr<const JitKernel> build(const Program& p, const jitdetail::IsaSpec& isa,
                                                std::string* why);
};

}  // namespace dc::num
