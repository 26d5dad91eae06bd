M98 P7001
G65 P7002 X5
M98 P7001 L2
M30
%
; FEATURES: ISO-M-03 ISO-LEX-08
; Subprograms not in the main file are loaded from the main file's directory: 7001.mpf,
; O7002.nc (candidates O<n>.nc, <n>.nc, O<n>.ngc, <n>.mpf, <n>.spf, zero-padded to 4 digits).
; RUN: rm -rf %t && mkdir -p %t && cp %s %t/main.nc && cp %S/Inputs/7001.mpf %S/Inputs/O7002.nc %t/
; RUN: %ncc compile %t/main.nc --emit=ir | FileCheck %s
; CHECK: func @main
; CHECK: call callee="O7001" count=1 frame=shared
; CHECK: call callee="O7002" count=1 frame=new a.24=5
; CHECK: call callee="O7001" count=2 frame=shared
; CHECK-DAG: func @O7001 loc(2:1:1)
; CHECK-DAG: func @O7002
