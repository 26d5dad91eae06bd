G0 X0 Y0 Z10
G54 P12
M30
; FEATURES: ISO-CS-03
; The 808D's G54 P1…P93 (extended work offsets) and G54 P0 (the external offset) are not in ncc's
; offset table (G54-G59): an error naming them, never G54 with the P word dropped.
; RUN: not %ncc run %s -q 2>&1 | FileCheck %s
; CHECK: iso-cs-03-g54-p-refused.nc:2:5: error: G54 P (the extended work offsets P1-P93, the external offset P0) is not supported [unsupported-code]
; RUN: printf 'G54 P0\nM30\n' > %t.nc
; RUN: not %ncc run %t.nc -q 2>&1 | FileCheck %s --check-prefix=P0
; P0: :1:5: error: G54 P (the extended
