; The manual's example C21 (seed002a 09, L10709-L10851) with two changes, for sl-example09.test:
; cycle 22's Q19=150 is 0 here (a plunge along the tool table's ANGLE, which ncc's tool data lack,
; is refused) and cycle 24 (side finishing, not simulated yet) is left out (blocks 16 and 17).
0 BEGIN PGM C21 MM
1 BLK FORM 0.1 Z X+0 Y+0 Z-40 ; blank definition
2 BLK FORM 0.2 X+100 Y+100 Z+0
3 TOOL CALL 1 Z S2500 ; tool call: drill, diameter 12
4 L Z+250 R0 FMAX ; retract tool
5 CYCL DEF 14.0 DANNYJE KONTURA ; define contour subprograms
6 CYCL DEF 14.1 METKA KONTURA 1/2/3/4
7 CYCL DEF 20 DANNYJE KONTURA ; general machining parameters
  Q1=-20 ;GLUBINA FREZEROWANIA
  Q2=1 ;PEREKRITIE TRAEKTOR.
  Q3=+0.5 ;PRIPUSK NA STORONU
  Q4=+0.5 ;PRIPUSK NA GLUBINU
  Q5=+0 ;KOORD. POVERHNOSTI
  Q6=2 ;BEZOPASN.RASSTOYANIE
  Q7=+100 ;B.WYSOTA?
  Q8=0.1 ;ROUNDING RADIUS
  Q9=-1 ;ROTATIONAL DIRECTION
8 CYCL DEF 21 PREDSWERLENJE ; cycle definition: pilot drilling
  Q10=5 ;GLUBINA WREZANJA
  Q11=250 ;PODACHA NA WREZANJE
  Q13=2 ;ROUGH-OUT TOOL
9 CYCL CALL M3 ; call pilot drilling cycle
10 L Z+250 R0 FMAX M6 ; retract tool
11 TOOL CALL 2 Z S3000 ; tool call: roughing/finishing, diameter 12
12 CYCL DEF 22 CHERN.OBRAB. ; cycle definition: roughing
  Q10=5 ;GLUBINA WREZANJA
  Q11=100 ;PODACHA NA WREZANJE
  Q12=350 ;FEED RATE F. ROUGHNG
  Q18=0 ;INST.CHER.OBR.
  Q19=0 ;FEED RATE FOR RECIP.
  Q208=30000 ;PODACHA WYCHODA
13 CYCL CALL M3 ; call roughing cycle
14 CYCL DEF 23 CHIST.OBRAB.DNA ; cycle definition: floor finishing
  Q11=100 ;PODACHA NA WREZANJE
  Q12=200 ;FEED RATE F. ROUGHNG
  Q208=30000 ;PODACHA WYCHODA
15 CYCL CALL ; call floor finishing cycle
18 L Z+250 R0 FMAX M2 ; retract tool, end of program
19 LBL 1 ; contour subprogram 1: pocket left
20 CC X+35 Y+50
21 L X+10 Y+50 RR
22 C X+10 DR-
23 LBL 0
24 LBL 2 ; contour subprogram 2: pocket right
25 CC X+65 Y+50
26 L X+90 Y+50 RR
27 C X+90 DR-
28 LBL 0
29 LBL 3 ; contour subprogram 3: square island left
30 L X+27 Y+50 RL
31 L Y+58
32 L X+43
33 L Y+42
34 L X+27
35 LBL 0
36 LBL 4 ; contour subprogram 4: triangular island right
37 L X+65 Y+42 RL
38 L X+57
39 L X+65 Y+58
40 L X+73 Y+42
41 LBL 0
42 END PGM C21 MM
