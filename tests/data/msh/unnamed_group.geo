// A square whose physical curve group 7 has no name.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Physical Curve("free", 1) = {1, 2, 3};
Physical Curve(7) = {4};
Mesh.ElementOrder = 2;
