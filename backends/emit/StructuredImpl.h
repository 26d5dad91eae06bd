// The structure-keeping writer (docs/EMIT.md "Structure-keeping translation"): shared by
// StructuredExpr.cpp (variables, expressions, conditions) and Structured.cpp (blocks, control
// flow, subprograms, the files).
#pragma once
#include "backends/emit/Structured.h"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace ncc::emit::structured {

using ir::Expr;
using ir::Op;
using ir::Region;

// A number as the shortest plain decimal that reads back to the same double (no exponent: the
// ISO reader has none); `point` adds a decimal point to an integer (`10.`, ISO words).
std::string exactNumber(double v, bool point);

class Writer {
public:
  Writer(const ir::Module &m, const StructuredOptions &o, Diagnostics &d) : m_(m), o_(o), diags_(d) {
    iso_ = o.target == Target::ISO;
  }
  bool run(std::vector<StructuredFile> &files);

  // ---- StructuredExpr.cpp
  // A value in the target's syntax; false after reporting what cannot be written exactly.
  bool expr(const Expr &e, std::string &out);
  // The value after an address letter: ISO `10.`, `#1`, `[#1*2]`; Sinumerik `10`, `=R1`, `=(R1*2)`.
  bool word(const Expr &e, std::string &out);
  // A condition (IF, WHILE, a BOOL's value): ISO compares a plain number with 0.
  bool condition(const Expr &e, std::string &out);
  // A variable as an assignment target or operand.
  bool variable(const Expr &e, std::string &out);
  // What a store into `target` must wrap the value in (ISO: ROUND for a Sinumerik INT).
  bool storeValue(const Expr &target, const Expr &value, std::string &out);
  // Reports `what` at loc as an [unsupported-code] error; always false.
  bool fail(SourceLoc loc, const std::string &what);

  // Per-function variable state (set by Structured.cpp before a function is written).
  struct Declared {
    ir::Type type = ir::Type::Real;
    int number = 0;  // ISO target: the #number that holds it
  };
  std::map<std::string, Declared> locals_;  // the function's named locals (declared or NGC #<x>)
  std::set<int> rUsed_;                     // Sinumerik source: the R numbers used (ISO: set to 0 first)
  int nextCommon_ = 500;                    // ISO target: the next #number for a named local

private:
  bool binary(const Expr &e, std::string &out);
  bool call(const Expr &e, std::string &out);
  bool comparison(ir::OpCode op, const Expr &a, const Expr &b, SourceLoc loc, std::string &out);
  bool toleranceComparison(const Expr &e, std::string &out);
  // A bracketed operand unless atomic (or the left operand of a chain of its own level).
  bool wrap(const Expr &e, std::string &out, const Expr *parent = nullptr);

  // ---- Structured.cpp
public:
  struct Line {
    std::string prefix;               // "N50 ", "LBL1: "
    std::vector<std::string> words;
    std::string trail;                // a comment at the end of the line
  };

private:
  bool function(const ir::Function &f, StructuredFile &out);
  bool region(const Region &r, int depth);
  bool op(const Op &o, int depth);
  bool block(const Op &o);
  bool mode(const Op &o);
  bool move(const Op &o);
  bool machineWord(const Op &o);
  bool control(const Op &o, int depth);
  bool ifOp(const Op &o, int depth);
  bool loopOp(const Op &o, int depth);
  bool callOp(const Op &o);
  bool gotoText(const Op &o, std::string &out);
  bool jumpText(const Op &o, std::string &out);  // a goto or a break
  bool declare(const Op &o);
  bool calleeName(const Op &o, const std::string &fn, std::string &out);
  void addWord(std::string w);
  void statement(std::string text);  // a line of its own (control, assignment)
  void flush();
  void flushPrefix();                // a block number or label no line has taken yet
  std::string newLabel();            // ISO: a free N number; Sinumerik: a label name
  std::string jumpTo(const std::string &label, const char *dir);  // the goto text for newLabel()
  void placeLabel(const std::string &label);

  const ir::Module &m_;
  const StructuredOptions &o_;
  Diagnostics &diags_;
  bool iso_ = false;
  bool inMain_ = false;              // writing the main program
  bool ok_ = true;
  std::string text_;                 // the function being written
  Line cur_;
  bool curOpen_ = false;
  int indent_ = 0;                   // nesting depth of the line being written
  std::string pendingPrefix_;
  std::set<long long> blockNumbers_;   // the function's N numbers (ISO labels avoid them)
  std::map<std::string, std::string> labelN_;  // ISO target: source label -> N number
  long long nextN_ = 9001;
  int nextLabel_ = 1;
  std::vector<std::string> breakTargets_;  // innermost loop's exit label
  std::map<std::string, std::string> programNames_;  // function -> target program name
  std::vector<std::string> counters_;      // Sinumerik target: FOR counters to DEF
};

}  // namespace ncc::emit::structured
