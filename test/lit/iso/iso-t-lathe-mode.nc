G18 G21 G54
T0202 S500 M3
G0 X40. Z2.
G1 W-12. F0.1
U10. W-5.
G2 X70. Z-25. I10. K0
G3 U0 W-10. R5.
G98 G1 X80. F100.
T0200
G0 X100. Z50.
M30
%
; FEATURES: ISO-MOT-12 ISO-MOT-13 ISO-TOOL-01 ISO-FEED-02
; Lathe mode (machine [controller] kind = "lathe", G-code system A, diameter programming): X and
; U are diameters (machine X is a radius), U/W the incremental X/Z, arc I and R radii; T0202 =
; tool 2 with the X/Z offsets of offset 2 (x_offset 12 + x_wear 0.01, length 62 - 0.02) at once,
; T0200 cancels them; G99 (feed per revolution) is the lathe's start-up feed mode, G98 per minute.
; G54 is Z -450.
; RUN: %ncc compile %s --machine=%srcroot/examples/machines/lathe.toml --emit=motion | FileCheck %s
; CHECK:      plane 1
; CHECK-NEXT: feed_mode 1
; CHECK-NEXT: frame_change "start"
; CHECK-NEXT: plane 1 @1:1
; CHECK-NEXT: spindle_speed 500 @2:7
; CHECK-NEXT: tool_select 2 @2:1
; CHECK-NEXT: tool_change 2 @2:1
; CHECK-NEXT: tool_length 61.98 H2 X12.01 @2:1
; CHECK-NEXT: spindle_cw 0 @2:12
; CHECK-NEXT: rapid X32.01 Y0 Z-386.02 A0 B0 C0 @3:1
; CHECK-NEXT: feed_rate 0.1 @4:10
; CHECK-NEXT: linear X32.01 Y0 Z-398.02 A0 B0 C0 F50 @4:1
; CHECK-NEXT: linear X37.01 Y0 Z-403.02 A0 B0 C0 F50 @5:1
; CHECK-NEXT: arc X47.01 Y0 Z-413.02 A0 B0 C0 center(47.01, 0, -403.02) plane=zx turns=-1 F50 @6:1
; CHECK-NEXT: arc X47.01 Y0 Z-423.02 A0 B0 C0 center(47.01, 0, -418.02) plane=zx turns=1 F50 @7:1
; CHECK-NEXT: feed_mode 0 @8:1
; CHECK-NEXT: feed_rate 100 @8:13
; CHECK-NEXT: linear X52.01 Y0 Z-423.02 A0 B0 C0 F100 @8:5
; CHECK-NEXT: tool_select 2 @9:1
; CHECK-NEXT: tool_change 2 @9:1
; CHECK-NEXT: tool_length 0 H0 @9:1
; CHECK-NEXT: rapid X50 Y0 Z-400 A0 B0 C0 @10:1
; CHECK-NEXT: program_end 30 @11:1
; In NC IR U/W are X/Z with ic, the T word three ops.
; RUN: %ncc compile %s --machine=%srcroot/examples/machines/lathe.toml --emit=ir | FileCheck %s --check-prefix=IR
; IR: tool_select value=2
; IR-NEXT: tool_change
; IR-NEXT: tool_length h=2
; IR: move X=10.0 Z=-5.0 ic=XZ
; The Motion IR text with the X offset reads back unchanged.
; RUN: %ncc compile %s --machine=%srcroot/examples/machines/lathe.toml --emit=motion -o %t.motion
; RUN: %ncc compile %t.motion --emit=motion | FileCheck %s --check-prefix=BACK
; BACK: tool_length 61.98 H2 X12.01 @2:1
; Translated for the lathe (docs/EMIT.md "Lathes"): G54 coordinates (the offset is written) with
; the tool's offsets in them (X 20 + 12.01 as a diameter, Z 2 + 61.98), T0200 (offset 00).
; RUN: %ncc translate %s --machine=%srcroot/examples/machines/lathe.toml --to=iso | FileCheck %s --check-prefix=TRANSLATE
; TRANSLATE: N20 G18 G98 G54
; TRANSLATE: T0200
; TRANSLATE: N50 G0 X64.02 Z63.98
; The JSONL trace carries the X offset too.
; RUN: %ncc run %s --machine=%srcroot/examples/machines/lathe.toml --trace=jsonl | FileCheck %s --check-prefix=JSONL
; JSONL: {"kind":"tool_length","file":1,"line":2,"col":1,"value":61.98,"ivalue":2,"value2":12.01}
; JSONL: {"kind":"tool_length","file":1,"line":9,"col":1,"value":0,"ivalue":0}
