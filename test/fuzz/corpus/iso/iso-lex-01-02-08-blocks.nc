%
(a comment line before the program number)
O0012
N10 G01 X10. Z5. F0.2;
n020 g0 x1 z2 ;
N030
;
G1 X3
%
; FEATURES: ISO-LEX-01 ISO-LEX-02 ISO-LEX-08
; Blocks are lines; a trailing `;` is the Fanuc end of block; N words become `block n=`;
; a leading `%` and the O-number line are accepted; text after the closing `%` is ignored.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: func @main
; CHECK-NEXT: block loc(1:2:1)
; CHECK-NEXT: comment text="a comment line before the program number"
; CHECK-NEXT: block n=10 loc(1:4:1)
; CHECK-NEXT: feed value=0.2
; CHECK-NEXT: mode motion=linear
; CHECK-NEXT: move X=10.0 Z=5.0
; CHECK-NEXT: block n=20 loc(1:5:1)
; CHECK-NEXT: mode motion=rapid
; CHECK-NEXT: move X=1 Z=2
; CHECK-NEXT: block n=30 loc(1:6:1)
; CHECK-NEXT: block loc(1:8:1)
; CHECK-NEXT: mode motion=linear
; CHECK-NEXT: move X=3
; CHECK-NEXT: }
; CHECK-NOT: func
