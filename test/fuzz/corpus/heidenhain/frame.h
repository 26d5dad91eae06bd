0 BEGIN PGM FRAME MM
1 BLK FORM 0.1 Z X+0 Y+0 Z-20 ; the blank: minimum point
2 BLK FORM 0.2 X+100 Y+100 Y+0
3 * - a comment block
4 TOOL CALL 1 Z S3000
4 L X+0 Y+0 Z+0 R0 FMAX
7 L X+12.5 Y+2 ~
  F100
8 L X+25,5
9 L ~
  IY+2,25 ;a comment
10 M2
11 END PGM FRAME MM
