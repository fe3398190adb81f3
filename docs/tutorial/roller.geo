// Tutorial: an aluminium roller, R = 50 mm, on a rigid shaft of radius 10 mm, touching the
// x-axis at the origin (body A, above the contact). Units: mm.
R = 50;  rs = 10;
ne = 21;                 // contact elements
L = 0.5*21/17;           // contact segment |x| <= L: 1.24 Hertz half-widths for a = 0.5 mm
lc_contact = 2*L/ne;  lc_far = 2*Pi*R/48;  lc_shaft = 2*Pi*rs/24;
Point(1) = {0, R, 0};                                     // centre
For i In {0:ne}
  x = -L + 2*L*i/ne;
  Point(10+i) = {x, R - Sqrt(R*R - x*x), 0, lc_contact};  // contact element ends
EndFor
For i In {0:ne-1}
  Circle(100+i) = {10+i, 1, 11+i};
  Transfinite Curve{100+i} = 2;                           // exactly one element each
EndFor
Point(200) = {R, R, 0, lc_far};  Point(201) = {0, 2*R, 0, lc_far};  Point(202) = {-R, R, 0, lc_far};
Circle(300) = {10+ne, 1, 200};  Circle(301) = {200, 1, 201};
Circle(302) = {201, 1, 202};    Circle(303) = {202, 1, 10};
Point(400) = {rs, R, 0, lc_shaft};  Point(401) = {0, R+rs, 0, lc_shaft};
Point(402) = {-rs, R, 0, lc_shaft}; Point(403) = {0, R-rs, 0, lc_shaft};
Circle(500) = {400, 1, 401};  Circle(501) = {401, 1, 402};
Circle(502) = {402, 1, 403};  Circle(503) = {403, 1, 400};
Physical Curve("contact") = {100:100+ne-1};
Physical Curve("free") = {300, 301, 302, 303};
Physical Curve("shaft") = {500, 501, 502, 503};
