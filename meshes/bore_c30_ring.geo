// Ring with a bore R2 = 30.6 mm and a fixed rim R3 = 42 mm holding the roller of
// bore_c30_roller.geo (tests/validation/smooth_cuts.rs): contact segment |x| <= L = 1.3a in 52 elements.
R2 = 30.6;
R3 = 42;
L = 11.7;
ne = 52;
Include "bore_ring.inc";
