// The JIT's code generation (numeric/jit.hpp): a Program as LLVM IR on <W x double>, compiled
// by LLVM 14 ORC (LLJIT) for the host CPU. One LLJIT per kernel: the kernel owns its code and
// frees it with itself, and kernels compiled on different threads share nothing.
#if DERIVCHECK_HAVE_JIT
#include <chrono>
#include <cstring>
#include <mutex>

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

namespace dc::num {

struct JitKernel::Session {
  std::unique_ptr<llvm::orc::LLJIT> jit;
};

JitKernel::~JitKernel() = default;

namespace {

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
std::unique_ptr<llvm::Module> emit(const Program& p, const jitdetail::IsaSpec& isa,
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
    Value* c = op_arity(in.op) == 2 ? reg[in.b] : nullptr;
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
        r = op_arity(in.op) == 2 ? b.CreateCall(sleef(k, 2), {a, c}) : b.CreateCall(sleef(k, 1), {a});
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

}  // namespace

std::shared_ptr<const JitKernel> JitBuilder::build(const Program& p, const jitdetail::IsaSpec& isa,
                                                   std::string* why) {
  const auto t0 = std::chrono::steady_clock::now();
  static std::once_flag init;
  std::call_once(init, [] {
    llvm::InitializeNativeTarget();
    llvm::InitializeNativeTargetAsmPrinter();
  });
  auto fail = [&](const std::string& what) -> std::shared_ptr<const JitKernel> {
    if (why) *why = "JIT: " + what;
    return nullptr;
  };
  auto jtmb = llvm::orc::JITTargetMachineBuilder::detectHost();  // host CPU and its features
  if (!jtmb) return fail(message(jtmb.takeError()));
  jtmb->setCodeGenOptLevel(llvm::CodeGenOpt::Aggressive);
  auto jit = llvm::orc::LLJITBuilder().setJITTargetMachineBuilder(std::move(*jtmb)).create();
  if (!jit) return fail(message(jit.takeError()));
  // The SLEEF functions by address (linked into this process), nothing else from outside.
  llvm::orc::SymbolMap syms;
  for (const auto& s : isa.fns)
    syms[(*jit)->mangleAndIntern(s.symbol)] = llvm::JITEvaluatedSymbol(
        llvm::pointerToJITTargetAddress(s.address), llvm::JITSymbolFlags::Exported | llvm::JITSymbolFlags::Callable);
  if (auto e = (*jit)->getMainJITDylib().define(llvm::orc::absoluteSymbols(std::move(syms))))
    return fail(message(std::move(e)));

  auto ctx = std::make_unique<llvm::LLVMContext>();
  std::unique_ptr<llvm::Module> mod = emit(p, isa, *ctx);
  mod->setDataLayout((*jit)->getDataLayout());
  mod->setTargetTriple((*jit)->getTargetTriple().str());
  std::string verr;
  llvm::raw_string_ostream vos(verr);
  if (llvm::verifyModule(*mod, &vos)) return fail("invalid IR: " + vos.str());
  if (auto e = (*jit)->addIRModule(llvm::orc::ThreadSafeModule(std::move(mod), std::move(ctx))))
    return fail(message(std::move(e)));
  auto sym = (*jit)->lookup("dc_kernel");  // compiles
  if (!sym) return fail(message(sym.takeError()));

  std::shared_ptr<JitKernel> k(new JitKernel());
  k->fn_ = reinterpret_cast<JitKernel::Fn>(static_cast<std::uintptr_t>(sym->getAddress()));
  k->width_ = isa.width;
  k->isa_ = isa.name;
  k->n_inputs_ = p.n_inputs();
  k->session_ = std::make_unique<JitKernel::Session>();
  k->session_->jit = std::move(*jit);
  k->compile_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return k;
}

}  // namespace dc::num
#endif  // DERIVCHECK_HAVE_JIT
