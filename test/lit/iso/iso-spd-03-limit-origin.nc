G50 S2000
T0101
G96 S200 M3
G0 X50. Z2.
G99 G1 Z-10. F0.2
T0202
G1 Z-20.
G97 S800
M30
; FEATURES: ISO-SPD-02 ISO-SPD-03 ISO-CS-04
; The CSS radius is measured from the program's X zero: work offset, G50 and the tool's X offset
; (examples/machines/lathe.toml: T1 x_offset 10, T2 12 + wear 0.01; X in diameters). The tool
; change moves the origin under G96: a spindle_mode 2 record (no code) gives the new one before the
; next move. X50 is r = 25: 200 m/min = 1273.24 rpm, 0.2 mm/rev = 254.65 mm/min; after T0202 the
; tool tip is at r = 22.99 (the machine X stays): 276.91 mm/min. The limit 2000 holds.
; RUN: %ncc compile %s --machine=%srcroot/examples/machines/lathe.toml --emit=motion | FileCheck %s
; CHECK:      spindle_mode 0 2000 0 @1:5
; CHECK:      spindle_mode 1 2000 10 @3:1
; CHECK-NEXT: spindle_speed 200 @3:1
; CHECK:      rapid X35 Y0 Z{{.*}} @4:1
; CHECK:      linear X35 Y0 Z{{.*}} F254.647908{{[0-9]*}} @5:5
; CHECK:      tool_length {{.*}} @6:1
; CHECK-NEXT: spindle_mode 2 2000 12.01 @7:1
; CHECK-NEXT: linear X35 Y0 Z{{.*}} F276.911601{{[0-9]*}} @7:1
; CHECK-NEXT: spindle_mode 0 2000 12.01 @8:1
; CHECK-NEXT: spindle_speed 800 @8:1
; The canonical trace prints no command for the moved origin.
; RUN: %ncc run %s --machine=%srcroot/examples/machines/lathe.toml --trace=canon -o - | FileCheck %s --check-prefix=CANON
; CANON:      SET_SPINDLE_MODE(0 0.0000)
; CANON-NEXT: SELECT_TOOL(1)
; CANON:      SET_SPINDLE_MODE(0 2000.0000)
; CANON-NEXT: SET_SPINDLE_SPEED(0, 200.0000)
; CANON:      CHANGE_TOOL(2)
; CANON-NEXT: STRAIGHT_FEED
; CANON-NEXT: SET_SPINDLE_MODE(0 0.0000)
; CANON-NEXT: SET_SPINDLE_SPEED(0, 800.0000)
