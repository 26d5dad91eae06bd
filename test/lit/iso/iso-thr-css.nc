G18 G21 G54
T0101
G97 S500 M03
G0 X40. Z5.
G96 S100
G32 Z-20. F2.
G0 X50.
G32 X60. Z-40. F2.
M30
%
; FEATURES: ISO-THR-01 ISO-SPD-02
; A thread under constant surface speed (G96) runs at the rpm of its radius: X40 (diameter) is
; r = 20 mm, 1000 * 100 / (2 pi 20) = 795.77 rpm, so lead 2 mm feeds 1591.55 mm/min. A tapered
; thread would change the speed along the cut: an error, not a thread at the wrong feed.
; RUN: sed -e '/^G32 X60/d' %s > %t.nc
; RUN: %ncc compile %t.nc --machine=%srcroot/examples/machines/lathe.toml --emit=motion | FileCheck %s
; RUN: not %ncc compile %s --machine=%srcroot/examples/machines/lathe.toml --emit=motion 2>&1 | FileCheck %s --check-prefix=ERR
; CHECK: thread X30 Y0 Z-410 {{.*}} lead=2 along=z sync=index F1591.549430918
; ERR: iso-thr-css.nc:8:1: error: a thread that changes X under constant surface speed (G96): the spindle speed would change along the cut; program G97 S<rpm> for it [unsupported-code]
