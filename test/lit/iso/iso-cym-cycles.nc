G17 G90 G98
G81 X10 Y10 Z-5 R1 F100
G82 X20 Z-5 R1 P500
G83 X30 Z-10 R1 Q2
G73 X40 Z-10 R1 Q2
G84 X50 Z-10 R1 P300
G74 X60 Z-10 R1
G85 X70 Z-10 R1
G86 X80 Z-10 R1
G87 X90 Z-10 R1 Q1 P100
G89 X100 Z-10 R1 P200
G76 X110 Z-10 R1 Q1 P50
G99 G81 X1 Y1 Z-1 R1 K0
G91 Y-20. K2
Y-500.
G80
G90 G1 X0
%
; FEATURES: ISO-CYM-01 ISO-CYM-02 ISO-CYM-03 ISO-CYM-04 ISO-CYM-05 ISO-CYM-06 ISO-CYM-08
; FEATURES: ISO-CYM-09 ISO-CYM-10 ISO-CYM-11 ISO-CYM-12 ISO-CYM-13 ISO-CYM-14 ISO-CYM-15 ISO-CYM-16
; FEATURES: ISO-CYT-15
; Milling canned cycles: the motion mode names, the cycle words (dwell P in seconds: Fanuc P
; is milliseconds), K repeats become L, G98/G99 return level, modal repetition, G80 cancel
; (cycle_cancel: the G0-G3 mode before the cycle resumes, as on Fanuc; iso-cym-15-g80-resume.nc).
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: mode retract=retract_initial
; CHECK: mode motion=drill loc(1:2:1)
; CHECK-NEXT: move X=10 Y=10 Z=-5 R=1
; CHECK: mode motion=drill_dwell
; CHECK-NEXT: move X=20 Z=-5 R=1 P=0.5
; CHECK: mode motion=peck
; CHECK-NEXT: move X=30 Z=-10 R=1 Q=2
; CHECK: mode motion=peck_chipbreak
; CHECK-NEXT: move X=40 Z=-10 R=1 Q=2
; CHECK: mode motion=tap
; CHECK-NEXT: move X=50 Z=-10 R=1 P=0.3
; CHECK: mode motion=tap_left
; CHECK-NEXT: move X=60 Z=-10 R=1
; CHECK: mode motion=bore_feed
; CHECK: mode motion=bore_stop
; CHECK: mode motion=bore_back
; CHECK-NEXT: move X=90 Z=-10 R=1 P=0.1 Q=1
; CHECK: mode motion=bore_dwell
; CHECK-NEXT: move X=100 Z=-10 R=1 P=0.2
; CHECK: mode motion=bore_fine
; CHECK-NEXT: move X=110 Z=-10 R=1 P=0.05 Q=1
; CHECK: mode retract=retract_r
; CHECK-NEXT: mode motion=drill
; CHECK-NEXT: move X=1 Y=1 Z=-1 R=1 L=0
; CHECK: mode distance=incremental
; CHECK-NEXT: move Y=-20.0 L=2
; CHECK-NEXT: block
; CHECK-NEXT: move Y=-500.0
; CHECK-NEXT: block
; CHECK-NEXT: mode motion=cycle_cancel
; CHECK-NEXT: block
