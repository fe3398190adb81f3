// Annulus a = 10 (hole, group "inner"), b = 20 (group "outer"), quadratic elements.
// Both circles are drawn counter-clockwise, so the hole's loop must be turned round by the reader.
a = 10; b = 20; n = 8;
Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0};  Point(3) = {-a, 0, 0};
Point(4) = {b, 0, 0};  Point(5) = {-b, 0, 0};
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 2};
Circle(3) = {4, 1, 5}; Circle(4) = {5, 1, 4};
Transfinite Curve{1, 2} = n + 1;
Transfinite Curve{3, 4} = n + 1;
Physical Curve("inner", 11) = {1, 2};
Physical Curve("outer", 12) = {3, 4};
Mesh.ElementOrder = 2;
