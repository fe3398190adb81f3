// The body of bore_c30_ring.geo meshed 4 times finer everywhere (208 contact elements, 192 per
// circumference away from the contact): the reference of the body-mesh error at tolerance 1e-5
// (tests/validation/smooth_cuts.rs, an ignored test).
// Ring with a bore R2 = 30.6 mm and a fixed rim R3 = 42 mm holding the roller of
// bore_c30_roller.geo (tests/validation/smooth_cuts.rs): contact segment |x| <= L = 1.3a in 52 elements.
R2 = 30.6;
R3 = 42;
L = 11.7;
ne = 208;
far = 192;
Include "bore_ring.inc";
