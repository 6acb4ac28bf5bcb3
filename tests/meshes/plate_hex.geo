// A plate of n x 1 x n mm meshed with n x 1 x n hexahedra of 1 mm (a transfinite square
// extruded in layers), named like the built-in box: the fixture of
// tests/model/test_gmsh_solid.cpp (the corner peel on a gmsh mesh against the built-in box).
DefineConstant[ n = {4, Name "n"} ];
Point(1) = {0, 0, 0}; Point(2) = {n, 0, 0}; Point(3) = {n, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = n + 1; Transfinite Curve{2, 4} = 2;
Transfinite Surface{1}; Recombine Surface{1};
out[] = Extrude {0, 0, n} { Surface{1}; Layers{n}; Recombine; };
e = 1e-6;
Physical Volume("plate") = {out[1]};
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, n + e, e, n + e};
Physical Point("top_left_back") = {4};
