// The right half (x >= 0) of a disk of radius R1 about the origin, for the Hertz test of
// tests/app/test_curved.cpp: the contact arc from the bottom (0, -R1) to the angle thc is
// meshed uniformly in nc cells, the rest of the disk coarser away from it (triangles).
DefineConstant[ R1 = {10, Name "R1"}, thc = {0.3, Name "thc"}, nc = {24, Name "nc"},
                lc = {1.5, Name "lc"} ];
h = R1 * thc / nc;   // the cell size along the contact arc
Point(1) = {0, 0, 0, lc};
Point(2) = {0, -R1, 0, h};
Point(3) = {R1 * Sin(thc), -R1 * Cos(thc), 0, h};
Point(4) = {R1, 0, 0, lc};
Point(5) = {0, R1, 0, lc};
Circle(1) = {2, 1, 3};   // the contact arc
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Line(4) = {5, 2};        // the symmetry line x = 0
Transfinite Curve{1} = nc + 1;
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("disk") = {1};
Physical Curve("contact") = {1};
Physical Curve("axis") = {4};
Physical Point("top") = {5};
