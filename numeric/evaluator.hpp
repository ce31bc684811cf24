// The fast evaluator: a GiNaC expression compiled into a register program ("tape") that is
// interpreted for double or long double. No C compiler is needed at run time, so it works on
// any formula a user's derivation file defines.
//
// Compilation (numeric/evaluator.cpp):
//   - common subexpressions are shared: structurally equal subexpressions and equal
//     instructions map to one register;
//   - integer powers become multiplications (x^5 = (x^2)^2 x), negative powers divisions,
//     half-integer powers square roots;
//   - operands of sums and products are ordered by a canonical key of our own (never GiNaC's
//     hash order, which changes between processes), so results are bit-for-bit reproducible;
//   - in a product with a denominator, a numerator factor sharing symbols with the denominator
//     is divided first (m1/(m1+m2) * m2, not (m1*m2)/(m1+m2)): the same number of roundings,
//     but no overflow of m1*m2 for masses near 1e160;
//   - constant subexpressions (pi, sqrt(2), 1/3) are folded to correctly rounded constants;
//   - primitive operations that the expression language does not have are recognised:
//       log(1 + x)         -> log1p(x)   (accurate when |x| << 1)
//       exp(x) - 1         -> expm1(x)
//       sqrt(x^2 + y^2)    -> hypot(x, y) (no overflow of the squares)
//   - temporaries are given registers by liveness, so the working set stays small.
//
// Evaluation: Evaluator<T>::operator() walks the tape for one point; eval_batch_tape() runs
// each instruction over a block of points before the next instruction, so the inner loops are
// plain array loops that the compiler vectorises. Evaluator<double>::eval_batch() is the fast
// path: on its first call it JIT-compiles the program to SIMD machine code (numeric/jit.hpp,
// LLVM + SLEEF) and uses that from then on; where the JIT is unavailable, switched off
// (DERIVCHECK_JIT=0) or fails, it is eval_batch_tape(). The JIT's + - * / sqrt abs are bit for
// bit the tape's; its transcendental functions are SLEEF's (at most 1 ulp, docs/numeric.md).
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <ginac/ginac.h>

#include "numeric/jit.hpp"

namespace dc::num {

enum class Op : std::uint8_t {
  Add, Sub, Mul, Div, Neg, Sqrt, Exp, Expm1, Log, Log1p, Sin, Cos, Tan, Asin, Acos, Atan, Abs,
  Pow, Hypot
};
const char* op_name(Op op);
int op_arity(Op op);

struct Instr {
  Op op;
  std::uint32_t dst, a, b;  // b unused for unary operations
};

// Registers: [0, n_inputs) the inputs in the order given to compile(); then the constants;
// then temporaries. `result` may be any register (an input for `f = x`).
struct Program {
  std::vector<std::string> inputs;
  std::vector<double> const_double;
  std::vector<long double> const_long_double;
  std::vector<double> const_double_lo;  // c - const_double[i] rounded: double-double constants
  std::vector<std::string> const_text;  // exact value as text (for listings)
  std::vector<Instr> code;
  std::uint32_t result = 0;
  std::uint32_t n_registers = 0;

  std::size_t n_inputs() const { return inputs.size(); }
  std::size_t first_temp() const { return inputs.size() + const_double.size(); }
  std::size_t count(Op op) const;
  // One instruction per line: "r7 = mul r0 r5"; inputs and constants listed first.
  std::string listing() const;
};

struct CompileOptions {
  bool fuse_log1p = true;
  bool fuse_expm1 = true;
  bool fuse_hypot = true;
  bool ratio_first = true;  // divide a numerator factor sharing symbols with the denominator first
};

// Compile `e` with `inputs` as the input registers. Throws std::invalid_argument naming the
// problem for a free symbol not among `inputs`, an unsupported function (abstract functions,
// derivatives), a non-real constant, or an exponent larger than 1e6 in magnitude.
Program compile(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& inputs,
                const CompileOptions& opt = {});

namespace detail {
template <class T>
inline T apply(Op op, T a, T b) {
  using std::abs, std::acos, std::asin, std::atan, std::cos, std::exp, std::expm1, std::hypot,
      std::log, std::log1p, std::pow, std::sin, std::sqrt, std::tan;
  switch (op) {
    case Op::Add: return a + b;
    case Op::Sub: return a - b;
    case Op::Mul: return a * b;
    case Op::Div: return a / b;
    case Op::Neg: return -a;
    case Op::Sqrt: return sqrt(a);
    case Op::Exp: return exp(a);
    case Op::Expm1: return expm1(a);
    case Op::Log: return log(a);
    case Op::Log1p: return log1p(a);
    case Op::Sin: return sin(a);
    case Op::Cos: return cos(a);
    case Op::Tan: return tan(a);
    case Op::Asin: return asin(a);
    case Op::Acos: return acos(a);
    case Op::Atan: return atan(a);
    case Op::Abs: return abs(a);
    case Op::Pow: return pow(a, b);
    case Op::Hypot: return hypot(a, b);
  }
  return a;
}

// One instruction over n points; d never aliases a or b (the register allocator guarantees it).
template <class T>
inline void apply_block(Op op, T* __restrict d, const T* __restrict a, const T* __restrict b,
                        std::size_t n) {
  switch (op) {
    case Op::Add: for (std::size_t i = 0; i < n; ++i) d[i] = a[i] + b[i]; return;
    case Op::Sub: for (std::size_t i = 0; i < n; ++i) d[i] = a[i] - b[i]; return;
    case Op::Mul: for (std::size_t i = 0; i < n; ++i) d[i] = a[i] * b[i]; return;
    case Op::Div: for (std::size_t i = 0; i < n; ++i) d[i] = a[i] / b[i]; return;
    case Op::Neg: for (std::size_t i = 0; i < n; ++i) d[i] = -a[i]; return;
    case Op::Sqrt: for (std::size_t i = 0; i < n; ++i) d[i] = std::sqrt(a[i]); return;
    default:
      for (std::size_t i = 0; i < n; ++i) d[i] = apply<T>(op, a[i], b[i]);
      return;
  }
}
}  // namespace detail

// Evaluates a Program in scalar type T (double or long double). Holds scratch registers, so
// one Evaluator must not be used from two threads at once (copy it instead).
template <class T>
class Evaluator {
 public:
  static constexpr std::size_t kBlock = 256;  // points per block in eval_batch

  Evaluator() = default;
  explicit Evaluator(Program p) : prog_(std::move(p)) {
    regs_.assign(prog_.n_registers, T(0));
    for (std::size_t c = 0; c < prog_.const_double.size(); ++c)
      regs_[prog_.n_inputs() + c] = constant(c);
  }

  const Program& program() const { return prog_; }
  std::size_t n_inputs() const { return prog_.n_inputs(); }

  // One point: args[i] is the value of input i.
  T operator()(const T* args) const {
    T* r = regs_.data();
    const std::size_t n = prog_.n_inputs();
    for (std::size_t i = 0; i < n; ++i) r[i] = args[i];
    for (const Instr& in : prog_.code) r[in.dst] = detail::apply<T>(in.op, r[in.a], r[in.b]);
    return r[prog_.result];
  }
  T operator()(const std::vector<T>& args) const {
    check_arity(args.size());
    return (*this)(args.data());
  }

  // Many points: columns[i] points at n values of input i; writes n results to out. For
  // double: the JIT when available (compiled on the first call), else the tape.
  void eval_batch(const T* const* columns, T* out, std::size_t n) const {
    if constexpr (std::is_same_v<T, double>) {
      if (!jit_tried_) {
        jit_ = JitKernel::compile(prog_);
        jit_tried_ = true;
      }
      if (jit_) {
        (*jit_)(columns, out, n);
        return;
      }
    }
    eval_batch_tape(columns, out, n);
  }

  // The JIT kernel eval_batch uses (nullptr before the first call, or on the tape).
  const JitKernel* jit() const { return jit_.get(); }

  // Many points through the tape interpreter, whatever the JIT.
  void eval_batch_tape(const T* const* columns, T* out, std::size_t n) const {
    const std::size_t nreg = prog_.n_registers, nin = prog_.n_inputs(),
                      first_temp = prog_.first_temp();
    if (block_.size() != nreg * kBlock) {
      block_.assign(nreg * kBlock, T(0));
      for (std::size_t c = nin; c < first_temp; ++c)
        for (std::size_t i = 0; i < kBlock; ++i) block_[c * kBlock + i] = regs_[c];
    }
    std::vector<const T*> src(nreg);
    for (std::size_t c = nin; c < nreg; ++c) src[c] = block_.data() + c * kBlock;
    for (std::size_t start = 0; start < n; start += kBlock) {
      const std::size_t m = std::min(kBlock, n - start);
      for (std::size_t i = 0; i < nin; ++i) src[i] = columns[i] + start;
      for (const Instr& in : prog_.code)
        detail::apply_block<T>(in.op, block_.data() + in.dst * kBlock, src[in.a], src[in.b], m);
      const T* res = src[prog_.result];
      for (std::size_t i = 0; i < m; ++i) out[start + i] = res[i];
    }
  }

  // Eigen form: one column per input (rows = points); out is resized to the number of points.
  void eval_batch(const Eigen::Array<T, Eigen::Dynamic, Eigen::Dynamic>& in,
                  Eigen::Array<T, Eigen::Dynamic, 1>& out) const {
    check_arity(static_cast<std::size_t>(in.cols()));
    std::vector<const T*> cols(static_cast<std::size_t>(in.cols()));
    for (Eigen::Index j = 0; j < in.cols(); ++j) cols[static_cast<std::size_t>(j)] = in.col(j).data();
    out.resize(in.rows());
    eval_batch(cols.data(), out.data(), static_cast<std::size_t>(in.rows()));
  }

 private:
  T constant(std::size_t c) const {
    if constexpr (std::is_same_v<T, double>) return prog_.const_double[c];
    else return static_cast<T>(prog_.const_long_double[c]);
  }
  void check_arity(std::size_t got) const {
    if (got != prog_.n_inputs())
      throw std::invalid_argument("evaluator: expected " + std::to_string(prog_.n_inputs()) +
                                  " input values, got " + std::to_string(got));
  }

  Program prog_;
  mutable std::vector<T> regs_;
  mutable std::vector<T> block_;
  mutable std::shared_ptr<const JitKernel> jit_;  // shared by copies; calling it is thread-safe
  mutable bool jit_tried_ = false;
};

}  // namespace dc::num
