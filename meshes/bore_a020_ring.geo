// Ring with a bore R2 = 50 mm and a fixed rim R3 = 65 mm holding the roller of
// bore_a020_roller.geo (cases/bore_a020_*.yaml): contact segment |x| <= L = 1.3a in 52 elements.
R2 = 50;
R3 = 65;
L = 10.4;
ne = 52;
Include "bore_ring.inc";
