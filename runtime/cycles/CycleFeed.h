// Resolving the keyword feeds of a library cycle's arguments (the codes: ir/CycleFeed.h) where
// the cycle runs, before the entry sees them:
//  - FMAX stays the code kRapid. An entry listed in CycleFeed.cpp passes such a feed straight to
//    its moves, and the executor makes a step at kRapid a traverse (runSteps); elsewhere refused.
//  - FU f (mm/rev) becomes f x S mm/min, FZ f (mm/tooth) f x teeth x S (the tool table's `teeth`,
//    the TNC's CUT column); without a spindle speed or the teeth the call is an error.
#pragma once
#include "ir/CycleFeed.h"
#include "runtime/cycles/Library.h"

#include <string>

namespace ncc::cyclefeed {

// The tool data the FU/FZ conversion needs, at the call.
struct Spindle {
  double speed = 0;  // rpm
  int teeth = 0;     // of the tool in the spindle (0: not in the tool table)
};

// Replaces the FU/FZ codes in the feed parameters of `def` by mm/min and checks that FMAX appears
// only where the entry moves at it unchanged. False with the reason in err (an entry::unsupported
// message for FMAX where it is not honoured).
bool resolve(const CycleDef &def, CycleArgs &args, const Spindle &s, std::string &err);

}  // namespace ncc::cyclefeed
