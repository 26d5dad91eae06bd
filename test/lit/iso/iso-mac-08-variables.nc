#1 = 5
#100=#1*2+3
#[#1+1] = #0
##1 = -#1
#500 = #1
G1 X-#1 Y[#2+1] Z#[#1] F#9
G1 X#0
%
; FEATURES: ISO-MAC-08
; Macro B variables: #n, #[expr], ##n (indirect), #0 is vacant; words take variable values
; (X#1, X-#1, X[expr]); an assignment is an `assign` op. All variables are Numbered.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: assign target=#1 value=5 loc(1:1:1)
; CHECK: assign target=#100 value=(add (mul #1 2) 3) loc(1:2:1)
; A computed number is checked when the program runs: a plain variable, not controller state.
; CHECK: assign target=#[(MACRO_VARIABLE (add #1 1))] value=vacant loc(1:3:1)
; CHECK: assign target=#[(MACRO_VARIABLE #1)] value=(neg #1) loc(1:4:1)
; CHECK: assign target=#500 value=#1
; CHECK: feed value=#9
; CHECK-NEXT: mode motion=linear
; CHECK-NEXT: move X=(neg #1) Y=(add #2 1) Z=#[(MACRO_VARIABLE #1)] loc(1:6:1)
; CHECK: move X=vacant loc(1:7:1)
