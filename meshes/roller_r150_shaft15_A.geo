// Paper Fig. 14, body A: R = 150 mm roller on a 15 mm rigid shaft
// Boundary mesh (quadratic line3 elements) of a roller of radius R on a rigid shaft of radius rs,
// body A (above the contact). The contact segment |x| <= L carries ne elements whose ends have exactly the x of the
// half-space contact grid (aligned 21-element grid for a = 1 mm: L = 21/17 mm), so the two
// rollers' contact nodes pair node to node. Units: mm. Regenerate: python3 tools/make_meshes.py
R = 150;
rs = 15;
ne = 21;
L = 21/17;
lc_contact = 2*L/ne;
lc_far = 2*Pi*R/48;
lc_shaft = 2*Pi*rs/24;
s = 1;                 // +1: body A above the contact (centre at y = +R); -1: body B below
cy = s*R;
Point(1) = {0, cy, 0};
For i In {0:ne}
  x = -L + 2*L*i/ne;
  Point(10+i) = {x, cy - s*Sqrt(R*R - x*x), 0, lc_contact};
EndFor
For i In {0:ne-1}
  Circle(100+i) = {10+i, 1, 11+i};
  Transfinite Curve{100+i} = 2;
EndFor
// The rest of the outer circle, in four arcs; sizes grade from lc_contact to lc_far.
Point(200) = {R, cy, 0, lc_far};
Point(201) = {0, cy + s*R, 0, lc_far};
Point(202) = {-R, cy, 0, lc_far};
Circle(300) = {10+ne, 1, 200};
Circle(301) = {200, 1, 201};
Circle(302) = {201, 1, 202};
Circle(303) = {202, 1, 10};
// Shaft hole.
Point(400) = {rs, cy, 0, lc_shaft};
Point(401) = {0, cy + rs, 0, lc_shaft};
Point(402) = {-rs, cy, 0, lc_shaft};
Point(403) = {0, cy - rs, 0, lc_shaft};
Circle(500) = {400, 1, 401};
Circle(501) = {401, 1, 402};
Circle(502) = {402, 1, 403};
Circle(503) = {403, 1, 400};
// Gmsh orients each curve as drawn above; rollbem wants the material on the left of every
// element (outer contour counter-clockwise, the shaft hole clockwise), else it turns the loop
// round on loading and says so. Body B's contour is drawn clockwise, the hole counter-clockwise.
If (s < 0)
  Reverse Curve{100:100+ne-1, 300:303};
EndIf
Reverse Curve{500:503};
Physical Curve("contact") = {100:100+ne-1};
Physical Curve("free") = {300, 301, 302, 303};
Physical Curve("shaft") = {500, 501, 502, 503};
Mesh.ElementOrder = 2;
Mesh.SecondOrderLinear = 0;
Mesh.MshFileVersion = 4.1;
