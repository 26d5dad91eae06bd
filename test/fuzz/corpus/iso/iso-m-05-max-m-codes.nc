M3 M8 M50 M51 M52
M3 M8 M50 M51 M52 M53
%
; FEATURES: ISO-M-05
; At most five M codes per block (L2613, L2750); free M numbers become `aux m=`.
; RUN: not %ncc compile %s --emit=ir 2>&1 | FileCheck %s
; CHECK-NOT: 1:{{[0-9]+}}: error
; CHECK: iso-m-05-max-m-codes.nc:2:19: error: more than 5 M codes in one block [too-many-m-codes]
; CHECK-NEXT: M3 M8 M50 M51 M52 M53
; CHECK-NEXT: {{^                  \^$}}
