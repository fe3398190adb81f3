// Roller R1 = 40 mm on a rigid shaft of 5 mm in a ring bore R2 = 50 mm (cases/bore_a020_*.yaml):
// Hertz half-width a = 8 mm (a/R1 = 0.20), contact segment |x| <= L = 1.3a in 52 elements.
R = 40;
rs = 5;
L = 10.4;
ne = 52;
Include "bore_roller.inc";
