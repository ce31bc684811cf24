// The JIT module libderivcheck_jit.so (numeric/jit.hpp, numeric/jit_internal.hpp): a Program
// as LLVM IR on <W x double>, compiled by LLVM 14 ORC (LLJIT) for the host CPU, transcendental
// functions as calls to SLEEF. One LLJIT per kernel: the kernel owns its code and frees it with
// itself, and kernels compiled on different threads share nothing.
#include <array>
#include <chrono>
#include <cstdio>
#include <cstring>
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
  std::array<SleefFn, 12> fns;  // exp expm1 log log1p sin cos tan asin acos atan pow hypot
};

const IsaSpec kIsas[] = {
    {"avx512f", 8, {{DC_SLEEF_FNS(DC_SLEEF_ENTRY, d8, avx512f)}}},
    {"avx2", 4, {{DC_SLEEF_FNS(DC_SLEEF_ENTRY, d4, avx2)}}},
    {"avx", 4, {{DC_SLEEF_FNS(DC_SLEEF_ENTRY, d4, avx)}}},
    {"sse2", 2, {{DC_SLEEF_FNS(DC_SLEEF_ENTRY, d2, sse2)}}},
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

// void dc_kernel(const double* const* columns, double* out, i64 n), n a multiple of W:
//   for (i = 0; i < n; i += W) out[i..i+W) = program(columns[0][i..i+W), ...)
std::unique_ptr<llvm::Module> emit(const Program& p, const IsaSpec& isa,
                                   llvm::LLVMContext& ctx) {
  using namespace llvm;
  auto mod = std::make_unique<Module>("derivcheck_jit", ctx);
  IRBuilder<> b(ctx);
  Type* dbl = b.getDoubleTy();
  Type* i64 = b.getInt64Ty();
  auto* vec = FixedVectorType::get(dbl, static_cast<unsigned>(isa.width));
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
  BasicBlock* exit = BasicBlock::Create(ctx, "exit", f);

  b.SetInsertPoint(entry);
  const std::size_t nin = p.n_inputs();
  std::vector<Value*> colp(nin);
  for (std::size_t j = 0; j < nin; ++j)
    colp[j] = b.CreateAlignedLoad(dptr, b.CreateConstInBoundsGEP1_64(dptr, cols, j), Align(8), "col");
  b.CreateBr(head);

  b.SetInsertPoint(head);
  PHINode* i = b.CreatePHI(i64, 2, "i");
  i->addIncoming(b.getInt64(0), entry);
  b.CreateCondBr(b.CreateICmpULT(i, n), body, exit);

  b.SetInsertPoint(body);
  std::vector<Value*> reg(p.n_registers, nullptr);
  for (std::size_t j = 0; j < nin; ++j)
    reg[j] = b.CreateAlignedLoad(vec, b.CreateBitCast(b.CreateInBoundsGEP(dbl, colp[j], i), PointerType::getUnqual(vec)),
                                 Align(8), "x");
  for (std::size_t c = 0; c < p.const_double.size(); ++c)
    reg[nin + c] = ConstantVector::getSplat(ElementCount::getFixed(static_cast<unsigned>(isa.width)),
                                            ConstantFP::get(dbl, p.const_double[c]));
  auto sleef = [&](int k, int arity) -> FunctionCallee {
    std::vector<Type*> args(static_cast<std::size_t>(arity), vec);
    FunctionCallee fc = mod->getOrInsertFunction(isa.fns[static_cast<std::size_t>(k)].symbol,
                                                 FunctionType::get(vec, args, false));
    auto* decl = cast<Function>(fc.getCallee());
    decl->addFnAttr(Attribute::NoUnwind);
    decl->setDoesNotAccessMemory();  // pure: no errno, no state
    return fc;
  };
  for (const Instr& in : p.code) {
    Value* a = reg[in.a];
    Value* c = arity(in.op) == 2 ? reg[in.b] : nullptr;
    Value* r = nullptr;
    switch (in.op) {
      case Op::Add: r = b.CreateFAdd(a, c); break;
      case Op::Sub: r = b.CreateFSub(a, c); break;
      case Op::Mul: r = b.CreateFMul(a, c); break;
      case Op::Div: r = b.CreateFDiv(a, c); break;
      case Op::Neg: r = b.CreateFNeg(a); break;
      case Op::Sqrt: r = b.CreateUnaryIntrinsic(Intrinsic::sqrt, a); break;
      case Op::Abs: r = b.CreateUnaryIntrinsic(Intrinsic::fabs, a); break;
      default: {
        const int k = sleef_index(in.op);
        r = arity(in.op) == 2 ? b.CreateCall(sleef(k, 2), {a, c}) : b.CreateCall(sleef(k, 1), {a});
        if (in.op == Op::Log1p) {
          // SLEEF 3.5's log1p overflows to inf for x above about 1e307; there 1 + x == x and
          // log(x) is log1p(x) to within 1e-300 relative. Lanes above 1e300 (rare: a branch
          // over the fix-up, not a second call per vector) take log(x).
          Value* big = b.CreateFCmpOGT(a, ConstantVector::getSplat(ElementCount::getFixed(static_cast<unsigned>(isa.width)),
                                                                   ConstantFP::get(dbl, 1e300)));
          Value* any = b.CreateOrReduce(big);
          BasicBlock* from = b.GetInsertBlock();
          BasicBlock* fix = BasicBlock::Create(ctx, "log1p_big", f, exit);
          BasicBlock* cont = BasicBlock::Create(ctx, "log1p_cont", f, exit);
          b.CreateCondBr(any, fix, cont);
          b.SetInsertPoint(fix);
          Value* l = b.CreateSelect(big, b.CreateCall(sleef(sleef_index(Op::Log), 1), {a}), r);
          b.CreateBr(cont);
          b.SetInsertPoint(cont);
          PHINode* phi = b.CreatePHI(vec, 2);
          phi->addIncoming(r, from);
          phi->addIncoming(l, fix);
          r = phi;
        }
      }
    }
    reg[in.dst] = r;
  }
  b.CreateAlignedStore(reg[p.result], b.CreateBitCast(b.CreateInBoundsGEP(dbl, out, i), PointerType::getUnqual(vec)),
                       Align(8));
  i->addIncoming(b.CreateAdd(i, b.getInt64(static_cast<std::uint64_t>(isa.width))), b.GetInsertBlock());
  b.CreateBr(head);

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
