G0 X0 Y0 Z10
POPEN
DPRNT[X#5001[53]]
BPRNT[X#5001[53]]
PCLOS
M30
; Fanuc Macro B external output (POPEN, DPRNT, BPRNT, PCLOS, issue 7 part 3) is not written
; anywhere yet: each is a located error naming it, not an unknown word.
; RUN: not %ncc run %s -q 2>&1 | FileCheck %s
; CHECK: fanuc-macro-output-refused.nc:2:1: error: POPEN (Fanuc Macro B data output) is not supported [unsupported-code]
; CHECK: fanuc-macro-output-refused.nc:3:1: error: DPRNT (Fanuc Macro B data output) is not supported [unsupported-code]
; CHECK: fanuc-macro-output-refused.nc:4:1: error: BPRNT (Fanuc Macro B data output) is not supported [unsupported-code]
; CHECK: fanuc-macro-output-refused.nc:5:1: error: PCLOS (Fanuc Macro B data output) is not supported [unsupported-code]
