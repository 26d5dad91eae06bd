G54
G55 G0 X1
G56
G57
G58
G59
G59.1
%
; FEATURES: ISO-CS-02
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: work_offset index=1 loc(1:1:1)
; CHECK: work_offset index=2 loc(1:2:1)
; CHECK-NEXT: mode motion=rapid
; CHECK-NEXT: move X=1
; CHECK: work_offset index=3
; CHECK: work_offset index=4
; CHECK: work_offset index=5
; CHECK: work_offset index=6
; CHECK: work_offset index=7
