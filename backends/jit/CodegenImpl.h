// Internal to backends/jit: the code generator's state, shared by Codegen.cpp (module,
// functions, control flow), CodegenExpr.cpp (expressions, variables) and CodegenCmd.cpp
// (machine commands and constant tables).
#pragma once
#include "backends/jit/MachineOps.h"
#include "ir/NCIR.h"

#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/Module.h>

#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace ncc::jit {

// A value of an expression and whether it can be vacant at run time (variable reads);
// arithmetic results never are, so most vacant checks fold away at compile time.
struct Val {
  llvm::Value *v;
  bool mayVacant;
};

class Codegen {
public:
  Codegen(const ir::Module &src, llvm::LLVMContext &ctx, Diagnostics &diags);
  std::unique_ptr<llvm::Module> run();

private:
  // ------------------------------------------------ module level (Codegen.cpp)
  void declareRuntime();
  void scanNames(const ir::Region &r);
  void scanExprNames(const ir::Expr &e);
  void emitFunction(const ir::Function &f, llvm::Function *F);
  void emitEntry();
  void initFrame(llvm::Value *frame);
  // ------------------------------------------------ control flow (Codegen.cpp)
  void scanTargets(const ir::Region &r);
  void emitRegion(const ir::Region &r);
  void emitOp(const ir::Op &op);
  void emitIf(const ir::Op &op);
  void emitWhile(const ir::Op &op);
  void emitLoop(const ir::Op &op);
  void emitGoto(const ir::Op &op);
  void emitCall(const ir::Op &op);
  const ir::Op *resolveTarget(unsigned from, const ir::Op &go, int64_t n, const std::string *label);
  llvm::BasicBlock *targetBlock(const ir::Op *op);
  void emitJump(const ir::Op &go, const ir::Op *target);
  void emitIterationCheck(llvm::Value *counter, SourceLoc loc);
  // ------------------------------------------------ helpers (Codegen.cpp)
  llvm::BasicBlock *newBlock(const char *name);
  void startBlock(llvm::BasicBlock *bb);  // falls through from an open current block
  void ensureOpen();                      // after a terminator: continue in a dead block
  llvm::Value *allocaEntry(llvm::Type *t, const char *name);
  void checkStatus(llvm::Value *status);  // returns the status when it is not NCRT_OK
  void failIf(llvm::Value *cond, SourceLoc loc, const std::string &msg);
  void faultIf(llvm::Value *cond, SourceLoc loc, unsigned kind, const std::string &name, llvm::Value *value);
  llvm::Constant *cstring(const std::string &s);
  std::vector<llvm::Value *> locArgs(SourceLoc loc);
  // ------------------------------------------------ expressions (CodegenExpr.cpp)
  Val expr(const ir::Expr &e);
  Val binary(const ir::Expr &e);
  Val callBuiltin(const ir::Expr &e);
  llvm::Value *numOf(Val v);
  llvm::Value *truthy(Val v);  // i1
  llvm::Value *isVacant(llvm::Value *v);
  llvm::Value *toDouble(llvm::Value *i1);
  llvm::Value *roundIndex(Val v);  // llvm.round(num(v))
  llvm::Value *varPtr(const ir::Expr &var, bool write);
  llvm::Value *numberedPtr(const ir::Expr &var, bool write);
  llvm::Value *paramPtr(const ir::Expr &var, llvm::Value *base, int64_t count);
  Val loadVar(const ir::Expr &var);
  void storeVar(const ir::Expr &var, llvm::Value *value);
  void badExpr(const ir::Expr &e, const std::string &msg);
  // ------------------------------------------------ commands (CodegenCmd.cpp)
  void emitMachineOp(const ir::Op &op);
  void flushRun();
  void emitDynamicCmd(const CmdSpec &s);
  llvm::Constant *cmdConstant(const CmdSpec &s);

  const ir::Module &src_;
  llvm::LLVMContext &C;
  Diagnostics &diags_;
  std::unique_ptr<llvm::Module> M;
  llvm::IRBuilder<> B;
  bool failed_ = false;

  llvm::Type *dblTy, *i8Ty, *i32Ty, *i64Ty, *i1Ty;
  llvm::PointerType *ptrTy;
  llvm::StructType *cmdTy, *storageTy;
  llvm::FunctionType *ncFnTy;
  llvm::FunctionCallee fBegin, fExec, fExecTable, fExecPacked, fError, fFault, fPoll, fMod, fIDiv, fPow;
  std::map<std::string, llvm::FunctionCallee> builtins_;
  std::map<std::string, llvm::Function *> functions_;
  std::map<std::string, llvm::Constant *> strings_;

  // Named variables get module-wide slots: locals index the frame after #0..#33, so a shared
  // frame sees the caller's named locals; globals index storage->named.
  std::map<std::string, unsigned> localNames_, globalNames_, qSpaces_;
  unsigned frameSize_ = 34;

  // ------------------------------------------------ per function
  llvm::Function *F = nullptr;
  llvm::BasicBlock *entryBB = nullptr, *failBB = nullptr, *exitBB = nullptr;
  llvm::PHINode *exitPhi = nullptr;
  llvm::Value *ctxArg, *stArg, *frameArg;
  llvm::Value *numberedBase, *rBase, *qBase, *namedBase, *maxLoop, *depthPtr, *pollPtr;
  llvm::Value *cmdSlot = nullptr, *argSlot = nullptr, *calleeFrame = nullptr, *gotoCounter = nullptr,
              *scratch = nullptr;
  struct LoopTargets {
    llvm::BasicBlock *cont, *brk;
  };
  std::vector<LoopTargets> loops_;
  // Jump targets: every op in pre-order (goto search order), block numbers and labels.
  std::unordered_map<const ir::Op *, unsigned> order_;
  std::vector<std::pair<int64_t, const ir::Op *>> blocks_;
  std::vector<std::pair<std::string, const ir::Op *>> labels_;
  std::unordered_map<const ir::Op *, llvm::BasicBlock *> targetBBs_;
  bool dynamicGoto_ = false;
  std::vector<CmdSpec> run_;  // pending constant commands
};

}  // namespace ncc::jit
