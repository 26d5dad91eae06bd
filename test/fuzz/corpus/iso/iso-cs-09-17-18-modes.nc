G17
G18
G19
G90
G91 X10.
G20
G21
%
; FEATURES: ISO-CS-09 ISO-CS-17 ISO-CS-18
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: mode plane=xy loc(1:1:1)
; CHECK: mode plane=zx loc(1:2:1)
; CHECK: mode plane=yz loc(1:3:1)
; CHECK: mode distance=absolute loc(1:4:1)
; CHECK: mode distance=incremental loc(1:5:1)
; CHECK-NEXT: move X=10.0
; CHECK: mode units=inch loc(1:6:1)
; CHECK: mode units=mm loc(1:7:1)
