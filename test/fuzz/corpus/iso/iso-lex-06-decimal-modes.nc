G21 G94 G17
G1 X1000 Y100.5 Z-25 A1000 F100
G76 X1234 Z-500 R250 Q100 P1500 K2
G95 F25
G20 G94 G1 X1000 F10
G4 X1500
%
; FEATURES: ISO-LEX-06
; Words without a decimal point: calculator notation reads them as mm/deg; IS-B multiplies
; X Y Z U V W A B C I J K Q R by 0.001 (inch 0.0001), IS-C by 0.0001 (inch 0.00001); F per
; minute stays 1 mm/min (0.01 in/min), F per revolution is 0.01 mm/rev; G04 X is 0.001 s.
; Words with a point are never scaled.
; RUN: %ncc compile %s --emit=ir | FileCheck %s --check-prefix=CALC
; RUN: %ncc compile %s --emit=ir --decimal-mode=calculator | FileCheck %s --check-prefix=CALC
; RUN: %ncc compile %s --emit=ir --decimal-mode=is-b | FileCheck %s --check-prefix=ISB
; RUN: %ncc compile %s --emit=ir --decimal-mode=is-c | FileCheck %s --check-prefix=ISC
; CALC: move X=1000 Y=100.5 Z=-25 A=1000 loc
; CALC: move X=1234 Z=-500 R=250 P=1.5 Q=100 L=2 loc
; CALC: feed value=25 loc
; CALC: feed value=10 loc
; CALC: move X=1000 loc
; CALC: dwell seconds=1500 loc
; ISB: feed value=100 loc
; ISB: move X=1.0 Y=100.5 Z=-0.025 A=1.0 loc
; ISB: move X=1.234 Z=-0.5 R=0.25 P=1.5 Q=0.1 L=2 loc
; ISB: feed value=0.25 loc
; ISB: feed value=0.1 loc
; ISB: move X=0.1 loc
; ISB: dwell seconds=1.5 loc
; ISC: feed value=100 loc
; ISC: move X=0.1 Y=100.5 Z=-0.0025 A=0.1 loc
; ISC: move X=0.1234 Z=-0.05 R=0.025 P=1.5 Q=0.01 L=2 loc
; ISC: feed value=0.25 loc
; ISC: feed value=0.1 loc
; ISC: move X=0.01 loc
; ISC: dwell seconds=1.5 loc
