N5 G00 X100. /3 Y100
/3 N6 X7
N7 G00 X100. (/3 part 1) Y100
/ N8 X8
/1 N9 X9
%
; FEATURES: ISO-LEX-05
; Without active skip levels every `/` block runs; a leading `/n` is kept as block skip=n.
; With level 3 active the block from `/3` on is cut, even mid-block, and `/` inside a comment
; is not a skip. `/` (level 0) and `/1` are different levels.
; RUN: %ncc compile %s --emit=ir | FileCheck %s --check-prefix=OFF
; RUN: %ncc compile %s --emit=ir --block-delete 3 | FileCheck %s --check-prefix=ON3
; RUN: %ncc compile %s --emit=ir --block-delete 0 | FileCheck %s --check-prefix=ON0
; OFF: block n=5
; OFF-NEXT: mode motion=rapid
; OFF-NEXT: move X=100.0 Y=100
; OFF-NEXT: block n=6 skip=3
; OFF-NEXT: move X=7
; OFF: block n=8 skip=0
; OFF: block n=9 skip=1
; ON3: block n=5
; ON3-NEXT: mode motion=rapid
; ON3-NEXT: move X=100.0 loc
; ON3-NEXT: block n=7
; ON3-NEXT: comment text="/3 part 1"
; ON3-NEXT: mode motion=rapid
; ON3-NEXT: move X=100.0 Y=100
; ON3-NEXT: block n=8 skip=0
; ON3-NOT: n=6
; ON0: block n=6 skip=3
; ON0-NOT: n=8
; ON0: block n=9 skip=1
