// The Sinumerik front end's internals: one ProgramParser for the program and its subprogram
// files, one FunctionParser per file (its declarations, control-structure stack and labels),
// and the block parser that reads one line's statements and lowers them to NC IR ops.
#pragma once
#include "frontend/sinumerik/Codes.h"
#include "frontend/sinumerik/Lexer.h"
#include "frontend/sinumerik/SinFrontend.h"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace ncc::sin {

struct VarDecl {
  ir::Type type = ir::Type::Real;
  std::vector<uint32_t> dims;  // empty: a scalar
  bool global = false;         // DEF NCK / CHAN: %%name
  unsigned len = 0;            // STRING[n]
  bool isChar = false;         // CHAR: a one-character string (docs/IR.md §2.2)
};

struct Signature {
  std::vector<ir::Param> params;
  bool ready = false;  // its PROC line was read
  bool retTarget = false;  // it has RET(target) / RETB(target): its calls are followed by the jump
};

class ProgramParser;

// A predefined name of the control (Predefined.cpp, from the operator table).
struct PredefinedName {
  std::string_view name, kind, meaning;
};
const PredefinedName *findPredefined(std::string_view upperName);

// Control structures open in a function (IF, WHILE, FOR, LOOP, REPEAT … UNTIL).
enum class Ctl : uint8_t { If, Else, While, For, Loop, Repeat };
struct CtlFrame {
  Ctl kind;
  SourceLoc loc;
  ir::Region *region;       // where the body's ops go
  ir::Op *op = nullptr;     // the if/while/loop op (its regions)
  ir::ExprPtr forVar;       // FOR: the counter
};

// One file's function.
class FunctionParser {
public:
  FunctionParser(ProgramParser &pp, uint32_t file, std::string name, bool isMain);
  bool run();  // parses every line; the function goes to pp's module
  // One source line (a block, a header line, a skipped block) into cur(). False when an error was reported.
  bool line(std::string_view line, uint32_t lineNo);
  // A mode the ISO blocks of the program set (G291 … G290): the static modes below follow it.
  void followMode(ModeValue m);
  // False (with errors) when a section call names a label the function lacks.
  bool sectionLabelsExist(const ir::Region &r, const std::set<std::string> &labels);
  ir::Function fn;

  // -- shared with the block parser
  ProgramParser &pp;
  uint32_t file;
  bool isMain;
  std::map<std::string, VarDecl> vars;     // DEF and parameters, upper-case names
  std::vector<CtlFrame> ctl;
  std::vector<std::pair<std::string, uint32_t>> labels;  // in text order, with their line
  std::vector<ir::Region *> regions;        // innermost last
  ModeValue plane = ModeValue::XY;  // static: the plane of ROT RPL= (docs/SINUMERIK.md)
  ModeValue motion = ModeValue::Count;  // static: G0/G1 for G53 blocks
  int leadChange = 0;  // static, with motion G33/G34/G35: 0, +1 (G34: F the lead's growth), -1 (G35)
  ModeValue distance;                    // static: G90/G91 (the main program starts in G90)
  bool poleKnown = true;                 // static: no plane change since the last G110/G111 (docs/SINUMERIK.md)
  bool apKnown = false;                  // static: AP= programmed since the last pole definition
  bool definitions = false;  // a GUD definition file (DEF NCK|CHAN only)
  bool retTarget = false;    // a RET(target) / RETB(target) was read
  std::vector<std::pair<std::string, SourceLoc>> laterLabels;  // REPEAT A B with B after the REPEAT
  bool sawStatement = false;                // a statement before: PROC must be first
  bool startsWithProc = false;              // the program's first statement is PROC: ENDPROC may end it
  SourceLoc endproc;                        // ENDPROC's place (line 0: none yet): nothing may follow it
  std::map<std::string, std::vector<Token>> macros;  // DEFINE NAME AS … of this program
  // DEFINE NAME AS tokens: stores the macro (true); other lines: replaces macro names by their
  // tokens (SIN-MAC-01). False with an error reported.
  bool macroLine(std::vector<Token> &toks, uint32_t line, bool &defined);
  ir::Region &cur() { return *regions.back(); }
  std::vector<Token> lineTokens;  // the current line's, reused
  // CONTPRON / CONTDCON … EXECUTE (Contour.cpp): the table being prepared (empty name: none), and
  // the last G70 G71 G700 G710 above in this file (0 … 3, -1 none), the tables' unit code.
  struct ContourTable {
    std::string name;
    VarDecl decl;
    ir::ExprPtr undercuts;
    bool coded = false;
    SourceLoc loc;
  } contourTable;
  int staticUnits = -1;
  void noteUnits(std::string_view gcode);
};

class ProgramParser {
public:
  ProgramParser(SourceManager &sm, const SinOptions &o, Diagnostics &d, ir::Module &m)
      : sm(sm), opts(o), diags(d), module(m) {}
  SourceManager &sm;
  const SinOptions &opts;
  Diagnostics &diags;
  ir::Module &module;
  std::map<std::string, Signature> procs;  // by upper-case name
  std::set<std::string> missing;
  std::vector<ir::Function> done;
  bool polar = false;       // some file uses polar coordinates: the main program declares their state
  bool globalR = false;      // some file uses RG[n]: the main program declares them
  bool retTargets = false;   // some file has RET(target): the main program declares its globals
  bool namedSections = false;  // some file has CALL "P" BLOCK with labels in STRING variables
  bool modalCalls = false;
  // GUD definition files (Gud.cpp): their variables, seen by every file, and the declarations
  // the main program starts with.
  std::map<std::string, VarDecl> guds;
  std::vector<ir::Op> gudOps;
  bool loadDefinitionFiles();  // false with errors reported  // some file read so far has MCALL: blocks may trigger it (docs/IR.md §5.5)
  bool ok = true;

  // The signature of a subprogram: loads and parses its file on first use. Null (with an
  // error at `loc` naming the paths tried) when it cannot be found.
  // A standard cycle without a subprogram of its name that the cycle library has: null without an
  // error, its entry in *libCycle.
  // `type` "MPF"/"SPF": the call named the file type (`name` is then _N_NAME_TYPE), only that
  // one is looked for.
  const Signature *callee(const std::string &name, SourceLoc loc, CycleSignature *libCycle = nullptr,
                          const std::string &type = {});
  // Every subprogram (.SPF) of the search path, for a call whose name is known only when it runs.
  // False with errors reported (in the files read).
  bool loadSearchPath(SourceLoc loc);
  // The file of program `base` (`type` "MPF"/"SPF" or empty: MPF first), 0 when not found.
  uint32_t programFile(const std::string &base, const std::string &type);
  std::vector<std::string> searchPath() const;  // searchDirs, then the CALLPATH folder
  void missingProgram(const std::string &name, SourceLoc loc);  // the error naming the folders
  // The function running program `name`'s section from label `from` through `to`'s block
  // (CALL "P" BLOCK A TO B): its name, null with an error reported.
  const std::string *sectionFunction(const std::string &name, const std::string &type, const std::string &from,
                                     const std::string &to, SourceLoc loc);
  std::map<std::string, bool> sections;  // section functions, true: with a RET(target)
  std::string callPath;  // the folder of the last CALLPATH (empty: none), searched after searchDirs
  // The folder a Sinumerik path names (`/_N_WKS_DIR/_N_X_WPD`, `//NC:/WKS.DIR/X.WPD`) under the
  // first search folder that has it; "" when none does.
  std::string programFolder(const std::string &path) const;
  // The function of ISO-dialect program `written` (ISOCALL): read by the ISO front end on first
  // use; null with an error reported.
  const std::string *isoProgram(const std::string &written, SourceLoc loc);
  std::unique_ptr<GuestBlocks> isoGuest;
  std::set<std::string> isoPrograms;
  bool searchPathLoaded = false;
  bool error(SourceLoc loc, std::string msg, const char *rule = "syntax") {
    diags.error(loc, std::move(msg), rule);
    ok = false;
    return false;
  }
};

// Reads one block (line) and appends its ops to the function's current region.
class BlockParser {
public:
  BlockParser(FunctionParser &f, std::vector<Token> &toks, uint32_t line) : f_(f), t_(toks), line_(line) {}
  bool parse();

  // Expressions (also used by PROC defaults).
  ir::ExprPtr expr(int minPrec = 0);

private:
  FunctionParser &f_;
  std::vector<Token> &t_;
  uint32_t line_;
  size_t i_ = 0;
  bool failed_ = false;

  // The block's machine words, lowered together at its end.
  struct Word {
    std::string addr;  // X, CR, I1, F, …
    ir::ExprPtr value;
    char mode = 0;     // 'A' AC(), 'I' IC()
    SourceLoc loc;
  };
  std::vector<Word> words_;
  // POLY polynomials PO[X]=(end, a2 … a5), X=PO(…), PO[]=(…)/PO(…) (axis empty: the denominator)
  struct PolyTerm {
    std::string axis;
    std::vector<ir::ExprPtr> values;
  };
  std::vector<PolyTerm> poly_;
  bool polyTerm(std::string axis, const Token &at);
  bool lowerPoly(ir::Region &out, ir::ExprPtr &denominator);
  bool lowerSpindleMode(const GInfo *g, ir::ExprPtr s, ir::ExprPtr lims, ir::Op &mode, ir::Region &out);
  bool lowerSmoothing(const GInfo *g, SourceLoc gl, ir::Op &mode);
  bool lowerFloatTap(SourceLoc gl, bool path, ir::Op mv, ir::Region &out);
  bool spindlePosition();
  ir::Op spindleAlarm(bool speed, const char *msg);
  std::vector<std::pair<GInfo, SourceLoc>> gcodes_;
  std::vector<std::pair<int, SourceLoc>> mcodes_;
  std::vector<ir::Op> pre_, post_;  // ops before the machine words (assignments) and after (calls)
  ir::Op *blockOp_ = nullptr;

  const Token &tok() const { return t_[i_]; }
  const Token &peek(size_t k = 1) const { return t_[std::min(i_ + k, t_.size() - 1)]; }
  SourceLoc loc(const Token &t) const { return {f_.file, line_, t.col}; }
  SourceLoc loc() const { return loc(tok()); }
  bool fail(const Token &t, std::string msg, const char *rule = "syntax");
  bool failAt(SourceLoc l, std::string msg, const char *rule);
  bool expect(std::string_view punct);
  bool atEnd() const { return tok().kind == Tok::End; }

  // statements
  bool statement();
  bool keyword(const std::string &kw);
  bool assignment();
  bool addressWord();
  bool gcode(const std::string &name, const Token &at);
  bool def();
  bool proc();
  bool callStatement(bool modal);
  bool computedCall(ir::ExprPtr name, const Token &at, SourceLoc l);        // CALL PROGNAME (SIN-CAL-05)
  bool sectionCall(ir::ExprPtr program, SourceLoc l);                      // CALL [p] BLOCK a TO b (SIN-CAL-06)
  // PCALL, EXTCALL, CALLPATH, ISOCALL (Calls.cpp): false when `kw` is none of them.
  bool programCall(const std::string &kw);
  bool pcall();
  bool extcall();
  bool callpath();
  bool isocall();
  bool namedCall(const std::string &written, SourceLoc l);
  bool plainCall(const std::string *fn, SourceLoc l, bool resume);
  bool sectionFunctionCall(const std::string &name, const std::string &type, const std::string &from,
                           const std::string &to, SourceLoc l);  // a call of P's section function
  ir::ExprPtr stringArgument(const char *kw, bool empty);
  bool retStatement(bool backward);  // RET, RET(…), RETB(…)
  bool endproc();                     // ENDPROC
  bool execString();                 // EXECSTRING("block")
  void resumeAfterCall(SourceLoc l);
  bool argumentList(const std::string &name, const std::vector<std::string> &params, const char *prefix, ir::Op &c);
  // A standard cycle from the library (Cycles.cpp): `NAME(args)` runs it here (a position
  // pattern: the modal cycle at each position), `MCALL NAME(args)` makes it modal.
  bool libraryCycle(bool modal, const std::string &name, const CycleSignature &lib, const Token &at);
  bool contourCapture(const std::string &name, const char *param, const ir::Op &cycle, const Token &at);
  ir::Op cycleCancel(SourceLoc l) const;
  bool transformation(const std::string &kw);  // TRANSMIT TRACYL TRAFOOF (Transform.cpp)
  bool gotoStatement(const std::string &kw, std::vector<ir::Op> &into);
  bool ifStatement();
  bool caseStatement();
  bool repeatStatement(bool single);
  bool frameStatement(const GInfo &g, const Token &at);
  bool closeCtl(Ctl want, const char *name, const Token &at);
  // Machine-specific constructs (MachineOnly.cpp): parsed, checked and lowered to a
  // not_simulated message. False when `kw` is none.
  bool machineConstruct(const std::string &kw);
  bool syncAction();
  bool machineItems(bool inSync);
  // A G code of a machine function (punching, repositioning): true when it is one (consumed).
  bool machineGCode(const GInfo &g, const Token &at);
  bool machineCtx_ = false;
  // WRITE DELETE READ FILEDATE … (Files.cpp): false when `kw` is none.
  // Contour tables (Contour.cpp): CONTPRON CONTDCON EXECUTE EXECTAB (false: `kw` is none of
  // them); INTERSEC and CALCDAT as the value of an assignment.
  bool contourStatement(const std::string &kw);
  bool executeTable(const Token &at);
  bool exectab(const Token &at);
  ir::ExprPtr contourFunction(const Token &at);
  const VarDecl *contourTableArg(const char *kw, int cols, std::string &name);
  bool contourArgs(std::vector<ir::ExprPtr> &out, std::vector<const Token *> &at);
  bool fileCommand(const std::string &kw);  // inside one: unknown names, $ variables and functions parse as placeholders
  // DELDL (ToolData.cpp): the statement at `at` (the keyword, not consumed) and, as the value of an
  // assignment, the status it leaves.
  bool deleteAdditive(const Token &at, bool status);
  ir::ExprPtr deldlStatus(const Token &at);
  ir::ExprPtr machineValue();
  void openCtl(Ctl kind, ir::Op op, SourceLoc l);
  bool lowerWords();
  Word *findWord(std::string_view addr);
  ir::ExprPtr takeWord(std::string_view addr, char *mode);  // the value; the word is used up
  bool lowerPole(const GInfo &g, ir::Region &out);           // Polar.cpp
  bool lowerPolarMove(ir::Op &mv, std::string &ac, ir::Region &out);

  // expressions
  ir::ExprPtr unary();
  ir::ExprPtr primary();
  ir::ExprPtr nameExpr(const Token &t);
  ir::ExprPtr variable(const Token &t);  // a declared variable, its element or frame component
  ir::ExprPtr systemVar(const Token &t);
  ir::ExprPtr function(const Token &t);
  // Isvar.cpp: the introspection functions, answered when the program is read.
  ir::ExprPtr isvar(const Token &t);
  ir::ExprPtr getvartyp(const Token &t);
  ir::ExprPtr stringis(const Token &t);
  ir::ExprPtr isaxis(const Token &t);
  ir::ExprPtr constantArg(const Token &t, ir::ExprKind kind);
  ir::ExprPtr modaxval(const Token &t);
  ir::ExprPtr indexList(std::vector<ir::ExprPtr> &out, bool axisOk);
  ir::ExprPtr comparison(ir::OpCode op, ir::ExprPtr a, ir::ExprPtr b, SourceLoc l);
  bool stringy(const ir::Expr &e) const;
  bool frameTyped(const ir::Expr &e) const;
  ir::ExprPtr assignValue(const ir::Expr &target);  // after '=': SET/REP lists and ':' chains
  bool arrayInit(const ir::Expr &target, const VarDecl &d, std::vector<ir::Op> &into, bool atDef);
};

// True when the text has MCALL (a modal call: blocks may trigger it).
bool mentionsMcall(std::string_view text);
// WHEN WHENEVER FROM EVERY DO ELSE: the words that structure a synchronized action.
bool isSyncKeyword(const std::string &name);
// The program a call names: `/_N_WKS_DIR/_N_P_WPD/_N_TEIL1_SPF`, `_N_TEIL1_SPF` and `TEIL1` are
// TEIL1 (upper case; the folders are not kept: the search path decides, L6885-L6897), with its
// type ("MPF", "SPF") in `type` when the name gives it.
std::string calledProgram(const std::string &written, std::string &type);
// The number of elements of a declared array (1 for a scalar).
size_t elementCount(const VarDecl &d);
// Declares the polar coordinates' program-wide state at the start of the main program.
void declarePolarState(ir::Region &mainBody);
// The global R parameters RG[0 … kGlobalRCount-1] (SIN-VAR-05): one REAL array of the program.
constexpr const char *kGlobalR = "_SIN_RG";
constexpr uint32_t kGlobalRCount = 1000;
void declareGlobalR(ir::Region &mainBody);
// RET(target): the target a callee leaves for its caller (kRetTarget, "" none; kRetBackward for
// RETB), and the caller's copy it jumps to (kRetJump).
constexpr const char *kRetTarget = "_SIN_RET", *kRetJump = "_SIN_RET_JUMP", *kRetBackward = "_SIN_RETB";
void declareReturnTargets(ir::Region &mainBody);
// CALL "P" BLOCK with labels in STRING variables: the caller's start and end labels (globals) and
// the section function's copy of the end (a local).
constexpr const char *kSectionFrom = "_SIN_SEC_FROM", *kSectionTo = "_SIN_SEC_TO", *kSectionEnd = "_SIN_SEC_END";
void namedSectionFunction(ir::Function &fn, SourceLoc l);  // adds the checks to P's function
void declareNamedSections(ir::Region &mainBody);
// `assign target= value=` at l.
ir::Op assignOp(ir::ExprPtr target, ir::ExprPtr value, SourceLoc l);
// A builtin call with the given arguments.
ir::ExprPtr callOf(const char *fn, SourceLoc l, ir::ExprPtr a, ir::ExprPtr b = nullptr);

}  // namespace ncc::sin
