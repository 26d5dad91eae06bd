G92 S1500
%
; FEATURES: ISO-CS-04
; G92 S is the turning spindle speed limit, not a speed: on a milling machine (no constant
; surface speed to limit) it is an error rather than misread as `speed`; lathes: iso-spd-03-*.
; RUN: not %ncc compile %s --emit=ir 2>&1 | FileCheck %s
; CHECK: iso-cs-04-g92-spindle-limit.nc:1:5: error: G92 S (spindle speed limit) needs a lathe (machine kind = "lathe") [unsupported-code]
