// The touch-probe cycles' builders (ProbeGen.cpp: the table, 0, 400-404; ProbeDatum.cpp: 408-419;
// ProbeMeasure.cpp: 420-431) and the sequences more than one of them probes.
#pragma once
#include "frontend/heidenhain/ProbeSteps.h"

namespace ncc::hei::probe {

bool cycle408(ProbeCall &c);
bool cycle409(ProbeCall &c);
bool cycle410(ProbeCall &c);
bool cycle411(ProbeCall &c);
bool cycle412(ProbeCall &c);
bool cycle413(ProbeCall &c);
bool cycle414(ProbeCall &c);
bool cycle416(ProbeCall &c);
bool cycle417(ProbeCall &c);
bool cycle418(ProbeCall &c);
bool cycle419(ProbeCall &c);
bool cycle420(ProbeCall &c);
bool cycle421(ProbeCall &c);
bool cycle422(ProbeCall &c);
bool cycle423(ProbeCall &c);
bool cycle424(ProbeCall &c);
bool cycle426(ProbeCall &c);
bool cycle427(ProbeCall &c);
bool cycle430(ProbeCall &c);
bool cycle431(ProbeCall &c);

// 400 and 420: two points on a line along ax1 (axis 1) or ax2 (2), probed across it (Q267).
void twoPointLine(Gen &g, int axis);
// 419 and 427: one probing at (Q263, Q264) along axis Q272 (1 X, 2 Y, 3 the probe axis, down onto
// Q261) in the direction Q267; the measured coordinate in M1. False after a located error.
bool onePoint(Gen &g, int &axis);
// The holes at the angles Q291-Q293 on the circle Q273/Q274 D Q262, each probed from its centre,
// and the circle through their centres in BCX, BCY, BDIA (416, 430).
void boltCircle(Gen &g);
// The intersection (<key>X, <key>Y) of the line through a1, a2 with the line through b1, b2
// (points named by their MX/MY or centre variables: "MX1"/"MY1" as {"MX1", "MY1"}).
struct PointVars {
  std::string x, y;
};
void intersect(Gen &g, const std::string &key, PointVars a1, PointVars a2, PointVars b1, PointVars b2);

}  // namespace ncc::hei::probe
