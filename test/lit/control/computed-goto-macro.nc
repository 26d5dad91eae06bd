G21 G90 G1 F100
#1=0
#2=30
N10 #1=#1+1
X#1
IF [#1 LT 3] GOTO [#2-20]
GOTO #2
N20 X99
N30 Y5
M30
%
; FEATURES: ISO-MAC-08
; Macro B `GOTO #n` and `IF [...] GOTO [expr]` jump to the block number the value gives, at run
; time, in both engines; a block number that does not exist is a run-time error at the GOTO.
; RUN: %ncc compile --emit=motion --engine=eval %s > %t.e
; RUN: %ncc compile --emit=motion --engine=jit %s > %t.j
; RUN: diff %t.e %t.j
; RUN: FileCheck %s < %t.j
; CHECK: linear X1 Y0 Z0
; CHECK-NEXT: linear X2 Y0 Z0
; CHECK-NEXT: linear X3 Y0 Z0
; CHECK-NEXT: linear X3 Y5 Z0
; CHECK-NEXT: program_end
; RUN: sed -e 's/#2=30/#2=35/' %s > %t.miss.nc
; RUN: not %ncc run %t.miss.nc --engine=eval 2>&1 | FileCheck %s --check-prefix=MISS
; RUN: not %ncc run %t.miss.nc --engine=jit 2>&1 | FileCheck %s --check-prefix=MISS
; MISS: computed-goto-macro.nc.tmp.miss.nc:{{[0-9]+}}:1: error: jump to missing sequence number N15
; MISS-NEXT: IF [#1 LT 3] GOTO [#2-20]
; MISS-NEXT: {{^}}^
