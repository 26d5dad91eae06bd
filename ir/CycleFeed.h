// Cycle feeds written as keywords (Heidenhain `Q208=FMAX`, `Q206=FU0.2`, `Q207=FZ0.05`; manual
// L566-L579, docs/HEIDENHAIN.md "Cycle parameter values"). The `cycle` op's arguments are
// numbers, so a front end lowers a keyword feed to a code in the argument's number and the
// executor resolves it where the cycle runs (runtime/cycles/CycleFeed.h): FMAX stays kRapid and
// its moves are traverses; FU f and FZ f become mm/min with the spindle speed and the tool's
// teeth of the call. The manual's feeds lie in 0 … 99999.999: no number written as a feed is a code.
#pragma once

namespace ncc::cyclefeed {

constexpr double kRapid = 1e9;      // FMAX
constexpr double kPerRev = -1e6;    // FU f: kPerRev - f
constexpr double kPerTooth = -2e6;  // FZ f: kPerTooth - f
constexpr double kBand = 1e6;       // the width of each FU/FZ band

}  // namespace ncc::cyclefeed
