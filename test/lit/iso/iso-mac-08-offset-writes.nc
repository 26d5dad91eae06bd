G21 G90 G17 G54
G0 X0 Y0
#5221=10
G0 X1
#5242=5
G0 X2
G55
G0 X3 Y0
#100=#5221+#5242
G0 X#100
M30
%
; FEATURES: ISO-MAC-08
; Fanuc: a written work offset (#5221+20(n-1) …) takes effect at once, also for the active
; system (offset_write "immediate", the default outside the linuxcnc, sinumerik and heidenhain
; families); both engines.
; RUN: %ncc run %s --trace=canon -o %t.eval
; RUN: FileCheck %s --input-file=%t.eval
; RUN: %ncc run %s --engine=jit --trace=canon -o %t.jit
; RUN: diff %t.eval %t.jit
; CHECK: STRAIGHT_TRAVERSE(0.0000, 0.0000,
; CHECK: STRAIGHT_TRAVERSE(11.0000, 0.0000,
; CHECK: STRAIGHT_TRAVERSE(12.0000, 0.0000,
; CHECK: STRAIGHT_TRAVERSE(3.0000, 5.0000,
; CHECK: STRAIGHT_TRAVERSE(15.0000, 5.0000,
; The motion IR marks the change of the active system's origin.
; RUN: %ncc compile %s --emit=motion | FileCheck %s --check-prefix=MOT
; MOT: frame_change "offset write"
