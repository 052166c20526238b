%
(MillExpert sample: pocket in mm, stock top Z0)
N10 G21 G90 G17
N20 G0 Z5. S1500 M3
N30 G0 X0 Y0
N40 G1 Z-2. F150 ; plunge to 2 mm
N50 G1 X40. F600
N60 Y20.
N70 G2 X60 Y40 I20 J0 (quarter circle, R20)
N80 G3 X80 Y20 I0 J-20
N90 G1 X80 Y0
N100 G4 P0.5
N110 G1 Z-1. (step up: 1 mm)
N120 X0
N130 G0 Z5.
N140 M5
N150 M30
%
