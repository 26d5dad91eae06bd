// The Klartext front end's internals: one ProgramParser for the program and the programs it
// calls, one FileParser per file (a function: its labels, section calls, Q parameters) and the
// block parser that lowers one block to NC IR ops.
#pragma once
#include "frontend/heidenhain/HeiFrontend.h"
#include "frontend/heidenhain/Lexer.h"

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace ncc::hei {

// The NC IR names every file of the front end builds ops from.
using ir::Expr;
using ir::ExprPtr;
using ir::Op;
using ir::OpCode;
using ir::OpKind;

class ProgramParser;
struct Approach;  // an APPR block waiting for its first contour element (Approach.cpp)
struct FkChain;   // FK blocks being solved (Fk.h)
namespace fk {
struct Element;
}

// CALL LBL n: resolved once every label of the file is known (a subprogram LBL n … LBL 0, or
// with REP a section repeat back to LBL n).
struct LabelCall {
  size_t at;          // index of its call_section op in the body
  std::string label;  // "LBL5", "LBL:NAME"
  bool rep;           // REP written
  SourceLoc loc;
};

// One program file: one function.
class FileParser {
public:
  FileParser(ProgramParser &pp, uint32_t file, std::string name, bool isMain);
  bool run();
  ir::Function fn;

  ProgramParser &pp;
  uint32_t file;
  bool isMain;
  std::string pgmName;              // BEGIN PGM name
  bool inch = false;                // BEGIN PGM … INCH
  bool begun = false, ended = false;
  bool sawEnd = false;              // an M2/M30 block: END PGM adds no program end
  SourceLoc beginLoc;
  bool usesQL = false;              // declares the local QL array at its start
  std::map<std::string, size_t> labels;        // label name -> body index
  std::vector<size_t> lbl0;                    // body indices of the LBL 0 labels
  std::vector<LabelCall> calls;
  std::vector<std::pair<std::string, SourceLoc>> gotos;  // FN 9-12 targets
  size_t lastMove = SIZE_MAX;       // body index of the last move (RND and CHF attach to it)
  int cycle = -1;                   // the last CYCL DEF of a CALL-active cycle (static)
  bool cycleRuns = false;           // … and the library has it (CYCL CALL and M99 lower to `cycle`)
  bool m89 = false;                 // the modal cycle call M89 is on (static: no labels, calls, jumps)
  bool cycleSurface = false;        // … and gives Q203 (kept in %_HEI_Q203 for CYCL CALL POS)
  int oldCycle = -1;                // the last old-style CYCL DEF n.0
  std::string cycleProgram;         // cycle 12 PGM CALL: the program's function
  ir::Op storedCall(SourceLoc l) const;  // CYCL CALL, M99, M89: the stored cycle or cycle 12's program
  std::vector<ir::Op> pattern;      // the last PATTERN DEF / SEL PATTERN: CYCL CALL PAT's ops
  std::shared_ptr<Approach> approach;  // APPR: lowered with the next block (an L)
  int compSide = 0;                 // the last RL (1) / RR (2) / R0 (0) in file order (DEP)
  bool lastWasLine = false;         // the block before is an L (DEP's last element)
  int lastArcDir = 0;               // … or a C: its DR (+1, -1), else 0
  bool usesDep = false;             // the file has DEP: each L keeps where it starts
  SourceLoc cycleLoc;
  // SL cycles (SlCycles.cpp): cycle 14's labels (each with where it is written), the parameters
  // each SL cycle's last definition gave, and whether its Q208 was FMAX.
  std::vector<std::pair<std::string, SourceLoc>> slLabels;
  std::map<int, std::set<std::string>> slGiven;
  std::map<int, bool> slFmaxOut;
  // Contour formulas (ContourFormula.cpp): the function of the program SEL CONTOUR selected, the
  // entries of CONTOUR DEF (either replaces cycle 14), whether this file was loaded by SEL
  // CONTOUR (DECLARE CONTOUR and QC formulas belong there) and the QC numbers it has so far.
  std::string slProgram;
  struct ContourDefEntry {
    bool island;
    int n;
    std::string callee, label;  // a program's function, or a label of this file
    SourceLoc at;
  };
  std::vector<ContourDefEntry> contourDef;
  bool contourProgram = false;
  std::set<int> qcKnown;
  bool slBroken = false;  // the last SEL CONTOUR or CONTOUR DEF failed: its calls add no error
  // TCH PROBE 0.0 <title> Qn X-: the result parameter and the probing axis and direction for 0.1.
  struct OldProbe {
    int cycle = -1, resultQ = 0, dir = 0;
    char axis = 0;
  } oldProbe;
  std::shared_ptr<FkChain> fk;      // FK: the chain being solved, the position known statically
  FkChain &fkChain();
  bool fkLower();                   // hands on the elements solved once one solution is left
  bool fkFinish(SourceLoc at, const std::string &what);  // the contour continues with `what`: solved?
  bool error(SourceLoc loc, std::string msg, const char *rule = "syntax");

private:
  bool resolveLabels();
};

class ProgramParser {
public:
  ProgramParser(SourceManager &sm, const HeiOptions &o, Diagnostics &d) : sm(sm), opts(o), diags(d) {}
  SourceManager &sm;
  const HeiOptions &opts;
  Diagnostics &diags;
  std::vector<ir::Function> done;                 // called programs
  std::map<std::string, std::string> loaded;      // file path -> function name
  bool polar = false;    // some file uses CC/LP/CP: the main program declares the pole
  bool fauto = false;    // some file uses FAUTO or TOOL CALL F
  bool frames = false;   // some file uses cycle 7 or 10: the main program declares the shift and angle
  bool surface = false;  // some file uses CYCL CALL POS: the main program declares the cycle's Q203
  bool global125 = false;  // some file has GLOBAL DEF 125: … declares its Q345
  bool callFeed = false;   // some CYCL CALL POS has a feed: … declares the kept modal feed
  bool approach = false;   // some file uses APPR/DEP: … declares their scratch values
  bool callPat = false;    // some CYCL CALL PAT is split over several ops: … declares the call's level
  bool mainInch = false;
  bool loadingContourProgram = false;  // program() loads SEL CONTOUR's program
  std::set<std::string> probeVars;  // the touch-probe cycles' scratch values (ProbeGen.cpp)
  std::set<std::string> slVars;  // the SL cycles' frozen parameters: declared by the main program
  std::set<std::string> globalDefVars;  // the GLOBAL DEF values PREDEF reads (GlobalDef.cpp): … unset at the start
  bool ok = true;
  // The function of a called program (CALL PGM): parsed on first use; "" with an error at loc.
  std::string program(const std::string &written, uint32_t fromFile, SourceLoc loc);
  // Where a file named in `fromFile` is looked for: its folder, then each --include folder.
  std::vector<std::string> folders(uint32_t fromFile) const;
  bool error(SourceLoc loc, std::string msg, const char *rule = "syntax") {
    diags.error(loc, std::move(msg), rule);
    ok = false;
    return false;
  }
};

// The words of a path block (L, C, CR, CT, LP, CP, CC) and what else a block may carry.
struct Coord {
  char axis;  // X Y Z A B C U V W
  bool inc;   // IX …
  ir::ExprPtr value;
  SourceLoc loc;
};
struct PathWords {
  std::vector<Coord> coords;
  ir::ExprPtr pa, pr;
  bool paInc = false, prInc = false;
  SourceLoc paLoc, prLoc;
  int comp = -1;  // R0 0, RL 1, RR 2
  ir::ExprPtr feed;
  bool fmax = false, fauto = false;
  SourceLoc feedLoc;
  int dr = 0;  // DR+ 1, DR- -1
  SourceLoc drLoc;
  ir::ExprPtr radius;  // CR's R
  SourceLoc radiusLoc;
  std::vector<std::pair<int, SourceLoc>> ms;
  const Coord *find(char axis) const {
    for (auto &c : coords)
      if (c.axis == axis) return &c;
    return nullptr;
  }
};

// A cycle parameter line's value (GlobalDef.cpp): a number or Q parameter, or what the manual
// allows beside (docs/HEIDENHAIN.md "Cycle parameter values").
struct CycleValue {
  enum Kind { Number, Fauto, Fmax, PerRev, PerTooth, Predef, Text } kind = Number;
  ir::ExprPtr value;  // null for Text; FMAX, FU, FZ as the feed codes of ir/CycleFeed.h
  std::string text;   // Text: the string
  SourceLoc at;       // where the value is written
};

// Which words a statement takes.
enum WordSet : unsigned {
  kCoords = 1, kPolar = 2, kComp = 4, kFeed = 8, kM = 16, kDir = 32, kRadius = 64,
};

class BlockParser {
public:
  BlockParser(FileParser &f, Block &b) : f_(f), b_(b), t_(b.toks) {}
  bool parse();
  int arcDir() const { return arcDir_; }  // a C block's DR (+1, -1), after parse()
  bool fkLowerElement(const fk::Element &e, PathWords &w);  // Fk.cpp: a solved FK element as L or C

  // Expressions (Expr.cpp)
  ir::ExprPtr formula();           // + - * / ^, functions, parentheses
  ir::ExprPtr signedValue();       // [+|-] number | Q param: a word's value
  ir::ExprPtr qParam();            // Q5, QL5, QR5, QS5 at the current token
  ir::ExprPtr stringFormula();     // "text" || QS5: the value of a QS assignment
  static bool isString(const ir::Expr &e);  // a QS parameter

private:
  FileParser &f_;
  Block &b_;
  std::vector<Token> &t_;
  size_t i_ = 0;
  bool moved_ = false;  // the block emitted a move (M89 calls the cycle after it)
  int arcDir_ = 0;

  const Token &tok() const { return t_[i_]; }
  const Token &peek(size_t k = 1) const { return t_[std::min(i_ + k, t_.size() - 1)]; }
  SourceLoc loc(const Token &t) const { return {f_.file, t.line, t.col}; }
  SourceLoc loc() const { return loc(tok()); }
  bool fail(const Token &t, std::string msg, const char *rule = "syntax");
  bool expectWord(std::string_view w);
  bool atEnd() const { return tok().kind == Tok::End; }
  ir::Op blockOp() const;  // `block n=` of this block
  ir::Region &out() { return f_.fn.body; }

  // statements (Block.cpp)
  bool beginPgm();
  bool endPgm();
  bool blkForm();
  bool tool();
  ir::ExprPtr toolByName(const std::string &name, SourceLoc at);  // a tool's number by its name
  bool fn();
  bool assign();
  bool label();
  bool call();
  bool cycl();
  bool oldCycleBlock(int number, const Token &n);  // Cycles.cpp: 7.k, 9.k, 10.k
  bool transformBlock(int number, const Token &n);  // Transforms.cpp: 8.k, 11.k, 26.k
  bool toleranceBlock(const Token &n);             // Cycles.cpp: 32.1, 32.2
  bool workingPlaneCycle(const Token &n);          // Plane.cpp: 19.1
  bool plane();                                    // Plane.cpp: PLANE …
  ir::Op tiltOp(bool set, const char *form, const char *position);
  std::string planeWord();
  bool planePositioning(ir::Op &o, const Token &kw);
  bool cyclCallPos();                              // Cycles.cpp
  bool programCycle(const Token &n);               // Cycles.cpp: CYCL DEF 12.1 PGM
  bool contourLabels(const Token &n);              // SlCycles.cpp: CYCL DEF 14.1 1/2/3
  bool slDefinition(int number, const Token &n);   // SlCycles.cpp: CYCL DEF 20-25
  // Reads `Qn=` / `QSn=` of a cycle parameter line into `name` ("Q200"); a repeat is an error
  // naming `block` ("CYCL DEF 200", "TCH PROBE 410").
  bool cycleParamName(int number, std::set<std::string> &seen, std::string &name, const char *block = "CYCL DEF");
  bool slCall(const std::string &how);             // SlCycles.cpp: CYCL CALL of 21-25
  void subContourCapture(const char *use, const std::string &label, SourceLoc at, SourceLoc bl);
  bool trainCall(SourceLoc bl, PathWords &w);
  // Contour formulas (ContourFormula.cpp)
  bool selContour();                               // SEL CONTOUR "program"
  bool declareContour();                           // DECLARE CONTOUR QCn = "program" | LBL n [DEPTHd]
  bool contourDef();                               // CONTOUR DEF P1 = … I2 = … [DEPTHd]
  bool qcFormula();                                // QCn = ( QC1 | QC2 ) \ QC3
  bool contourSource(FileParser::ContourDefEntry &e);  // "program" | LBL n, then DEPTH
  bool formulaOperand(int closeWith, char &op);    // QCn | ( … ) with the operators that follow
  void formulaCapture(const FileParser::ContourDefEntry &e, SourceLoc bl);
  bool formulaCaptures(SourceLoc bl);              // CYCL CALL: SEL CONTOUR's or CONTOUR DEF's region
  bool cyclCallPat();                              // Patterns.cpp
  bool patternDef();                               // Patterns.cpp
  bool select();                                   // Patterns.cpp: SEL PATTERN
  bool globalDef();                                // GlobalDef.cpp: GLOBAL DEF 100 … 125
  // The value of parameter `name` of cycle `cycle` at the current token; with `emit`, PREDEF adds
  // the check that a GLOBAL DEF gave the value (a run-time stop at the word otherwise).
  bool cycleValue(int cycle, const std::string &name, CycleValue &v, bool emit);
  bool tchProbe();                                 // Probe.cpp: TCH PROBE
  bool oldProbeBlock(int number, int sub, const Token &n);  // Probe.cpp: TCH PROBE 0.0, 0.1
  bool approachDepart();                           // Approach.cpp: APPR, DEP
  bool approachBefore(PathWords &firstElement, int dr);  // … the APPR before its first element (dr: C's DR, 0: L)
  void arcTangent(const char *px, const char *py, int dr, SourceLoc l);
  bool depart(Approach &a);
  bool takeWord(const char *w, ir::ExprPtr &out);
  void unitAndNormal(int side, const std::string &zeroLength, SourceLoc l);
  void tangentPoint(int turn, ir::ExprPtr scale, const std::string &inside, SourceLoc l, ir::ExprPtr &x, ir::ExprPtr &y);
  void keepLineStart();
  bool stop();
  bool mOnly();
  // FK free contour (Fk.cpp)
  bool fkElement();
  bool fkPole();
  bool fkSelect();
  void fkFollowLine(const PathWords &w);  // where an L leaves the contour, when known statically
  // paths (Path.cpp)
  bool line();
  bool linePolar();
  bool arc();
  bool arcPolar();
  bool arcRadius();
  bool arcTangent();
  bool centre();
  bool corner();
  bool words(PathWords &w, unsigned allowed, const char *stmt);
  bool emitBefore(PathWords &w);                 // feed, M at the block start, compensation
  bool inchFeed(SourceLoc at);                   // false (an error) for F in an INCH program
  bool emitMove(ir::Op mv, PathWords &w, const char *motion);
  bool emitAfter(PathWords &w);                  // M at the block end
  bool polarEnd(PathWords &w, ir::Op &mv, bool arc);

  // expressions
  ir::ExprPtr term();
  ir::ExprPtr factor();
  ir::ExprPtr unary();
  ir::ExprPtr primary();
  bool labelName(std::string &name);             // LBL n / LBL "name": its label
};

// Helpers shared by the statements.
ir::ExprPtr hglobal(const char *name, SourceLoc l = {});
ir::Op assignOp(ir::ExprPtr target, ir::ExprPtr value, SourceLoc l);
ir::ExprPtr num(double v, SourceLoc l = {});
// The pole (CC) and FAUTO's feed: program-wide variables declared at the main program's start.
extern const char *const kCcX, *const kCcY, *const kPr, *const kPa, *const kFauto;
// The datum shift (cycle 7) and rotation angle (cycle 10), program-wide.
extern const char *const kShiftX, *const kShiftY, *const kShiftZ, *const kRot;
extern const char *const kSurface;  // Q203 of the stored cycle
extern const char *const kModalFeed;  // the modal feed kept around CYCL CALL POS's own
extern const char *const kApproachVars[];  // APPR/DEP's scratch values, null-terminated
extern const char *const kGlobal125, *const kCallLevel;  // GLOBAL DEF 125's Q345, CYCL CALL PAT's level
// Scaling (cycle 11; cycle 26's factors and centres) and mirroring (cycle 8), program-wide.
extern const char *const kScl, *const kAxisScl[3], *const kAxisCc[3], *const kMirror[2];
// Around a change of the frame's state: the active rotation, scaling, mirror off, then back on.
void frameTakeOff(ir::Region &out, SourceLoc l);
void framePutOn(ir::Region &out, SourceLoc l);
bool oldCycleRuns(int number);
// The SL cycles 20-25 (SlCycles.cpp), and the variable that keeps parameter q of cycle n.
bool slCycle(int number);
std::string slVar(int cycle, const std::string &q);
// A program name written in a block: a string, or the words and numbers up to `stopWord`.
std::string nameText(const std::vector<Token> &t, size_t &k, std::string_view stopWord);
// The program-wide variable holding GLOBAL DEF's value of `q` ("Q200"), and its value before
// any GLOBAL DEF gave one.
std::string globalDefVar(const std::string &q);
double globalDefUnset();
// Sections (call_section) need label names; LBL 0 gets one per occurrence.
std::string labelOf(const Token &t);

}  // namespace ncc::hei
