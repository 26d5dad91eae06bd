O0002
G21 G90 G17 G54 G49 G40
#1=1
WHILE [#1 LE 3] DO1
#[100+#1]=#[2200+#1]
#[110+#1]=#[13000+#1]
#1=#1+1
END1
G53 G0 X-#101 Y-#102 Z-#103
G53 G0 X-#111 Y-#112 Z-#113
#[2200+2]=#102+10.
#[12000+#1-2]=-0.5
#120=#[2000+10]
G53 G0 X[#120*1000]
G0 X0 Y0
#121=#[5020+1]
#122=#[5020+2]
#123=#[5220+1]
#[5240+1]=-100.
G53 G0 X#121 Y#122 Z#123
G55 G0 X0. Y0.
#124=#[5021]
G43 Z10. H2
#125=#[5020+3]
G53 G0 X#124 Y#125 Z0.
G41 D2 G1 X20. F500.
X40.
G40 G0 X50.
M30
%
; FEATURES: ISO-MAC-08 ISO-TOOL-08
; Computed variable numbers that are Fanuc system variables, resolved when the program runs with
; the map a constant number uses (ir/SystemParams.h), on the Fanuc sample machine (tool
; compensation memory C; G54 = -255 -205 -300, G55 = -155 -205 -300; tools 1-3 L110 R6, L130
; R3.4, L125 R4; tool 10 length wear -0.03). The loop reads H and D geometry of offsets 1-3 by
; #[2200+#1] and #[13000+#1]; #[2200+2] and #[12000+#1-2] write H2 geometry 140 and D2 wear -0.5,
; which G43 H2 and G41 D2 use (Z10 in G55 is machine -150, the path runs 2.9 beside Y55);
; #[5020+n] reads the machine position, #[5220+1] G54 X, #[5240+1] writes G55 X. Both engines
; give the same Motion IR.
; RUN: %ncc compile --emit=motion --engine=eval --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %s > %t.e
; RUN: %ncc compile --emit=motion --engine=jit --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %s > %t.j
; RUN: diff %t.e %t.j
; RUN: FileCheck %s < %t.j
; CHECK: rapid X-110 Y-130 Z-125 {{.*}} @9:1
; CHECK-NEXT: rapid X-6 Y-3.4 Z-4 {{.*}} @10:1
; CHECK-NEXT: rapid X-30 Y-3.4 Z-4 {{.*}} @14:1
; CHECK-NEXT: rapid X-255 Y-205 Z-4 {{.*}} @15:1
; CHECK-NEXT: rapid X-255 Y-205 Z-255 {{.*}} @20:1
; CHECK-NEXT: frame_change "G55" m00=1 m01=0 m02=0 m03=-100 {{.*}} @21:1
; CHECK-NEXT: rapid X-100 Y-205 Z-255 {{.*}} @21:5
; CHECK-NEXT: tool_length 140 H2 @23:1
; CHECK-NEXT: rapid X-100 Y-205 Z-150 {{.*}} @23:1
; CHECK-NEXT: rapid X-100 Y-150 Z0 {{.*}} @25:1
; CHECK-NEXT: feed_rate 500
; CHECK-NEXT: linear X-80 Y-147.1 Z0 {{.*}} @26:8
; In NC IR a computed number keeps its map: the builtin around it names memory C.
; RUN: %ncc compile --emit=ir --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %s | FileCheck %s --check-prefix=IR
; IR: assign target=#[(MACRO_VARIABLE_C (add 100 #1))] value=#[(MACRO_VARIABLE_C (add 2200 #1))]
; IR: assign target=#[(MACRO_VARIABLE_C (add 2200 2))] value=(add #102 10.0)
; IR: assign target=#121 value=#[(MACRO_VARIABLE_C (add 5020 1))]
; Without offset memory (the default machine) the map is MACRO_VARIABLE.
; RUN: %ncc compile --emit=ir %s | FileCheck %s --check-prefix=NOMEM
; NOMEM: value=#[(MACRO_VARIABLE (add 2200 #1))]
; Numbers that are not variables ncc provides stop the run at the variable, with the constant
; form's message, in both engines: an unsupported system variable, a read-only one written, a
; number that does not exist, the alarm variables (assigned with a constant number only), a tool
; offset the table lacks, offset variables without memory C and on a lathe.
; RUN: printf 'G0 X0\n#1=#[4000+1]\nM30\n' > %t.1.nc
; RUN: printf 'G0 X0\n#[5040+1]=3.\nM30\n' > %t.2.nc
; RUN: printf 'G0 X0\n#1=#[50+#0]\nM30\n' > %t.3.nc
; RUN: printf 'G0 X0\n#[3000]=1\nM30\n' > %t.4.nc
; RUN: printf 'G0 X0\n#1=#[2200+5]\nM30\n' > %t.5.nc
; RUN: printf 'G0 X0\n#2=1\n#1=#[2000+#2]\nM30\n' > %t.6.nc
; RUN: rm -f %t.err
; RUN: not %ncc run --engine=eval --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %t.1.nc 2>> %t.err
; RUN: not %ncc run --engine=eval --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %t.2.nc 2>> %t.err
; RUN: not %ncc run --engine=eval --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %t.3.nc 2>> %t.err
; RUN: not %ncc run --engine=eval --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %t.4.nc 2>> %t.err
; RUN: not %ncc run --engine=eval --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %t.5.nc 2>> %t.err
; RUN: not %ncc run --engine=eval %t.6.nc 2>> %t.err
; RUN: not %ncc run --engine=eval --machine=%S/../../../examples/machines/lathe.toml %t.6.nc 2>> %t.err
; RUN: not %ncc run --engine=jit --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %t.1.nc 2>> %t.err
; RUN: not %ncc run --engine=jit --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %t.2.nc 2>> %t.err
; RUN: not %ncc run --engine=jit --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %t.3.nc 2>> %t.err
; RUN: not %ncc run --engine=jit --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %t.4.nc 2>> %t.err
; RUN: not %ncc run --engine=jit --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %t.5.nc 2>> %t.err
; RUN: not %ncc run --engine=jit %t.6.nc 2>> %t.err
; RUN: not %ncc run --engine=jit --machine=%S/../../../examples/machines/lathe.toml %t.6.nc 2>> %t.err
; RUN: FileCheck %s --check-prefix=ERR < %t.err
; RUN: grep -c ': error: ' %t.err | FileCheck %s --check-prefix=COUNT
; COUNT: 14
; ERR: 1.nc:2:4: error: Fanuc system variable #4001 is not supported
; ERR: 2.nc:2:1: error: #5041 (current position X) is read-only
; ERR: 3.nc:2:4: error: #50 does not exist in Custom Macro B (#1-#33 local, #100-#999 common)
; ERR: 4.nc:2:1: error: #3000 (alarm and message stop) can only be assigned with a constant number
; ERR: 5.nc:2:4: error: Requested tool 5 not found in the tool table
; ERR: 6.nc:3:4: error: #2001 is a tool offset variable: the machine's [controller] offset_memory is "none" ("C": Fanuc tool compensation memory C)
; ERR: 6.nc:3:4: error: #2001 is a lathe tool offset variable: ncc provides Fanuc's offset variables on mills (tool compensation memory C) only
; ERR: 1.nc:2:4: error: Fanuc system variable #4001 is not supported
; ERR: 2.nc:2:1: error: #5041 (current position X) is read-only
; ERR: 3.nc:2:4: error: #50 does not exist in Custom Macro B (#1-#33 local, #100-#999 common)
; ERR: 4.nc:2:1: error: #3000 (alarm and message stop) can only be assigned with a constant number
; ERR: 5.nc:2:4: error: Requested tool 5 not found in the tool table
; ERR: 6.nc:3:4: error: #2001 is a tool offset variable: the machine's [controller] offset_memory is "none" ("C": Fanuc tool compensation memory C)
; ERR: 6.nc:3:4: error: #2001 is a lathe tool offset variable: ncc provides Fanuc's offset variables on mills (tool compensation memory C) only
