// Unit square with 2-node elements, one group per side pair.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Transfinite Curve{1, 2, 3, 4} = 3;
Physical Curve("bottom", 1) = {1};
Physical Curve("sides", 2) = {2, 3, 4};
Mesh.ElementOrder = 1;
