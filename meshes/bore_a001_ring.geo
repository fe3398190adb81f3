// Ring with a bore R2 = 50 mm and a fixed rim R3 = 65 mm holding the roller of
// bore_a001_roller.geo (cases/bore_a001_*.yaml): contact segment |x| <= L = 1.3a in 52 elements.
R2 = 50;
R3 = 65;
L = 0.52;
ne = 52;
Include "bore_ring.inc";
