0 BEGIN PGM SUB1 MM
1 ; QL1 is this program's own: 0 at each call; Q1 is the caller's
2 QL1 = QL1 + 5
3 Q1 = Q1 + 1
4 L X+QL1 Y+Q1 R0 FMAX
5 QL1 = 0
6 END PGM SUB1 MM
