// The JIT module libderivcheck_jit.so (numeric/jit.hpp, numeric/jit_internal.hpp): a Program
// as LLVM IR on <W x double>, compiled by LLVM 14 ORC (LLJIT) for the host CPU, transcendental
// functions as calls to SLEEF (asin and acos inline where the instruction set has FMA:
// jit_arcsine.hpp). One LLJIT per kernel: the kernel owns its code and frees it with
// itself, and kernels compiled on different threads share nothing.
#include <array>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <limits>
#include <mutex>
#include <string>

#include <llvm/ExecutionEngine/Orc/Core.h>
#include <llvm/ExecutionEngine/Orc/JITTargetMachineBuilder.h>
#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/ExecutionEngine/Orc/ThreadSafeModule.h>
#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/Intrinsics.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>
#include <llvm/IR/Verifier.h>
#include <llvm/Support/TargetSelect.h>
#include <llvm/Support/raw_ostream.h>

#include "numeric/jit_internal.hpp"
#include "numeric/jit_module/jit_arcsine.hpp"

// SLEEF 3.5.1 (libsleef3), one symbol per function and instruction set; the names are checked
// against `nm -D libsleef.so`. u10: max error 1.0 ulp; u05: 0.5001 ulp (SLEEF's documentation;
// tests/numeric/test_jit.cpp measures them against CLN on wide ranges). Declared here rather
// than through sleef.h, which declares each set only when compiling for it.
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
  {"Sleef_" #f #V "_" #U #ISA, reinterpret_cast<void*>(&Sleef_##f##V##_##U##ISA)},

namespace dc::num {
namespace {

struct SleefFn {
  const char* symbol;  // "Sleef_expd8_u10avx512f"
  void* address;
};

// One instruction set: its vector width and the SLEEF function for each transcendental Op.
struct IsaSpec {
  const char* name;
  int width;
  bool fma;  // fused multiply-add in hardware: asin and acos inline (jit_arcsine.hpp), not SLEEF
  std::array<SleefFn, 12> fns;  // exp expm1 log log1p sin cos tan asin acos atan pow hypot
};

// numeric/jit.cpp picks avx2 only where the CPU also has FMA
const IsaSpec kIsas[] = {
    {"avx512f", 8, true, {{DC_SLEEF_FNS(DC_SLEEF_ENTRY, d8, avx512f)}}},
    {"avx2", 4, true, {{DC_SLEEF_FNS(DC_SLEEF_ENTRY, d4, avx2)}}},
    {"avx", 4, false, {{DC_SLEEF_FNS(DC_SLEEF_ENTRY, d4, avx)}}},
    {"sse2", 2, false, {{DC_SLEEF_FNS(DC_SLEEF_ENTRY, d2, sse2)}}},
};

struct Session {
  std::unique_ptr<llvm::orc::LLJIT> jit;
};

int arity(Op op) {
  switch (op) {
    case Op::Add: case Op::Sub: case Op::Mul: case Op::Div: case Op::Pow: case Op::Hypot: return 2;
    default: return 1;
  }
}

std::string message(llvm::Error e) {
  std::string s;
  llvm::raw_string_ostream os(s);
  os << e;
  return os.str();
}

// The SLEEF function of a transcendental op (index into IsaSpec::fns), -1 for the others.
int sleef_index(Op op) {
  switch (op) {
    case Op::Exp: return 0;
    case Op::Expm1: return 1;
    case Op::Log: return 2;
    case Op::Log1p: return 3;
    case Op::Sin: return 4;
    case Op::Cos: return 5;
    case Op::Tan: return 6;
    case Op::Asin: return 7;
    case Op::Acos: return 8;
    case Op::Atan: return 9;
    case Op::Pow: return 10;
    case Op::Hypot: return 11;
    default: return -1;
  }
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The divisor of a division by a constant, else NaN.
double constant_divisor(const Program& p, const Instr& in) {
  if (in.op != Op::Div || in.b < p.n_inputs() || in.b >= p.first_temp()) return kNaN;
  return p.const_double[in.b - p.n_inputs()];
}

// For a division by a constant +-2^k: 2^-k (exact), else 0.
double power_of_two_reciprocal(const Program& p, const Instr& in) {
  const double c = constant_divisor(p, in);
  int e = 0;
  if (!std::isfinite(c) || c == 0 || std::fabs(std::frexp(c, &e)) != 0.5) return 0;
  const double r = 1.0 / c;   // 2^(1 - e): exact when it is a double (normal or subnormal)
  return r != 0 && std::isfinite(r) && r * c == 1.0 ? r : 0;
}

// For a division by a constant c whose reciprocal y = RN(1/c) has relative error at most 2^-54:
// y, else 0. Then for |a| in [2^-800, 2^800], q = RN(a y) is within 1 ulp of a/c, the remainder
// a - c q is exact in one FMA, and RN(q + (a - c q) y) = RN(a/c) (Markstein's theorem: y within
// half an ulp of 1/c, q within one ulp of a/c, no underflow or overflow on the way): the tape's
// division bit for bit, with two FMAs and a multiplication instead of the divider.
// |c| is kept to [2^-60, 2^60] so that the bounds on |a| leave every intermediate normal.
double markstein_reciprocal(const Program& p, const Instr& in) {
  const double c = constant_divisor(p, in);
  if (!std::isfinite(c) || std::fabs(c) < 0x1p-60 || std::fabs(c) > 0x1p60) return 0;
  const double y = 1.0 / c;
  // 1 - c y is exact in one FMA (|1 - c y| <= 2^-52 and it is a multiple of ulp(c) ulp(y))
  return std::fabs(std::fma(-c, y, 1.0)) <= 0x1p-54 ? y : 0;
}

// void dc_kernel(const double* const* columns, double* out, i64 n), n a multiple of W:
//   for (i = 0; i < n; i += W) out[i..i+W) = program(columns[0][i..i+W), ...)
// The main loop takes kUnroll vectors per iteration and emits each tape instruction for all of
// them before the next instruction: the vectors' dependency chains (a division's latency, a
// SLEEF call) are independent, so the CPU overlaps them instead of waiting on one chain per
// iteration. A loop of single vectors takes the rest. Every lane computes exactly what the
// tape computes, in the same order, so the results do not depend on the unrolling.
constexpr unsigned kUnroll = 4;

std::unique_ptr<llvm::Module> emit(const Program& p, const IsaSpec& isa,
                                   llvm::LLVMContext& ctx) {
  using namespace llvm;
  auto mod = std::make_unique<Module>("derivcheck_jit", ctx);
  IRBuilder<> b(ctx);
  Type* dbl = b.getDoubleTy();
  Type* i64 = b.getInt64Ty();
  const auto width = static_cast<unsigned>(isa.width);
  auto* vec = FixedVectorType::get(dbl, width);
  PointerType* dptr = PointerType::getUnqual(dbl);
  PointerType* dptrptr = PointerType::getUnqual(dptr);
  auto* fty = FunctionType::get(b.getVoidTy(), {dptrptr, dptr, i64}, false);
  Function* f = Function::Create(fty, Function::ExternalLinkage, "dc_kernel", mod.get());
  f->addFnAttr(Attribute::NoUnwind);
  Argument* cols = f->getArg(0);
  Argument* out = f->getArg(1);
  Argument* n = f->getArg(2);
  cols->addAttr(Attribute::NoAlias);
  out->addAttr(Attribute::NoAlias);

  BasicBlock* entry = BasicBlock::Create(ctx, "entry", f);
  BasicBlock* head = BasicBlock::Create(ctx, "head", f);
  BasicBlock* body = BasicBlock::Create(ctx, "body", f);
  BasicBlock* tail_head = BasicBlock::Create(ctx, "tail_head", f);
  BasicBlock* tail = BasicBlock::Create(ctx, "tail", f);
  BasicBlock* exit = BasicBlock::Create(ctx, "exit", f);

  b.SetInsertPoint(entry);
  const std::size_t nin = p.n_inputs();
  std::vector<Value*> colp(nin);
  for (std::size_t j = 0; j < nin; ++j)
    colp[j] = b.CreateAlignedLoad(dptr, b.CreateConstInBoundsGEP1_64(dptr, cols, j), Align(8), "col");
  b.CreateBr(head);

  auto splat = [&](double x) { return ConstantVector::getSplat(ElementCount::getFixed(width), ConstantFP::get(dbl, x)); };
  auto sleef = [&](int k, int arity) -> FunctionCallee {
    std::vector<Type*> args(static_cast<std::size_t>(arity), vec);
    FunctionCallee fc = mod->getOrInsertFunction(isa.fns[static_cast<std::size_t>(k)].symbol,
                                                 FunctionType::get(vec, args, false));
    auto* decl = cast<Function>(fc.getCallee());
    decl->addFnAttr(Attribute::NoUnwind);
    decl->setDoesNotAccessMemory();  // pure: no errno, no state
    return fc;
  };
  // Lanes `bad` take the value of `fallback()`, which is emitted in a block of its own that
  // runs only when some lane of the vector needs it (ordinary data never does).
  auto patch = [&](Value* bad, Value* r, auto&& fallback) -> Value* {
    BasicBlock* from = b.GetInsertBlock();
    BasicBlock* fix = BasicBlock::Create(ctx, "fix", f, tail_head);
    BasicBlock* cont = BasicBlock::Create(ctx, "cont", f, tail_head);
    b.CreateCondBr(b.CreateOrReduce(bad), fix, cont);
    b.SetInsertPoint(fix);
    Value* l = b.CreateSelect(bad, fallback(), r);
    BasicBlock* fixed = b.GetInsertBlock();
    b.CreateBr(cont);
    b.SetInsertPoint(cont);
    PHINode* phi = b.CreatePHI(vec, 2);
    phi->addIncoming(r, from);
    phi->addIncoming(l, fixed);
    return phi;
  };
  // One tape instruction on one vector.
  auto apply = [&](const Instr& in, Value* a, Value* c) -> Value* {
    switch (in.op) {
      case Op::Add: return b.CreateFAdd(a, c);
      case Op::Sub: return b.CreateFSub(a, c);
      case Op::Mul: return b.CreateFMul(a, c);
      case Op::Div: return b.CreateFDiv(a, c);
      case Op::Neg: return b.CreateFNeg(a);
      case Op::Sqrt: return b.CreateUnaryIntrinsic(Intrinsic::sqrt, a);
      case Op::Abs: return b.CreateUnaryIntrinsic(Intrinsic::fabs, a);
      default: break;
    }
    const int k = sleef_index(in.op);
    auto call = [&](int fn) { return b.CreateCall(sleef(fn, 1), {a}); };
    if (isa.fma && (in.op == Op::Asin || in.op == Op::Acos)) return jitir::emit_arcsine(b, a, in.op == Op::Acos);
    Value* r = arity(in.op) == 2 ? b.CreateCall(sleef(k, 2), {a, c}) : call(k);
    // SLEEF 3.5's log1p overflows to inf for x above about 1e307; there 1 + x == x and log(x)
    // is log1p(x) to within 1e-300 relative. Lanes above 1e300 take log(x).
    if (in.op == Op::Log1p) r = patch(b.CreateFCmpOGT(a, splat(1e300)), r, [&] { return call(sleef_index(Op::Log)); });
    return r;
  };
  // The program on `u` vectors at points i, i + W, ...: instruction by instruction.
  auto program = [&](Value* i, unsigned u) {
    std::vector<std::vector<Value*>> reg(u, std::vector<Value*>(p.n_registers, nullptr));
    std::vector<Value*> at(u);
    for (unsigned v = 0; v < u; ++v) at[v] = v ? b.CreateAdd(i, b.getInt64(std::uint64_t{v} * width)) : i;
    for (unsigned v = 0; v < u; ++v) {
      for (std::size_t j = 0; j < nin; ++j)
        reg[v][j] = b.CreateAlignedLoad(vec, b.CreateBitCast(b.CreateInBoundsGEP(dbl, colp[j], at[v]), PointerType::getUnqual(vec)),
                                        Align(8), "x");
      for (std::size_t c = 0; c < p.const_double.size(); ++c) reg[v][nin + c] = splat(p.const_double[c]);
    }
    for (const Instr& in : p.code) {
      // x / 2^k is x * 2^-k exactly (both are x / 2^k correctly rounded; 2^-k is a double for
      // every double 2^k): a multiplication instead of a division's latency
      if (const double r = power_of_two_reciprocal(p, in); r != 0) {
        for (unsigned v = 0; v < u; ++v) reg[v][in.dst] = b.CreateFMul(reg[v][in.a], splat(r));
        continue;
      }
      if (const double y = isa.fma ? markstein_reciprocal(p, in) : 0; y != 0) {
        const double c = constant_divisor(p, in);
        for (unsigned v = 0; v < u; ++v) {
          Value* a = reg[v][in.a];
          Value* q = b.CreateFMul(a, splat(y));
          Value* r = b.CreateIntrinsic(Intrinsic::fma, {vec}, {b.CreateFNeg(q), splat(c), a});
          Value* q1 = b.CreateIntrinsic(Intrinsic::fma, {vec}, {r, splat(y), q});
          // a = +-0: q is the zero of the right sign; |a| outside [2^-800, 2^800], inf, NaN:
          // the division itself (a branch ordinary data does not take)
          Value* mag = b.CreateUnaryIntrinsic(Intrinsic::fabs, a);
          Value* zero = b.CreateFCmpOEQ(a, splat(0.0));
          Value* in_range = b.CreateAnd(b.CreateFCmpOGE(mag, splat(0x1p-800)), b.CreateFCmpOLE(mag, splat(0x1p800)));
          Value* res = b.CreateSelect(zero, q, q1);
          reg[v][in.dst] = patch(b.CreateNot(b.CreateOr(zero, in_range)), res, [&] { return b.CreateFDiv(a, splat(c)); });
        }
        continue;
      }
      for (unsigned v = 0; v < u; ++v)
        reg[v][in.dst] = apply(in, reg[v][in.a], arity(in.op) == 2 ? reg[v][in.b] : nullptr);
    }
    for (unsigned v = 0; v < u; ++v)
      b.CreateAlignedStore(reg[v][p.result], b.CreateBitCast(b.CreateInBoundsGEP(dbl, out, at[v]), PointerType::getUnqual(vec)),
                           Align(8));
  };

  // main loop: kUnroll vectors while i + kUnroll W <= n
  const std::uint64_t step = std::uint64_t{kUnroll} * width;
  b.SetInsertPoint(head);
  PHINode* i = b.CreatePHI(i64, 2, "i");
  i->addIncoming(b.getInt64(0), entry);
  b.CreateCondBr(b.CreateICmpULE(b.CreateAdd(i, b.getInt64(step)), n), body, tail_head);
  b.SetInsertPoint(body);
  program(i, kUnroll);
  i->addIncoming(b.CreateAdd(i, b.getInt64(step)), b.GetInsertBlock());
  b.CreateBr(head);

  // the rest, one vector at a time
  b.SetInsertPoint(tail_head);
  PHINode* t = b.CreatePHI(i64, 2, "t");
  t->addIncoming(i, head);
  b.CreateCondBr(b.CreateICmpULT(t, n), tail, exit);
  b.SetInsertPoint(tail);
  program(t, 1);
  t->addIncoming(b.CreateAdd(t, b.getInt64(width)), b.GetInsertBlock());
  b.CreateBr(tail_head);

  b.SetInsertPoint(exit);
  b.CreateRetVoid();
  return mod;
}

// Compiles `p`; the code and its LLJIT in a new Session.
std::string build(const Program& p, const IsaSpec& isa, DerivcheckJitResult* out) {
  const auto t0 = std::chrono::steady_clock::now();
  static std::once_flag init;
  std::call_once(init, [] {
    llvm::InitializeNativeTarget();
    llvm::InitializeNativeTargetAsmPrinter();
  });
  auto jtmb = llvm::orc::JITTargetMachineBuilder::detectHost();  // host CPU and its features
  if (!jtmb) return message(jtmb.takeError());
  jtmb->setCodeGenOptLevel(llvm::CodeGenOpt::Aggressive);
  auto jit = llvm::orc::LLJITBuilder().setJITTargetMachineBuilder(std::move(*jtmb)).create();
  if (!jit) return message(jit.takeError());
  // The SLEEF functions by address (linked into this module), nothing else from outside.
  llvm::orc::SymbolMap syms;
  for (const auto& s : isa.fns)
    syms[(*jit)->mangleAndIntern(s.symbol)] = llvm::JITEvaluatedSymbol(
        llvm::pointerToJITTargetAddress(s.address), llvm::JITSymbolFlags::Exported | llvm::JITSymbolFlags::Callable);
  if (auto e = (*jit)->getMainJITDylib().define(llvm::orc::absoluteSymbols(std::move(syms))))
    return message(std::move(e));

  auto ctx = std::make_unique<llvm::LLVMContext>();
  std::unique_ptr<llvm::Module> mod = emit(p, isa, *ctx);
  mod->setDataLayout((*jit)->getDataLayout());
  mod->setTargetTriple((*jit)->getTargetTriple().str());
  std::string verr;
  llvm::raw_string_ostream vos(verr);
  if (llvm::verifyModule(*mod, &vos)) return "invalid IR: " + vos.str();
  if (auto e = (*jit)->addIRModule(llvm::orc::ThreadSafeModule(std::move(mod), std::move(ctx))))
    return message(std::move(e));
  auto sym = (*jit)->lookup("dc_kernel");  // compiles
  if (!sym) return message(sym.takeError());
  auto session = std::make_unique<Session>();
  session->jit = std::move(*jit);
  out->fn = reinterpret_cast<void*>(static_cast<std::uintptr_t>(sym->getAddress()));
  out->session = session.release();
  out->compile_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return "";
}

}  // namespace
}  // namespace dc::num

extern "C" __attribute__((visibility("default"))) int derivcheck_jit_build(const dc::num::Program* p, const char* isa,
                                                                          int width, DerivcheckJitResult* out) {
  std::string why;
  try {
    const dc::num::IsaSpec* spec = nullptr;
    for (const auto& s : dc::num::kIsas)
      if (std::strcmp(s.name, isa) == 0 && s.width == width) spec = &s;
    why = spec ? dc::num::build(*p, *spec, out) : std::string("the JIT module has no instruction set ") + isa;
  } catch (const std::exception& e) {
    why = e.what();
  }
  if (why.empty()) return 0;
  std::snprintf(out->why, sizeof out->why, "%s", why.c_str());
  return 1;
}

extern "C" __attribute__((visibility("default"))) void derivcheck_jit_free(void* session) {
  delete static_cast<dc::num::Session*>(session);
}
