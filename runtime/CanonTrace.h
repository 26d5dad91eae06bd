// Canonical trace writer: prints Motion IR in the text format of LinuxCNC's rs274 standalone
// interpreter (`%5d N..... NAME(args)`, %.4f), so `ncc run --trace=canon` output can be compared
// with rs274's (runtime/CanonDiff.h). Positions are machine coordinates in mm: the preamble
// declares mm units and zero offsets, and offsets are never printed (they are already applied).
#pragma once
#include "ir/MotionIR.h"

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace ncc {

class CanonTraceWriter : public MotionSink {
public:
  // Writes to `out` (not closed). Output is buffered; finish() flushes (the destructor too when
  // finish() was not called); records after finish() are ignored.
  explicit CanonTraceWriter(std::FILE *out);
  ~CanonTraceWriter() override;
  void record(const MotionRecord &r) override;
  // Ends the trace like rs274's driver (two ON_RESET() lines) and flushes. Returns false when
  // the stream reports a write error.
  bool finish(Diagnostics &diags) override;
  // Writes the buffered text to the stream.
  bool flush();

private:
  // Every record but the common one, a straight move outside a thread (record() does that one).
  void other(const MotionRecord &r);
  // Lines are formatted straight into buf_: begin() writes the "%5d N..... " prefix where the
  // line goes and end() the newline. room() makes space for n characters when the buffer is full
  // (writes it out, grows it for a huge line) and returns where they go.
  char *room(size_t n);
  char *begin(int64_t blockNumber, size_t n);  // the prefix, with room for n characters after it
  void end(char *p);
  void writeOut();
  void line(int64_t blockNumber, std::string_view text);
  void numLine(int64_t blockNumber, std::string_view name, double v);  // NAME(%.4f)
  // A move's positions, ", "-separated %.4f: a column whose value is bit for bit the last one
  // written there (the axes that did not move) copies that text instead of formatting it again.
  char *axes(char *p, const double *v, int n);
  void preamble();
  void epilogue(const MotionRecord &r);
  // Thread records: rs274's START_SPEED_FEED_SYNC(k,0) before a new synchronisation or a lead
  // change, STOP_SPEED_FEED_SYNCH() when the synchronised run ends.
  void thread(const MotionRecord &r);
  void stopSync(int64_t blockNumber);

  std::FILE *out_;
  std::vector<char> buf_;  // its size is the capacity; len_ characters are in use
  size_t len_ = 0;
  // The line counter as "%5d" text, counted up in place: the digits end at seq_ + kSeqEnd. The
  // bytes after them are there so that begin() copies sixteen at a time.
  static constexpr int kSeqEnd = 24;
  char seq_[kSeqEnd + 16];
  int seqFirst_ = 19;
  struct Column {
    uint64_t bits = 0;  // of the double last formatted; +0.0 to start with
    size_t len = 6;
    char text[16] = "0.0000";  // copied whole (fixed size): the bytes past len do not matter
  };
  Column columns_[kAxes];
  int64_t lastBlock_ = -1;  // the N column of the last prefix, kept as text (copied 24 bytes at a time)
  char blockCol_[32];
  size_t blockColLen_ = 0;
  bool started_ = false, finished_ = false, ioError_ = false;
  bool halted_ = false;  // a record it cannot write (tilted arc) stopped the trace
  Plane plane_ = Plane::XY;
  bool flood_ = false, mist_ = false;
  bool sync_ = false;       // inside a spindle-synchronised run
  double syncLead_ = 0;     // its lead along the path (mm/rev)
  int64_t syncBlock_ = -1;  // the block of its last record (STOP carries it)
  // rs274's G76 (a cycle_begin "rs274.G76") disables feed override around each pass: DISABLE
  // before the pass's first START, ENABLE after the traverse out that follows its STOP.
  bool inG76_ = false, enableAfterMove_ = false;
  TiltedArcCheck tilted_{"the canonical trace (rs274 ARC_FEED)"};
  // A variable-lead thread (808D G34) has no rs274 command: the trace stops there and finish()
  // reports it, as for a tilted arc.
  bool variableLead_ = false;
  MotionRecord variableLeadRecord_;
};

}  // namespace ncc
