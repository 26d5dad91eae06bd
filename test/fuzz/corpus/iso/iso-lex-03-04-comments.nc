N5 (comment) X100 Y100
N10 (comment (comment)) X100 Y100
N15 (comment (comment) X100) Y100
G0 X1 ; rest of line
(MSG, Insert tool 3)
N20 (first)(second) X2
%
; FEATURES: ISO-LEX-03 ISO-LEX-04
; Round-bracket comments nest: the comment ends when all brackets are closed (spec L350-361).
; `;` starts a comment to the end of the line. (MSG, ...) is an operator message.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: block n=5
; CHECK-NEXT: comment text="comment" loc(1:1:4)
; CHECK-NEXT: move X=100 Y=100
; CHECK-NEXT: block n=10
; CHECK-NEXT: comment text="comment (comment)"
; CHECK-NEXT: move X=100 Y=100
; CHECK-NEXT: block n=15
; CHECK-NEXT: comment text="comment (comment) X100"
; CHECK-NEXT: move Y=100
; CHECK-NEXT: block
; CHECK-NEXT: comment text="rest of line"
; CHECK-NEXT: mode motion=rapid
; CHECK-NEXT: move X=1
; CHECK-NEXT: block
; CHECK-NEXT: message text="Insert tool 3"
; CHECK-NEXT: block n=20
; CHECK-NEXT: comment text="first"
; CHECK-NEXT: comment text="second"
; CHECK-NEXT: move X=2
