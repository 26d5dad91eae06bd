G1 X1 Y2 Z3 A4 B5 C6 U7 V8 W9
g1 x-1.5 y+2 z.5
%
; FEATURES: ISO-LEX-07
; The nine axis addresses; lower case is accepted; signs and leading/trailing points.
; A machine with A B C (on one without B, a .nc B is the 808D auxiliary function: ISO-M-06).
; RUN: %ncc compile %s --emit=ir --machine=%S/../oracle/Inputs/oracle.toml | FileCheck %s
; CHECK: move X=1 Y=2 Z=3 A=4 B=5 C=6 U=7 V=8 W=9 loc(1:1:1)
; CHECK: move X=-1.5 Y=2 Z=0.5 loc(1:2:1)
