// Programs in two languages: the 808D's (and 840D's ISO dialect's) G290 selects Siemens mode and
// G291 ISO mode inside a program (seed001 §1, ISO-MODE-01/02, SIN-OPS-44). The front end of the
// file's dialect (the host) reads the program; the blocks written in the other mode go, one by
// one, to the other front end's block entry (the guest), which lowers them into the same region
// of the same function. The modal state is the executor's, so it is shared; the little static
// mode knowledge each front end keeps for its own decisions (the motion mode of bare axis words,
// the plane, G90/G91, units) follows the mode ops the other front end wrote.
#pragma once
#include "ir/Diagnostics.h"
#include "ir/ModeTable.h"
#include "ir/NCIR.h"

#include <functional>
#include <memory>
#include <string>
#include <string_view>

namespace ncc {

enum class Language : uint8_t { Siemens, Iso };

// One front end's block entry, used by a program of the other dialect.
class GuestBlocks {
public:
  virtual ~GuestBlocks() = default;
  // Parses source line `lineNo` of `file` and appends its ops to `out`. False when an error was reported.
  virtual bool block(std::string_view line, uint32_t file, uint32_t lineNo, ir::Region &out) = 0;
  // The guest's section ends at `at` (a switch back, the end of the file): false, reported, when
  // a control structure it opened is still open.
  virtual bool leave(SourceLoc at) = 0;
  // A mode the host's blocks set since the guest's last section (static knowledge only).
  virtual void follow(ModeValue m) = 0;
  // A whole program file of the guest's language, called from the host (808D: a macro or
  // subprogram whose first block is PROC runs in Siemens mode), as function `name`; it goes into
  // the module at finish(). False when an error was reported.
  virtual bool program(uint32_t file, const std::string &name) = 0;
  // At the end of the program: the functions the guest defined (subprogram files it loaded) go
  // into the host's module. False when an error was reported.
  virtual bool finish(ir::Module &) { return true; }
};
using GuestFactory = std::function<std::unique_ptr<GuestBlocks>()>;

// The host's side: call take() with every source line before parsing it. It reads G290/G291,
// hands the lines of the other mode to the guest (created at the first switch) and keeps both
// sides' static modes in step.
class MixedProgram {
public:
  // host: the language of the front end using it; mask: the active block-delete levels.
  MixedProgram(Language host, GuestFactory guest, unsigned blockDeleteMask, Diagnostics &diags);
  ~MixedProgram();
  // True when the line was taken (a mode switch or a guest block): the host skips it. `out` is
  // the host's current region; ok becomes false when an error was reported. hostFollow gets the
  // modes the guest's section set when the host's mode comes back.
  bool take(std::string_view line, uint32_t file, uint32_t lineNo, ir::Region &out, bool &ok,
            const std::function<void(ModeValue)> &hostFollow);
  // The end of a file (the next file starts in the host's language): false when the guest left a
  // structure open (reported).
  bool endFile(SourceLoc at);
  // The guest (created when first needed); null when the program has none.
  GuestBlocks *guest();
  // The end of the program: the guest's functions into `m`.
  bool finish(ir::Module &m) { return guest_ ? guest_->finish(m) : true; }

private:
  Language host_, mode_;
  GuestFactory factory_;
  std::unique_ptr<GuestBlocks> guest_;
  unsigned mask_;
  Diagnostics &diags_;
  const ir::Region *mark_ = nullptr;  // where the current section's ops begin
  size_t markAt_ = 0;
  void follow(const ir::Region &out, const std::function<void(ModeValue)> &f);
};

// Calls f for every mode value the ops r[from…] set, nested regions included, in order.
void forEachMode(const ir::Region &r, size_t from, const std::function<void(ModeValue)> &f);

}  // namespace ncc
