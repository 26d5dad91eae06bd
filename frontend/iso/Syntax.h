// The ISO front end's dialect AST: one ParsedBlock per source line, produced by BlockParser and
// consumed by BlockLowerer (NC IR ops) and the program parser (control structure, subprograms).
#pragma once
#include "frontend/iso/IsoFrontend.h"
#include "ir/Diagnostics.h"
#include "ir/NCIR.h"
#include "ir/SystemParams.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ncc::iso {

// Fanuc Custom Macro B (default) or RS274NGC / LinuxCNC (.ngc files): they differ in operator
// precedence, O-words, named parameters and the unit of dwell P.
enum class Flavour : uint8_t { Fanuc, RS274 };

// .ngc files are RS274NGC, everything else Fanuc.
Flavour flavourForFile(std::string_view name);

struct IsoWord {
  char letter = 0;         // upper case
  bool hasPoint = false;   // literal written with a decimal point
  double value = 0;        // the literal (when expr is null)
  ir::ExprPtr expr;        // a Macro B value: X#1, X-[#2+1]
  SourceLoc loc;           // the letter
};

struct IsoComment {
  std::string text;
  SourceLoc loc;
  bool message = false;    // (MSG, text), or a LinuxCNC DEBUG / PRINT / ABORT (kind)
  const char *kind = "msg";  // the message op's kind: msg, debug, print, abort
};

struct IsoAssign {
  ir::ExprPtr target, value;
  int alarm = 0;  // Fanuc #3000 (alarm: the run stops) or #3006 (stop with a message)
  SourceLoc loc;
};

// Macro B / O-word statement of a block.
enum class StmtKind : uint8_t {
  None,
  IfGoto,    // IF [cond] GOTO target
  IfThen,    // IF [cond] THEN <the block's assignments and words>
  Goto,      // GOTO target
  While,     // WHILE [cond] DO id
  Do,        // DO id (endless loop)
  End,       // END id
  OWord,     // RS274 o<name> <keyword> ...
};

// RS274NGC O-word keywords.
enum class OKeyword : uint8_t {
  Sub, EndSub, Call, Return, If, ElseIf, Else, EndIf, While, EndWhile, Do, Break, Continue, Repeat,
  EndRepeat
};

struct ParsedBlock {
  SourceLoc loc;             // first non-blank character
  bool content = false;      // anything but blanks and empty `;`
  bool percent = false;      // a `%` line
  int64_t n = -1;            // N word
  int skip = -1;             // leading `/n` whose level is not active
  int64_t programNumber = -1;  // a Fanuc `O1234` line
  std::vector<IsoWord> words;
  std::vector<IsoWord> corner;  // `,C` chamfer / `,R` rounding (letter 'C' or 'R'), at most one
  std::vector<IsoComment> comments;
  std::vector<IsoAssign> assigns;
  StmtKind stmt = StmtKind::None;
  SourceLoc stmtLoc;
  ir::ExprPtr cond;          // IF / WHILE / O-word if, while, repeat count, return value
  ir::ExprPtr target;        // GOTO target
  int loopId = 0;            // DO / END id
  OKeyword okw = OKeyword::Sub;
  std::string oname;         // O-word name: "100" or "name"
  ir::ExprPtr ocomputed;     // computed O-word number: O[#2*10] call, O#1 call
  std::vector<ir::ExprPtr> oargs;  // o<n> call [a] [b]
  bool plain = false;        // the parser's fast path wrote it: only loc, content, n and words
  // A plain block's shape, set by the fast path: its letters in order, one byte each (G1 X Y:
  // 0x47'58'59), so equal shapes have the same letters in the same order; 0 when not worked out
  // (more than 8 words). Part of the lean lowering's decision cache key (LowerLean.cpp).
  uint64_t shape = 0;

  // Back to empty; clearPlain after a plain block, which set nothing else.
  void clearPlain() {
    loc = {};
    content = plain = false;
    n = -1;
    shape = 0;
    words.clear();
  }
  void clear() {
    plain = false;
    shape = 0;
    loc = {};
    content = percent = false;
    n = -1;
    skip = -1;
    programNumber = -1;
    words.clear();
    corner.clear();
    comments.clear();
    assigns.clear();
    stmt = StmtKind::None;
    stmtLoc = {};
    cond.reset();
    target.reset();
    loopId = 0;
    oname.clear();
    ocomputed.reset();
    oargs.clear();
  }
};

// `#<name>` (the text between < and >; case and blanks do not count): a predefined LinuxCNC
// parameter (System), a global `_name`, or a local. Null for an empty name.
ir::ExprPtr namedParameter(std::string_view name, SourceLoc loc);

// The number -> system variable map (ir/SystemParams.h) of a file: its flavour, and for Macro B
// the machine's offset memory and kind (frontend/iso/SystemParams.cpp).
ParamMap paramMapFor(Flavour f, OffsetMemory mem, bool lathe);
// The expression reading a constant `#n` (n > 0): a Numbered or a System variable; null with err
// set when ncc does not provide it.
ir::ExprPtr numberedParameter(ParamMap m, long n, SourceLoc loc, std::string &err);
// A computed `#[number]`: the map's builtin around the number, resolved when the program runs.
ir::ExprPtr computedParameter(ParamMap m, ir::ExprPtr number, SourceLoc loc);

// Turns one line into a ParsedBlock. Reports syntax errors and returns false (the block is then
// dropped by the caller).
class BlockParser {
public:
  BlockParser(Diagnostics &diags, Flavour flavour, unsigned blockDeleteMask, OffsetMemory mem = OffsetMemory::None,
              bool lathe = false)
      : diags_(diags), flavour_(flavour), map_(paramMapFor(flavour, mem, lathe)), skipMask_(blockDeleteMask) {}
  bool parse(std::string_view line, uint32_t file, uint32_t lineNo, ParsedBlock &out);
  // The stream's fast path (frontend/iso/Stream.cpp): the line at `line`, whose newline comes
  // before `end`, when it is a block of plain words (parse()'s fast path); `newline` is then
  // where it ends. False: nothing reported, parse() reads the line.
  bool parsePlainLine(const char *line, const char *end, uint32_t file, uint32_t lineNo, ParsedBlock &out,
                      const char *&newline);

  // Expression entry points (also used by tests).
  ir::ExprPtr parseExpr(int minPrec);

private:
  Diagnostics &diags_;
  Flavour flavour_;
  ParamMap map_;  // the numbers of #n and #[e]
  unsigned skipMask_;
  const char *begin_ = nullptr, *p_ = nullptr, *end_ = nullptr;
  uint32_t file_ = 0, line_ = 0;
  bool failed_ = false;
  int depth_ = 0;

  SourceLoc locAt(const char *q) const { return {file_, line_, (uint32_t)(q - begin_ + 1)}; }
  bool fail(const char *at, std::string msg, const char *rule = "syntax");
  void skipBlanks();
  bool atEnd() const { return p_ >= end_; }
  char peekUpper() const;
  std::string_view readLetters();
  bool readNumber(double &v, bool &hasPoint, bool &any);
  bool parseComment(ParsedBlock &out);
  bool parseSemicolonComment(ParsedBlock &out);
  bool parseWordValue(IsoWord &w);
  bool parseStatement(std::string_view kw, const char *at, ParsedBlock &out);
  bool parseAssign(ParsedBlock &out);
  bool parseOWord(ParsedBlock &out, const char *at);
  bool parsePlainWords(ParsedBlock &out);  // the fast path of parse (false: parseItems reads the block)
  template <bool kSentinel>
  const char *plainWords(const char *q, const char *end, ParsedBlock &out);
  bool parseItems(ParsedBlock &out);
  ir::ExprPtr parseBracket();   // [ expr ]
  ir::ExprPtr parseUnary();
  ir::ExprPtr parsePrimary();
  ir::ExprPtr parseVariable(bool target = false);  // after '#'; target: of an assignment
  ir::ExprPtr parseFunction(std::string name, const char *at);
  bool binaryOp(int &prec, ir::OpCode &op, const char *&after);
  // A Fanuc two-letter abbreviation's keyword (WH -> WHILE); otherwise the word itself.
  std::string_view keyword(std::string_view w) const;
};

}  // namespace ncc::iso
