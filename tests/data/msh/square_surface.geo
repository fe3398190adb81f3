// The unit square of square_linear.geo, meshed in 2D and saved with everything Gmsh can put in
// a file: point elements, the triangles of a physical surface and parametric node coordinates
// (Mesh.SaveAll, Mesh.SaveParametric). Its boundary is the mesh of square_linear.msh.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Transfinite Curve{1, 2, 3, 4} = 3;
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("bottom", 1) = {1};
Physical Curve("sides", 2) = {2, 3, 4};
Physical Surface("body", 3) = {1};
Mesh.ElementOrder = 1;
Mesh.SaveAll = 1;
Mesh.SaveParametric = 1;
