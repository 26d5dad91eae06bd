G0 X10 B1234
B56 M8
G1 X20 B7 F100
M30
; FEATURES: ISO-M-06
; 808D (manual L2752-2760): where B names no axis it is an auxiliary function, a PLC output as
; H1=<n>. On the default machine (X Y Z) B<n> is an aux record after the block's move, kept in
; the Motion IR and written back by the ISO emitter; never a B move.
; RUN: %ncc compile %s --emit=ir | FileCheck %s --check-prefix=IR
; IR: move X=10 loc(1:1:1)
; IR-NEXT: aux b=1234 loc(1:1:8)
; IR: coolant flood=on loc(1:2:5)
; IR-NEXT: aux b=56 loc(1:2:1)
; IR: move X=20 loc(1:3:1)
; IR-NEXT: aux b=7 loc(1:3:8)
; RUN: %ncc compile %s --emit=motion | FileCheck %s --check-prefix=MOTION
; MOTION: rapid
; MOTION-SAME: X10
; MOTION: aux B1234
; MOTION: aux B56
; MOTION: aux B7
; RUN: %ncc translate %s --to=iso | FileCheck %s --check-prefix=ISO
; ISO: B1234
; ISO: B56
; ISO: B7
; With a B axis B stays an axis word (and .ngc B is always an axis, as rs274).
; RUN: %ncc compile %s --emit=ir --machine=%S/../oracle/Inputs/oracle.toml | FileCheck %s --check-prefix=AXIS
; AXIS: move X=10 B=1234 loc(1:1:1)
; AXIS: move X=20 B=7 loc(1:3:1)
; A B with a point is no output number.
; RUN: printf 'B1.5\nM30\n' > %t.nc
; RUN: not %ncc run %t.nc -q 2>&1 | FileCheck %s --check-prefix=POINT
; POINT: error: aux code must be an integer
