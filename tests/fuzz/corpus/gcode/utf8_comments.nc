(Tasche fräsen – Werkstück Ø 80 mm, Spannung prüfen)
G21 G90
G0 Z5 S1600 ; Schnittgeschwindigkeit ≈ 80 m/min
G1 Z-2 F150 (Eintauchen, µ-genau)
G1 X60 F700 (切削 cutting)
G0 Z5
