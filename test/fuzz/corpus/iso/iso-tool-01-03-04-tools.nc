T0202
T11 M6
M6 T3
G43 Z-20. H10
G49
G41 G1 X10 D01
G42 X20 D2
G40 X0
G43 H0
%
; FEATURES: ISO-TOOL-01 ISO-TOOL-03 ISO-TOOL-04 ISO-M-07
; T select, M6 change (T before M6 whatever the word order), G43 H / G49 length
; compensation, G41/G42 D / G40 radius compensation.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: tool_select value=202 loc(1:1:1)
; CHECK: tool_select value=11
; CHECK-NEXT: tool_change loc(1:2:5)
; CHECK: tool_select value=3 loc(1:3:4)
; CHECK-NEXT: tool_change loc(1:3:1)
; CHECK: tool_length h=10 loc(1:4:1)
; CHECK-NEXT: move Z=-20.0
; CHECK: tool_length h=0 loc(1:5:1)
; CHECK: cutter_comp side=left d=1
; CHECK-NEXT: mode motion=linear
; CHECK-NEXT: move X=10
; CHECK: cutter_comp side=right d=2
; CHECK-NEXT: move X=20
; CHECK: cutter_comp side=off loc(1:8:1)
; CHECK-NEXT: move X=0
; CHECK: tool_length h=0 loc(1:9:1)
