G93 G1 X100 F2
G94 F1500
G95 F0.3
G61
G61.1
G64 P0.01
%
; FEATURES: ISO-FEED-02 ISO-FEED-03 ISO-FEED-05
; Feed mode comes before F, F before motion; G61/G61.1/G64 path modes (G64 P = tolerance).
; RUN: %ncc compile %s --emit=ir 2>&1 | FileCheck %s
; CHECK-NOT: warning
; CHECK: block loc(1:1:1)
; CHECK-NEXT: mode feed_mode=inverse_time
; CHECK-NEXT: feed value=2
; CHECK-NEXT: mode motion=linear
; CHECK-NEXT: move X=100
; CHECK: mode feed_mode=per_minute loc(1:2:1)
; CHECK-NEXT: feed value=1500
; CHECK: mode feed_mode=per_rev loc(1:3:1)
; CHECK-NEXT: feed value=0.3
; CHECK: mode path_mode=exact_path loc(1:4:1)
; CHECK: mode path_mode=exact_stop loc(1:5:1)
; CHECK: mode path_mode=continuous tolerance=0.01 loc(1:6:1)
