G04 X1.5
G4 P1500
G4 P1.5
G4 U2.
G4 P#1
%
; FEATURES: ISO-DWL-01
; G04: X/U in seconds, P in internal units (milliseconds) unless written with a point.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: dwell seconds=1.5 loc(1:1:1)
; CHECK-NOT: move
; CHECK: dwell seconds=1.5 loc(1:2:1)
; CHECK: dwell seconds=1.5 loc(1:3:1)
; CHECK: dwell seconds=2.0 loc(1:4:1)
; CHECK: dwell seconds=(div #1 1000) loc(1:5:1)
