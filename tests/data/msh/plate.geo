// Plate 40 x 20 with a hole of radius 4 at (20, 10). The top side is split into a
// "contact" segment between two "free" segments; the bottom is "fixed"; the hole is "shaft".
// Curves 2 and 4 are drawn against the loop direction (their elements come out reversed),
// the hole is drawn counter-clockwise: the reader must orient all of it.
Point(1) = {0, 0, 0};   Point(2) = {40, 0, 0};
Point(3) = {40, 20, 0}; Point(4) = {25, 20, 0};
Point(5) = {15, 20, 0}; Point(6) = {0, 20, 0};
Line(1) = {1, 2};
Line(2) = {3, 2};   // reversed
Line(3) = {3, 4};
Line(4) = {5, 4};   // reversed
Line(5) = {5, 6};
Line(6) = {6, 1};
Point(7) = {20, 10, 0}; Point(8) = {24, 10, 0}; Point(9) = {16, 10, 0};
Circle(7) = {8, 7, 9}; Circle(8) = {9, 7, 8};
Transfinite Curve{1} = 9; Transfinite Curve{2, 6} = 5;
Transfinite Curve{3, 5} = 4; Transfinite Curve{4} = 7;
Transfinite Curve{7, 8} = 5;
Physical Curve("fixed", 1) = {1};
Physical Curve("free", 2) = {2, 3, 5, 6};
Physical Curve("contact", 3) = {4};
Physical Curve("shaft", 4) = {7, 8};
Mesh.ElementOrder = 2;
