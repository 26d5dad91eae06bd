G17 G90 G40 G49
G0 X0 Y0 Z0
G43 Z-20. H10
G43 Z-20. H14
G41 D15 G1 X10. F100
X20.
G40 X30.
G10 L12 P11 R6.
G41 D11 X40.
G40 X50.
G43 Z0 H12
G0 X#13015 Y#2211
M30
; FEATURES: ISO-TOOL-02 ISO-TOOL-03 ISO-TOOL-04 ISO-TOOL-08
; 808D ISO offset numbers: H and D address tool edges through $TC_DPH (machine [controller]
; offset_numbers, table 2-13 of the manual: H10 = T1 D1 … H15 = T2 D3). The manual's example:
; with H10 = -3, G43 Z-20. H10 is at -23; H14 = T2 D2 (length 60), D15 = T2 D3 (radius 8);
; G10 L12 P11 writes the radius of T1 D2, which D11 then uses; the Fanuc variables of offset
; numbers 15 and 11 (#13015 D geometry, #2211 H geometry) read T2 D3 and T1 D2. Both engines.
; RUN: %ncc compile --emit=motion --engine=eval --machine=%S/Inputs/808d-offset-numbers.toml %s > %t.e
; RUN: %ncc compile --emit=motion --engine=jit --machine=%S/Inputs/808d-offset-numbers.toml %s > %t.j
; RUN: diff %t.e %t.j
; RUN: FileCheck %s < %t.j
; CHECK: tool_length -3 H10 @3:1
; CHECK-NEXT: rapid X0 Y0 Z-23 {{.*}} @3:1
; CHECK-NEXT: tool_length 60 H14 @4:1
; CHECK-NEXT: rapid X0 Y0 Z40 {{.*}} @4:1
; CHECK: linear X10 Y8 Z40 {{.*}} @5:9
; CHECK-NEXT: linear X20 Y8 Z40 {{.*}} @6:1
; CHECK-NEXT: linear X30 Y0 Z40 {{.*}} @7:1
; CHECK-NEXT: linear X40 Y6 Z40 {{.*}} @9:1
; CHECK-NEXT: linear X50 Y0 Z40 {{.*}} @10:1
; CHECK-NEXT: tool_length 10 H12 @11:1
; CHECK-NEXT: linear X50 Y0 Z10 {{.*}} @11:1
; CHECK-NEXT: rapid X8 Y4 Z10 {{.*}} @12:1
; A number the mapping lacks is an error, in H, D and G10 P alike; so is a mapped edge the tool
; table lacks (ncc machine --check).
; RUN: printf 'G43 Z0 H1\nM30\n' > %t.h1.nc
; RUN: not %ncc run --machine=%S/Inputs/808d-offset-numbers.toml %t.h1.nc 2>&1 | FileCheck %s --check-prefix=H1
; H1: h1.nc:1:1: error: offset number 1 is not in the machine's offset_numbers [unknown-tool]
; RUN: printf 'G10 L10 P16 R1.\nM30\n' > %t.p16.nc
; RUN: not %ncc run --machine=%S/Inputs/808d-offset-numbers.toml %t.p16.nc 2>&1 | FileCheck %s --check-prefix=P16
; P16: p16.nc:1:1: error: offset number 16 is not in the machine's offset_numbers [unknown-tool]
; RUN: printf 'schema = 1\n[controller]\noffset_numbers = { 10 = [1, 3], 12 = [9, 1], 011 = [1, 1] }\n[axes.X]\nmax_velocity = 1\nmax_accel = 1\n[[tools]]\nnumber = 1\nedges = [{ d = 1 }]\n' > %t.bad.toml
; RUN: not %ncc machine --check %t.bad.toml 2>&1 | FileCheck %s --check-prefix=BAD
; BAD: bad.toml:3:46: error: offset_numbers: '011' is not an offset number 1..99999
; RUN: printf 'schema = 1\n[controller]\noffset_numbers = { 10 = [1, 3], 12 = [9, 1], 13 = [1] }\n[axes.X]\nmax_velocity = 1\nmax_accel = 1\n[[tools]]\nnumber = 1\nedges = [{ d = 1 }]\n' > %t.bad2.toml
; RUN: not %ncc machine --check %t.bad2.toml 2>&1 | FileCheck %s --check-prefix=BAD2
; BAD2: bad2.toml:3:51: error: offset_numbers.13: expected [tool, edge], two integers 1..99999
; RUN: printf 'schema = 1\n[controller]\noffset_numbers = { 10 = [1, 3], 12 = [9, 1] }\n[axes.X]\nmax_velocity = 1\nmax_accel = 1\n[[tools]]\nnumber = 1\nedges = [{ d = 1 }]\n' > %t.bad3.toml
; RUN: not %ncc machine --check %t.bad3.toml 2>&1 | FileCheck %s --check-prefix=BAD3
; BAD3: bad3.toml:3:25: error: offset_numbers.10: tool 1 has no edge d = 3
; BAD3: bad3.toml:3:38: error: offset_numbers.12: tool 9 is not in {{\[\[}}tools]]
