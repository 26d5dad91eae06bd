G18 G98 G0 X100. Z50.
G10 P101 X20. Z30. R0.4
G10 P1 U0.2 W-0.1
T0101
G0 X50. Z10.
G10 P1 U0.2
T0101
G0 X50. Z10.
M30
; FEATURES: ISO-TOOL-08
; The 808D turning G10 P X(U) Z(W) R(C) on the plain lathe: P101 writes the geometry of offset 1
; (X20 a diameter: 10 mm radius, Z30, nose radius 0.4), P1 its wear (U0.2 adds 0.1 radius, W-0.1);
; T0101 applies X 10.1 and Z 29.9; a second wear write adds again and counts at the next T.
; RUN: %ncc compile %s --machine=%S/Inputs/lathe0.toml --emit=motion | FileCheck %s
; CHECK:      rapid X50 Y0 Z50 A0 B0 C0 @1:9
; CHECK-NEXT: tool_select 1 @4:1
; CHECK-NEXT: tool_change 1 @4:1
; CHECK-NEXT: tool_length 29.9 H1 X10.1 @4:1
; CHECK-NEXT: rapid X35.1 Y0 Z39.9 A0 B0 C0 @5:1
; CHECK-NEXT: tool_select 1 @7:1
; CHECK-NEXT: tool_change 1 @7:1
; CHECK-NEXT: tool_length 29.9 H1 X10.2 @7:1
; CHECK-NEXT: rapid X35.2 Y0 Z39.9 A0 B0 C0 @8:1
; RUN: %ncc compile %s --machine=%S/Inputs/lathe0.toml --emit=ir | FileCheck %s --check-prefix=IR
; IR: set_offset kind=lathe_tool index=101 X=20.0 Z=30.0 R=0.4
; IR: set_offset kind=lathe_tool index=1 U=0.2 W=-0.1
; A P that is neither a wear (1-99) nor a geometry (101-1600) number.
; RUN: not %ncc compile %S/Inputs/g10-lathe-p100.nc --machine=%S/Inputs/lathe0.toml --emit=motion 2>&1 | FileCheck %s --check-prefix=P100
; P100: g10-lathe-p100.nc:3:1: error: G10 P must be 1-99 (wear) or 101-1600 (geometry: 100 + the offset number) [bad-offset-index]
