O0001
G21 G90 G17 G54 G49 G40
G0 X#2201 Y#13001
G0 X[#11010*2] Y[#2010*100]
#2202=140.
#13002=5.
#12002=-0.5
G0 X0 Y0
G43 Z10. H2
G41 D2 G1 X20. F500.
X40.
G40 X50.
#10002=1.
G0 Z10.
G43 H2 Z10.
G49 Z0
M30
%
; FEATURES: ISO-MAC-08 ISO-TOOL-03 ISO-TOOL-04 ISO-TOOL-08
; Fanuc Custom Macro B tool compensation memory C on the Fanuc sample machine (offset_memory
; "C", G54 = -255 -205 -300; tool 1 L110 R6, tool 2 L130 R3.4, tool 10 L90 length wear -0.03):
; #2201 (H1 geometry) and #13001 (D1 geometry) read 110 and 6, #11010 and #2010 read 90 and
; -0.03; the program writes H2 geometry 140, D2 geometry 5 and D2 wear -0.5, then G43 H2 and
; G41 D2 use them: Z10 is machine -150, the compensated path runs 4.5 beside Y0. The H2 wear
; written while G43 H2 is active (#10002=1) applies at the next G43 H2 (tool_write "on-select",
; Fanuc EVO = 0): Z10 stays at -150 until then, -149 after. Both engines.
; RUN: %ncc compile --emit=motion --engine=eval --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %s > %t.e
; RUN: %ncc compile --emit=motion --engine=jit --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %s > %t.j
; RUN: diff %t.e %t.j
; RUN: FileCheck %s < %t.j
; CHECK: rapid X-145 Y-199 Z0 {{.*}} @3:1
; CHECK-NEXT: rapid X-75 Y-208 Z0 {{.*}} @4:1
; CHECK-NEXT: rapid X-255 Y-205 Z0 {{.*}} @8:1
; CHECK-NEXT: tool_length 140 H2 @9:1
; CHECK-NEXT: rapid X-255 Y-205 Z-150 {{.*}} @9:1
; CHECK-NEXT: feed_rate 500
; CHECK-NEXT: linear X-235 Y-200.5 Z-150 {{.*}} @10:8
; CHECK-NEXT: linear X-215 Y-200.5 Z-150 {{.*}} @11:1
; CHECK-NEXT: linear X-205 Y-205 Z-150 {{.*}} @12:1
; CHECK-NEXT: rapid X-205 Y-205 Z-150 {{.*}} @14:1
; CHECK-NEXT: tool_length 141 H2 @15:1
; CHECK-NEXT: rapid X-205 Y-205 Z-149 {{.*}} @15:1
; In NC IR, constant numbers become the tool data family (tool, edge 0 = the H/D edge, field).
; RUN: %ncc compile --emit=ir --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %s | FileCheck %s --check-prefix=IR
; IR: assign target=$_tool_data[2, 0, 0] value=140.
; IR: assign target=$_tool_data[2, 0, 1] value=5.
; IR: assign target=$_tool_data[2, 0, 3] value=-0.5
; IR: assign target=$_tool_data[2, 0, 2] value=1.
; With tool_write "immediate" (Fanuc EVO = 1) the wear applies from the next block.
; RUN: sed 's/^tool_write = "on-select"/tool_write = "immediate"/' %S/../../../examples/machines/fanuc-0i-mill.toml > %t.toml
; RUN: %ncc compile --emit=motion --engine=jit --machine=%t.toml %s | FileCheck %s --check-prefix=NOW
; NOW: linear X-205 Y-205 Z-150 {{.*}} @12:1
; NOW-NEXT: tool_length 141 H2 @13:1
; NOW-NEXT: rapid X-205 Y-205 Z-149 {{.*}} @14:1
; NOW-NEXT: tool_length 141 H2 @15:1
; NOW-NEXT: rapid X-205 Y-205 Z-149 {{.*}} @15:1
; The same rule for G10 L10 of the active H: at once with "immediate", at the next G43 H1 else.
; RUN: printf 'G43 H1 G0 Z0\nG10 L10 P1 R120.\nG0 Z0\nM30\n' > %t.g10.nc
; RUN: %ncc compile --emit=motion --machine=%t.toml %t.g10.nc | FileCheck %s --check-prefix=G10NOW
; G10NOW: rapid X0 Y0 Z-190 {{.*}} @1:8
; G10NOW-NEXT: tool_length 120 H1 @2:1
; G10NOW-NEXT: rapid X0 Y0 Z-180 {{.*}} @3:1
; RUN: %ncc compile --emit=motion --engine=jit --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %t.g10.nc | FileCheck %s --check-prefix=G10SEL
; G10SEL: rapid X0 Y0 Z-190 {{.*}} @1:8
; G10SEL-NEXT: rapid X0 Y0 Z-190 {{.*}} @3:1
; Without offset memory (the default machine) the numbers are errors, not plain variables; an
; offset number the table lacks stops the run.
; RUN: not %ncc compile --emit=ir %s 2>&1 | FileCheck %s --check-prefix=NONE
; NONE: memory.nc:3:5: error: #2201 is a tool offset variable: the machine's [controller] offset_memory is "none" ("C": Fanuc tool compensation memory C) [unsupported-code]
; RUN: printf '#1=#2205\nM30\n' > %t.five.nc
; RUN: not %ncc run --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %t.five.nc 2>&1 | FileCheck %s --check-prefix=FIVE
; RUN: not %ncc run --engine=jit --machine=%S/../../../examples/machines/fanuc-0i-mill.toml %t.five.nc 2>&1 | FileCheck %s --check-prefix=FIVE
; FIVE: five.nc:1:4: error: Requested tool 5 not found in the tool table
