; FEATURES: HEI-LBL-01 HEI-LBL-02 HEI-LBL-03 HEI-FLOW-01 HEI-FLOW-02 HEI-FLOW-03 HEI-FLOW-04 HEI-PGM-08 HEI-QP-05 HEI-PGM-10
; Labels and calls: subprograms LBL n … LBL 0 after the program's end (CALL LBL, nested), a
; program-section repeat CALL LBL n REP m (the section runs m more times), named labels, and
; CALL PGM of a program found in this program's folder (Inputs/), with its own QL parameters
; and the caller's Q parameters; STOP and M0 stop the run for the operator, M1 is optional.
; RUN: %ncc compile --emit=motion --engine=eval %s --include=%S/Inputs > %t.e
; RUN: %ncc compile --emit=motion --engine=jit %s --include=%S/Inputs > %t.j
; RUN: diff %t.e %t.j
; RUN: FileCheck %s < %t.e
; The NC IR text (sections, the called program's function, the QL array) reads back alike:
; RUN: %ncc compile --emit=ir %s --include=%S/Inputs -o %t.ncir
; RUN: %ncc compile --emit=motion %t.ncir | FileCheck %s
; Subprograms after M2 are reached by their labels: lint finds no dead code (nor at END PGM).
; RUN: %ncc lint %s --include=%S/Inputs 2>&1 | FileCheck %s --check-prefix=LINT --allow-empty
; LINT-NOT: warning
; CHECK: rapid X1 Y0 Z0 {{.*}} N12
; CHECK-NEXT: rapid X2 Y0 Z0 {{.*}} N15
; CHECK-NEXT: rapid X1 Y0 Z0 {{.*}} N12
; CHECK-NEXT: rapid X3 Y0 Z0 {{.*}} N4
; The section LBL 5 … CALL LBL 5 REP 2 runs three times:
; CHECK-NEXT: rapid X4 Y1 Z0 {{.*}} N6
; CHECK-NEXT: rapid X4 Y2 Z0 {{.*}} N6
; CHECK-NEXT: rapid X4 Y3 Z0 {{.*}} N6
; CALL PGM SUB1 twice: QL1 starts at 0 in each, Q1 goes on from the caller's 3.
; CHECK-NEXT: comment "QL1 is this program's own
; CHECK-NEXT: rapid X5 Y4 Z0 {{.*}} N4
; CHECK-NEXT: comment
; CHECK-NEXT: rapid X5 Y5 Z0 {{.*}} N4
; CHECK-NEXT: program_stop {{.*}} N10
; CHECK-NEXT: program_stop {{.*}} N11
; CHECK-NEXT: optional_stop {{.*}} N12
; CHECK-NEXT: program_end 2
; RUN: printf '0 BEGIN PGM E MM\n1 CALL LBL 9\n2 CALL LBL 0\n3 CALL LBL 4 REP 2\n4 LBL 4\n5 LBL 4\n6 CALL LBL 3\n7 LBL 3\n8 CALL LBL 3\n9 LBL 0\n10 CALL PGM NOWHERE\n11 CALL PGM ENDS\n12 LBL 6\n13 END PGM E MM\n' > %t.err.h
; RUN: not %ncc compile --emit=ir %t.err.h --include=%S/Inputs 2>&1 | FileCheck %s --check-prefix=ERR
; ERR: err.h:3:12: error: LBL 0 ends a subprogram: it cannot be called or jumped to [syntax]
; ERR: err.h:6:7: error: LBL 4 is defined twice [syntax]
; ERR: err.h:11:13: error: program NOWHERE not found (searched {{.*}}Inputs for NOWHERE.h) [missing-subprogram]
; ERR: ENDS.h:2:17: error: M30 in a program called by CALL PGM (the called program must not end the run) [program-frame]
; ERR: err.h:2:12: error: CALL LBL to LBL9 that is not defined in this program [missing-block]
; ERR: err.h:4:12: error: CALL LBL … REP repeats the section above it: the label must come before the call [syntax]
; ERR: err.h:9:12: error: CALL LBL inside the subprogram it calls [syntax]
; A broken LBL 0 is no section end (a crash the fuzzer found):
; RUN: printf '0 BEGIN PGM E MM\n1 CALL LBL 1\n2 LBL 1\n3 LBL 0 X\n4 END PGM E MM\n' > %t.lbl0.h
; RUN: not %ncc compile --emit=ir %t.lbl0.h 2>&1 | FileCheck %s --check-prefix=LBL0
; LBL0: lbl0.h:4:9: error: unexpected 'X' after LBL [syntax]
; LBL0: lbl0.h:2:12: error: the subprogram has no LBL 0 after its label (a section repeat needs REP) [syntax]
0 BEGIN PGM LABELS MM
1 L X+0 Y+0 Z+0 R0 FMAX
2 CALL LBL 1
3 CALL LBL "TWO"
4 L X+3 R0 FMAX
5 LBL 5
5 Q1 = Q1 + 1
6 L X+4 Y+Q1 R0 FMAX
7 CALL LBL 5 REP 2/2
8 CALL PGM SUB1
9 CALL PGM TNC:\DIR\SUB1.H
10 STOP
11 M0
12 M1
13 M2
11 LBL 1
12 L X+1 R0 FMAX
13 LBL 0
14 LBL "TWO"
15 L X+2 R0 FMAX
16 CALL LBL 1
17 LBL 0
18 END PGM LABELS MM
