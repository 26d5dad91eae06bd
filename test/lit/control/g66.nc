G21 G90 G0 X0 Y0
G66 P9100 Z-5 F100
X10
X20
G67
X30
M30
O9100
G1 Z#26 F#9
G0 Z0
M99
%
; FEATURES: ISO-MAC-04
; Fanuc/808D G66 P<program> [L<count>] <arguments>: a modal macro call (L times), executed after each following block
; with axis motion with the G66 block's arguments (as G65: Z -> #26, F -> #9); the macro's own
; moves do not call it again; G67 cancels it. Lowered to `modal_call` (docs/IR.md §5.5). Both
; engines, identical output.
; RUN: %ncc compile --emit=motion --engine=eval %s > %t.e
; RUN: %ncc compile --emit=motion --engine=jit %s > %t.j
; RUN: diff %t.e %t.j
; RUN: FileCheck %s < %t.j
; RUN: %ncc compile --emit=ir %s | FileCheck %s --check-prefix=IR
; IR: modal_call callee="O9100" count=1 a.26=-5 a.9=100 loc(1:2:1)
; IR: modal_call loc(
; CHECK: rapid X10 Y0 Z0 A0 B0 C0
; CHECK-NEXT: feed_rate 100
; CHECK-NEXT: linear X10 Y0 Z-5 A0 B0 C0 F100
; CHECK-NEXT: rapid X10 Y0 Z0 A0 B0 C0
; CHECK-NEXT: rapid X20 Y0 Z0 A0 B0 C0
; CHECK-NEXT: feed_rate 100
; CHECK-NEXT: linear X20 Y0 Z-5 A0 B0 C0 F100
; CHECK-NEXT: rapid X20 Y0 Z0 A0 B0 C0
; CHECK-NEXT: rapid X30 Y0 Z0 A0 B0 C0
; CHECK-NEXT: program_end
; G66 L2: two calls after each move.
; RUN: sed -e 's/^G66 P9100 Z-5 F100/G66 P9100 L2 Z-5 F100/' %s > %t.l.nc
; RUN: %ncc compile --emit=motion --engine=eval %t.l.nc > %t.le
; RUN: %ncc compile --emit=motion --engine=jit %t.l.nc > %t.lj
; RUN: diff %t.le %t.lj
; RUN: FileCheck %s --check-prefix=L < %t.lj
; L: rapid X10 Y0 Z0 A0 B0 C0
; L-NEXT: feed_rate 100
; L-NEXT: linear X10 Y0 Z-5 A0 B0 C0 F100
; L-NEXT: rapid X10 Y0 Z0 A0 B0 C0
; L-NEXT: feed_rate 100
; L-NEXT: linear X10 Y0 Z-5 A0 B0 C0 F100
; L-NEXT: rapid X10 Y0 Z0 A0 B0 C0
; L-NEXT: rapid X20 Y0 Z0 A0 B0 C0
; RUN: sed -e 's/^G66 P9100 Z-5 F100/G66 G0 P9100 Z-5/' %s > %t.g.nc
; RUN: not %ncc run %t.g.nc 2>&1 | FileCheck %s --check-prefix=G
; G: error: G66 must not share its block with other G codes
