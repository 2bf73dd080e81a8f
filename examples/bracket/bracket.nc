%
(bracket: the shipped example - a step, a pocket, a slot and a through hole, 2.5D flat end)
G90 G21 G17
T1 M6 (flat end mill D8: step 6 mm deep along the front)
S10000 M3
G0 Z20
X-5 Y3
G1 Z9 F600
X45
Y7
X-5
G0 Z20
T2 M6 (flat end mill D6: pocket 16 x 10, 4 mm deep, then a slot)
G0 X22 Y17
G1 Z11 F400
X32
Y21
X22
Y17
X25 Y19
X29
G0 Z20
X6 Y26
G1 Z12 F400
X16
G0 Z20
T3 M6 (flat end mill D5: through hole)
G0 X8 Y16
G1 Z-1 F200
G0 Z20
M5
M30
%
