// Paper Fig. 11 (tyred cylinder), the scene b/a = 0.1: a strip of the cover layer around the
// contact, thickness b = 0.1 mm (a = 1 mm), bonded to the rigid core along y = -b (group
// `bonded`, fixed), its free face y = 0 carrying the contact segment |x| <= L (31 discontinuous
// elements) and the rest of the face (`free`). The strip ends at x = +-10 mm: a load on a thin
// bonded layer decays over a few thicknesses, so 100 b from the contact the ends (`ends`,
// fixed like the core) do not matter. The layer is flat; the case gives the cover's radius as
// the profile. Units: mm. Regenerate: python3 tools/make_meshes.py
b = 0.1;
W = 10;
ne = 31;
L = 1.3;
lc_contact = 2*L/ne;
lc_far = 0.5;
For i In {0:ne}
  Point(10+i) = {-L + 2*L*i/ne, 0, 0, lc_contact};
EndFor
For i In {0:ne-1}
  Line(100+i) = {10+i, 11+i};
  Transfinite Curve{100+i} = 2;
EndFor
Point(200) = {W, 0, 0, lc_far};
Point(201) = {W, -b, 0, lc_far};
Point(202) = {-W, -b, 0, lc_far};
Point(203) = {-W, 0, 0, lc_far};
Line(300) = {10+ne, 200};
Line(301) = {200, 201};
Line(302) = {201, 202};
Line(303) = {202, 203};
Line(304) = {203, 10};
Transfinite Curve{301, 303} = 3;
Physical Curve("contact") = {100:100+ne-1};
Physical Curve("free") = {300, 304};
Physical Curve("ends") = {301, 303};
Physical Curve("bonded") = {302};
Mesh.ElementOrder = 2;
Mesh.SecondOrderLinear = 0;
Mesh.MshFileVersion = 4.1;
