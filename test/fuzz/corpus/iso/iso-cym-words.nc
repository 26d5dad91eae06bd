G21 G90 G17 F100 S500 M3
G81 X1 Y1 Z-1 R1 P2
G82 X1 Y1 Z-1 R1 Q2 P0.5
G83 X1 Y1 Z-1 R1 P2 Q0.5
G73 X1 Y1 Z-1 R1 Q0.5 K2
G85 X1 Y1 Z-1 R1 I1
G84 X1 Y1 Z-1 R1 P500
M2
%
; FEATURES: ISO-CYM-01
; Each canned cycle reads only its own parameter words (808D tables 2-14..2-25): a P or Q the
; cycle does not read, or an I/J, is an error, never quietly dropped. K is the repeat count.
; RUN: not %ncc compile %s --emit=ir 2>&1 | FileCheck %s
; CHECK: iso-cym-words.nc:2:18: error: P word is not used by any code of this block [unused-word]
; CHECK: iso-cym-words.nc:3:18: error: Q word is not used by any code of this block [unused-word]
; CHECK: iso-cym-words.nc:4:18: error: P word is not used by any code of this block [unused-word]
; CHECK-NOT: iso-cym-words.nc:5:
; CHECK: iso-cym-words.nc:6:18: error: I word is not used by any code of this block [unused-word]
; CHECK-NOT: iso-cym-words.nc:7:
; The same blocks as RS274NGC: G84 has no dwell and K is no repeat count in rs274.
; RUN: cp %s %t.ngc
; RUN: not %ncc compile %t.ngc --emit=ir 2>&1 | FileCheck %s --check-prefix=NGC
; NGC: :2:18: error: P word is not used by any code of this block [unused-word]
; NGC: :5:{{[0-9]+}}: error: K word is not used by any code of this block [unused-word]
; NGC: :7:18: error: P word is not used by any code of this block [unused-word]
