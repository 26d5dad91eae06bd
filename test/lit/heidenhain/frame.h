; FEATURES: HEI-PGM-01 HEI-PGM-02 HEI-PGM-03 HEI-PGM-04 HEI-PGM-05 HEI-PGM-06 HEI-PGM-11 HEI-BLK-01 HEI-LNT-01 HEI-LNT-02
; The file frame: numbered blocks (gaps and duplicates are read), BEGIN PGM … END PGM with the
; unit, BLK FORM (kept as a comment, checked), `;` comments, `*` comment blocks, un-numbered and
; `~` continuation lines, a decimal comma read with a warning; the errors are located.
; RUN: %ncc compile --emit=motion --engine=eval %s --machine=%srcroot/examples/machines/heidenhain-tnc640-mill.toml > %t.e 2> %t.warn
; RUN: %ncc compile --emit=motion --engine=jit %s --machine=%srcroot/examples/machines/heidenhain-tnc640-mill.toml > %t.j
; RUN: diff %t.e %t.j
; RUN: FileCheck %s < %t.e
; RUN: FileCheck %s --check-prefix=WARN < %t.warn
; RUN: %ncc compile --emit=ir %s | FileCheck %s --check-prefix=IR
; IR: mode units=mm loc(1:32:3)
; IR: comment text="BLK FORM 0.1 Z X+0 Y+0 Z-20"
; IR: comment text="BLK FORM 0.2 X+100 Y+100 Y+0"
; IR: comment text="- a comment block"
; WARN: frame.h:40:7: warning: a decimal comma, read as a decimal point (the control writes '.') [lenient-syntax]
; WARN: frame.h:42:6: warning: a decimal comma
; WARN: frame.h:34:28: warning: BLK FORM 0.2 gives Y twice [blk-form]
; WARN: frame.h:34:12: warning: BLK FORM 0.2 leaves out Z [blk-form]
; Tool 1 of the machine is 119.99 long, G54 puts Z0 at -250: Z0 is Z-130.01 at the spindle.
; CHECK: comment "- a comment block" N3
; CHECK: tool_length 119.99 H1 N4
; CHECK: rapid X0 Y0 Z-130.01 A0 B0 C0 N4
; CHECK-NEXT: feed_rate 100 N7
; CHECK-NEXT: linear X12.5 Y2 Z-130.01 A0 B0 C0 F100 N7
; CHECK-NEXT: linear X25.5 Y2 Z-130.01 A0 B0 C0 F100 N8
; CHECK-NEXT: linear X25.5 Y4.25 Z-130.01 A0 B0 C0 F100 N9
; CHECK-NEXT: program_end 2 N10
; The German spelling of BEGIN is read, with a warning:
; RUN: printf '0 BEGINN PGM A MM\n1 END PGM A MM\n' > %t.beginn.h
; RUN: %ncc compile --emit=motion %t.beginn.h 2>&1 | FileCheck %s --check-prefix=BEGINN
; BEGINN: beginn.h:1:3: warning: BEGINN is the German spelling: the control writes BEGIN PGM [lenient-syntax]
0 BEGIN PGM FRAME MM
1 BLK FORM 0.1 Z X+0 Y+0 Z-20 ; the blank: minimum point
2 BLK FORM 0.2 X+100 Y+100 Y+0
3 * - a comment block
4 TOOL CALL 1 Z S3000
4 L X+0 Y+0 Z+0 R0 FMAX
7 L X+12.5 Y+2 ~
  F100
8 L X+25,5
9 L ~
  IY+2,25 ;a comment
10 M2
11 END PGM FRAME MM
