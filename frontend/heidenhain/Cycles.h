// The Heidenhain cycles: which act where they are defined. Their parameters come from the cycle
// library (FrontendOptions::cycles: the `hei.*` entries of `ncc cycle --list`).
#pragma once
#include "ir/NCIR.h"

namespace ncc::hei {

// Acts where it is defined (220, 221, transformations, SL data, probing …), digest §3.0.
bool defActiveCycle(int number);
// `cycle action=call`: runs the stored cycle here (CYCL CALL, M99).
ir::Op cycleCall(SourceLoc l);

}  // namespace ncc::hei
