G65 P9010 L2 A1. B-2 C#3 D4 E5 F6 H7 I8 J9 K10 M11 Q12 R13 S14 T15 U16 V17 W18 X19 Y20 Z[1+2]
G65 P9010
M30
O9010
#100 = #1 + #24
M99
%
; FEATURES: ISO-MAC-01 ISO-MAC-08
; G65 P<program> L<count> with Fanuc argument specification I: A=#1 B=#2 C=#3 I=#4 J=#5 K=#6
; D=#7 E=#8 F=#9 H=#11 M=#13 Q=#17 R=#18 S=#19 T=#20 U=#21 V=#22 W=#23 X=#24 Y=#25 Z=#26.
; Arguments keep their values (no decimal-point scaling) and are not executed as words.
; RUN: %ncc compile %s --emit=ir --decimal-mode=is-b | FileCheck %s
; CHECK: call callee="O9010" count=2 frame=new a.1=1.0 a.2=-2 a.3=#3 a.7=4 a.8=5 a.9=6 a.11=7 a.4=8 a.5=9 a.6=10 a.13=11 a.17=12 a.18=13 a.19=14 a.20=15 a.21=16 a.22=17 a.23=18 a.24=19 a.25=20 a.26=(add 1 2) loc(1:1:1)
; CHECK-NEXT: block
; CHECK-NEXT: call callee="O9010" count=1 frame=new loc(1:2:1)
; CHECK: func @O9010
; CHECK: assign target=#100 value=(add #1 #24)
; CHECK: return
