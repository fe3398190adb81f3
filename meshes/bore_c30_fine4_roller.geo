// The body of bore_c30_roller.geo meshed 4 times finer everywhere (208 contact elements, 192 per
// circumference away from the contact): the reference of the body-mesh error at tolerance 1e-5
// (tests/validation/smooth_cuts.rs, an ignored test).
// Roller R1 = 30 mm on a rigid shaft of 5 mm in a ring bore R2 = 30.6 mm (close conformity,
// R* = R1 R2/(R2 - R1) = 1530 mm; the cut-geometry test of tests/validation/smooth_cuts.rs):
// Hertz half-width a = 9 mm at P = 4797.68 N/mm, contact segment |x| <= L = 1.3a in 52 elements.
R = 30;
rs = 5;
L = 11.7;
ne = 208;
far = 192;
Include "bore_roller.inc";
