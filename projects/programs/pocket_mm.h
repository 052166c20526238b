0 BEGIN PGM POCKET MM
1 ; MillExpert sample: pocket in mm, stock top Z0 (the ISO pocket_mm.nc in Klartext)
2 BLK FORM 0.1 Z X+0 Y+0 Z-20
3 BLK FORM 0.2 X+100 Y+60 Z+0
4 TOOL CALL 1 Z S1500 F600
5 L Z+5 R0 FMAX M3
6 L X+0 Y+0 R0 FMAX
7 L Z-2 R0 F150 ; plunge to 2 mm
8 L X+40 F600
9 L Y+20
10 CC X+60 Y+20
11 C X+60 Y+40 DR- ; quarter circle, R20
12 CR X+80 Y+20 R-20 DR+
13 L X+80 Y+0
14 * - step up: 1 mm
15 L Z-1
16 L X+0
17 L Z+5 FMAX
18 M5
19 END PGM POCKET MM
