G21 G90 G17
G10 L2 P1 X10 Y20
G54 G0 X1 Y2
T2 M6 S1200 F300
#1=#5041
#2=#5042
#3=#5021
#4=#5221
#5=#5242
#6=#4109
#7=#4119
#8=#4120
#9=#5001
IF [#3 NE 11] GOTO 900
IF [#4 NE 10] GOTO 900
#3006=1 (CHECK THE PART)
G0 X#1 Y#2
N900 M30
%
; FEATURES: ISO-MAC-08
; Fanuc Custom Macro B system variables ncc provides: #5001/#5041 positions (program), #5021
; machine position, #5221+20(n-1) work offsets (mm), #4109 F, #4119 S, #4120 T; #3006 = n is a
; stop with a message (M0), #3000 = n an alarm that stops the run.
; RUN: %ncc compile %s --emit=ir | FileCheck %s --check-prefix=IR
; IR: assign target=#1 value=$_x
; IR: assign target=#3 value=$_abs_x
; IR: assign target=#4 value=$_work_offset1_x
; IR: assign target=#5 value=$_work_offset2_y
; IR: message text=(concat (concat "#3006 = " 1) " (CHECK THE PART)")
; IR-NEXT: stop kind=program
; RUN: %ncc run %s --trace=canon -o %t
; RUN: FileCheck %s --check-prefix=TRACE --input-file=%t
; TRACE: MESSAGE("#3006 = 1 (CHECK THE PART)")
; TRACE-NEXT: PROGRAM_STOP()
; TRACE-NEXT: STRAIGHT_TRAVERSE(11.0000, 22.0000
; RUN: printf 'G0 X1\n#3000=2 (TOOL BROKEN)\nG0 X2\nM30\n' > %t.alarm.nc
; RUN: %ncc compile %t.alarm.nc --emit=ir | FileCheck %s --check-prefix=IRA
; IRA: message text=(concat (concat "macro alarm #3000 = " 2) " (TOOL BROKEN)") kind=abort
; RUN: not %ncc run %t.alarm.nc 2>&1 | FileCheck %s --check-prefix=ALARM
; ALARM: alarm.nc:2:1: error: macro alarm #3000 = 2.000000 (TOOL BROKEN) [abort]
; Variables ncc does not provide are errors, and so are writes to read-only state (offset
; writes: iso-mac-08-offset-writes.nc).
; RUN: printf '#1=#4001\n#5041=3\n#2=#50\n#3=#3000\nM30\n' > %t.nc
; RUN: not %ncc compile %t.nc --emit=ir 2>&1 | FileCheck %s --check-prefix=ERR
; ERR: :1:4: error: Fanuc system variable #4001 is not supported [unsupported-code]
; ERR: :2:1: error: #5041 (current position X) is read-only [read-only-parameter]
; ERR: :3:4: error: #50 does not exist in Custom Macro B (#1-#33 local, #100-#999 common) [unsupported-code]
; ERR: :4:4: error: #3000 can only be assigned (alarm and message stop) [unsupported-code]
; A computed number reads the same variables when the program runs (#[#1+41] = #5041, the
; position; iso-mac-08-computed-system-variables.nc), and one ncc does not provide is a run-time
; error at the variable in both engines, not an empty parameter.
; RUN: printf '#1=5000\nG0 X7.\n#2=#[#1+41]\nG0 Y#2\n#3=#[#1+1000]\nM30\n' > %t.run.nc
; RUN: not %ncc run %t.run.nc --trace=canon > %t.eval 2> %t.eval.err
; RUN: not %ncc run %t.run.nc --engine=jit --trace=canon > %t.jit 2> %t.jit.err
; RUN: FileCheck %s --check-prefix=RUNERR < %t.eval.err
; RUN: FileCheck %s --check-prefix=RUNERR < %t.jit.err
; RUN: diff %t.eval %t.jit
; RUN: FileCheck %s --check-prefix=RUNTIME --input-file=%t.jit
; RUNTIME: STRAIGHT_TRAVERSE(7.0000, 0.0000
; RUNTIME-NEXT: STRAIGHT_TRAVERSE(7.0000, 7.0000
; RUNERR: :5:4: error: Fanuc system variable #6000 is not supported
