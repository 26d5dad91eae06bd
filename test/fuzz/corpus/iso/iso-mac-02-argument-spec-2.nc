G65 P9100 A10. C20. X30. Z40. I50. K60. J70. I80.
G65 P9100 I1 J2 K3 J4 K5 I6 K7
M30
O9100
M99
%
; (Fanuc locals, not the 808D $C_ variables of ISO-MAC-02)
; Fanuc argument specification II: repeated I/J/K form up to 10 sets, set s (0-based) going to
; #4+3s / #5+3s / #6+3s; a set ends when an address repeats or comes out of I-J-K order
; (the set-splitting rule of spec L4585-4626: I50 K60 | J70 | I80).
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: call callee="O9100" count=1 frame=new a.1=10.0 a.3=20.0 a.24=30.0 a.26=40.0 a.4=50.0 a.6=60.0 a.8=70.0 a.10=80.0 loc(1:1:1)
; CHECK: call callee="O9100" count=1 frame=new a.4=1 a.5=2 a.6=3 a.8=4 a.9=5 a.10=6 a.12=7 loc(1:2:1)
