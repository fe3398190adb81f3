// A square meshed with 4-node (cubic) line elements, which rollbem does not read.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Physical Curve("free", 1) = {1, 2, 3, 4};
Mesh.ElementOrder = 3;
