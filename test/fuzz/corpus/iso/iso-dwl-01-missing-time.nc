G4
%
; FEATURES: ISO-DWL-01
; RUN: not %ncc compile %s --emit=ir 2>&1 | FileCheck %s
; CHECK: iso-dwl-01-missing-time.nc:1:1: error: G4 needs a dwell time: P (milliseconds) or X (seconds) [missing-word]
