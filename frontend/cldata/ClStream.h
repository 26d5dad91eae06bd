// The streamed CL front ends' loop (docs/CLDATA.md and docs/APT.md "Streaming"), one for ADEM
// CLData and APT CL text: a chunk of records read into records reused from chunk to chunk,
// their reading errors reported, then lowered into the chunk's region, which the driver runs and
// clears. The lowerer's state (mode, feed, position, a waiting arc) goes on from chunk to chunk,
// so the ops are those of the whole program, a chunk at a time.
#pragma once
#include "frontend/Frontend.h"
#include "ir/Diagnostics.h"
#include "ir/NCIR.h"

#include <utility>
#include <vector>

namespace ncc::cld {

// Reader: next(Record &, std::vector<Error> &) (false at the end) and offset(); Lowerer: built
// from (Diagnostics &, ir::Region &), with setBody, start, lower, finish (after the last record)
// and ended.
template <class Reader, class Record, class Error, class Lowerer>
class ClStream : public BlockStream {
public:
  using Report = bool (*)(Diagnostics &, const std::vector<Error> &);
  template <class... ReaderArgs>
  ClStream(SourceManager &sm, uint32_t file, Diagnostics &d, SourceLoc start, Report report, ReaderArgs &&...args)
      : sm_(sm), file_(file), diags_(d), start_(start), report_(report), reader_(std::forward<ReaderArgs>(args)...),
        lw_(d, scratch_) {}

  bool next(ir::Region &out, size_t maxBlocks, CmdSink *) override {
    lw_.setBody(out);
    if (!started_) lw_.start(start_), started_ = true;
    chunk(maxBlocks);
    // After the end record the rest only gives warnings; after an error nothing runs, but every
    // error is still reported, as the whole-program front end does. Both read on to the end here.
    while (!atEnd_ && (lw_.ended() || diags_.hasErrors())) {
      if (diags_.hasErrors()) out.clear();
      chunk(maxBlocks);
    }
    return !atEnd_;
  }

private:
  void chunk(size_t maxBlocks) {
    size_t n = 0;
    errs_.clear();
    for (; n < maxBlocks; ++n) {
      if (recs_.size() <= n) recs_.emplace_back();
      if (!reader_.next(recs_[n], errs_)) {
        atEnd_ = true;
        break;
      }
    }
    report_(diags_, errs_);
    for (size_t i = 0; i < n; ++i) lw_.lower(recs_[i]);
    if (atEnd_) lw_.finish();
    sm_.released(file_, reader_.offset());  // the file's pages behind the reader
  }

  SourceManager &sm_;
  uint32_t file_;
  Diagnostics &diags_;
  SourceLoc start_;
  Report report_;
  Reader reader_;
  ir::Region scratch_;
  Lowerer lw_;
  std::vector<Record> recs_;
  std::vector<Error> errs_;
  bool started_ = false, atEnd_ = false;
};

}  // namespace ncc::cld
