G17 G90 G21 G94 F1000
G68 X0 Y0 R30 G1
G51 X0 Y0 P1.5
G51 X0 Y0 I2000
G51 G51.1 X0
G51 X0 Y0
G68 X0 Y0 I0 J0 K0 R30
G68 X0 Y0 R30
G92 X0
G52 X1
G55
G28 X0
G68 X0 Y0 R10
G68 X0 Y0 R10
G69
G51 X0 Y0 P2000
G68 X0 Y0 R10
G17 G3 X1 Y1 R5
G81 X0 Y0 Z-1 R1
G50
G51.1 X0
G81 X0 Y0 Z-1 R1
G80
G91 G51.1 Y0
G90 G50.1
G68 X0 Y0 Z1 R10
M30
%
; FEATURES: ISO-CS-11 ISO-CS-12 ISO-CS-13 ISO-CS-15
; What the programmable frame refuses, each with its rule: G68 with another G code (808D
; L6393), G51 factors written with a point or in the form the machine does not use, two frame
; codes in one block, coordinate commands and G28 under a rotation or scaling (L6679-6682), a zero
; rotation vector (alarm 12560), a third G68, G68 with G51, cycles under a mirror, G51.1 in G91,
; a centre word off the rotation plane. lint reports them all and goes on.
; RUN: not %ncc lint %s 2>&1 | FileCheck %s
; CHECK: iso-cs-frames-errors.nc:2:15: error: G68 must not share its block with other G codes [syntax]
; CHECK: iso-cs-frames-errors.nc:3:11: error: G51 P is an integer in units of the scale weighting [bad-number]
; CHECK: iso-cs-frames-errors.nc:4:11: error: G51 I needs per-axis scaling (machine [controller] axes_scale_enable = true) [unsupported-code]
; CHECK: iso-cs-frames-errors.nc:5:1: error: G51.1 and G51 in one block: each takes the axis words [modal-group-conflict]
; CHECK: iso-cs-frames-errors.nc:6:1: error: G51 needs P (the setting-data default factor is not modelled) [missing-word]
; CHECK: iso-cs-frames-errors.nc:7:1: error: G68 rotation vector I0 J0 K0 (808D alarm 12560: value outside the allowed limits) [frame-invalid]
; CHECK: iso-cs-frames-errors.nc:9:1: error: G92 is not allowed while a programmable rotation, scaling or mirror (G68, G51, G51.1) is active [frame-conflict]
; CHECK: iso-cs-frames-errors.nc:10:1: error: G52 is not allowed while {{.*}} [frame-conflict]
; CHECK: iso-cs-frames-errors.nc:11:1: error: changing the work offset is not allowed while {{.*}} [frame-conflict]
; CHECK: iso-cs-frames-errors.nc:12:1: error: G28 is not allowed while {{.*}} [frame-conflict]
; CHECK: iso-cs-frames-errors.nc:14:1: error: a third G68 rotation (two are active; cancel them with G69) [frame-invalid]
; CHECK: iso-cs-frames-errors.nc:17:1: error: G68 together with scaling or mirroring (G51, G51.1) is not supported [unsupported-code]
; CHECK: iso-cs-frames-errors.nc:19:1: error: canned cycles under scaling, mirroring or a rotation that tilts the drilling axis are not supported [unsupported-code]
; CHECK: iso-cs-frames-errors.nc:22:1: error: canned cycles under scaling, {{.*}} [unsupported-code]
; CHECK: iso-cs-frames-errors.nc:24:5: error: G51.1 mirror positions are absolute: program it in G90 [frame-invalid]
; CHECK: iso-cs-frames-errors.nc:26:1: error: G68 in the XY plane takes no Z word (a 3-D rotation needs I J K) [frame-invalid]
