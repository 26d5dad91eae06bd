G90 G0 X0 Y0 Z10
G1 F200
G31 G91 X100. F100
#100=#5061
X5.
G90 G31 Z-20.
X#100 Y#5063
G0
G31 X0 F50
X1.
M30
; FEATURES: ISO-MEAS-01
; G31 (808D L9398-9501): a one-shot linear move at F that stops where the measuring input
; switches (the probe-results file), the point in #5061-#5066 (Fanuc skip position, work
; coordinates); an incremental move after it starts from the measured point; a skip that does
; not switch ends at its target without an alarm; the group-01 mode (G1, G0) comes back.
; RUN: %ncc compile %s --emit=ir | FileCheck %s --check-prefix=IR
; IR: block loc(1:3:1)
; IR-NEXT: feed value=100 
; IR-NEXT: mode distance=incremental
; IR-NEXT: mode motion=skip loc(1:3:1)
; IR-NEXT: move X=100.0 loc(1:3:1)
; IR-NEXT: mode motion=linear loc(1:3:1)
; RUN: %ncc run %s --probe-results=%S/Inputs/iso-meas-01-g31.probe --trace=canon | FileCheck %s
; RUN: %ncc run %s --probe-results=%S/Inputs/iso-meas-01-g31.probe --trace=canon --engine=jit | FileCheck %s
; CHECK: TURN_PROBE_ON()
; CHECK-NEXT: STRAIGHT_PROBE(100.0000, 0.0000, 10.0000,
; CHECK-NEXT: TURN_PROBE_OFF()
; CHECK-NEXT: STRAIGHT_FEED(47.5000, 0.0000, 10.0000,
; CHECK-NEXT: TURN_PROBE_ON()
; CHECK-NEXT: STRAIGHT_PROBE(47.5000, 0.0000, -20.0000,
; CHECK-NEXT: TURN_PROBE_OFF()
; CHECK-NEXT: STRAIGHT_FEED(42.5000, -20.0000, -20.0000,
; CHECK: STRAIGHT_TRAVERSE(1.0000, -20.0000, -20.0000,
