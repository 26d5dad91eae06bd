G1 X10 F0
%
; FEATURES: ISO-FEED-04
; F0 is 808D alarm 14800 (unless fixed feedrates): a warning at compile time.
; RUN: %ncc compile %s --emit=ir 2>&1 | FileCheck %s
; CHECK: iso-feed-04-zero-feed.nc:1:8: warning: path feed F must be greater than zero (808D alarm 14800) [zero-feed]
; CHECK: feed value=0
