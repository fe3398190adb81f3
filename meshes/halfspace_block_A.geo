// Half-space block, body A (paper Fig. 2)
// Boundary mesh (quadratic line3 elements) of a large rectangular block standing in for a
// half-space (paper Fig. 2): width 2W, depth H, its contact face on y = 0 with ne elements on
// |x| <= L at exactly the x of the half-space contact grid (aligned 21-element grid, a = 1 mm).
// Groups: contact, free (rest of the contact face and the sides), far (the face opposite the
// contact, held fixed). Units: mm. Regenerate: python3 tools/make_meshes.py
W = 40;
H = 40;
ne = 21;
L = 21/17;
lc_contact = 2*L/ne;
lc_far = 4;
s = 1;                 // +1: body A (y >= 0); -1: body B (y <= 0)
For i In {0:ne}
  Point(10+i) = {-L + 2*L*i/ne, 0, 0, lc_contact};
EndFor
For i In {0:ne-1}
  Line(100+i) = {10+i, 11+i};
  Transfinite Curve{100+i} = 2;
EndFor
Point(200) = {W, 0, 0, lc_far};
Point(201) = {W, s*H, 0, lc_far};
Point(202) = {-W, s*H, 0, lc_far};
Point(203) = {-W, 0, 0, lc_far};
Line(300) = {10+ne, 200};
Line(301) = {200, 201};
Line(302) = {201, 202};
Line(303) = {202, 203};
Line(304) = {203, 10};
// Gmsh orients each curve as drawn above; rollbem wants the material on the left of every
// element (contour counter-clockwise), else it turns the loop round on loading and says so.
// Body B's contour (s = -1) is drawn clockwise.
If (s < 0)
  Reverse Curve{100:100+ne-1, 300:304};
EndIf
Physical Curve("contact") = {100:100+ne-1};
Physical Curve("free") = {300, 301, 303, 304};
Physical Curve("far") = {302};
Mesh.ElementOrder = 2;
Mesh.SecondOrderLinear = 0;
Mesh.MshFileVersion = 4.1;
