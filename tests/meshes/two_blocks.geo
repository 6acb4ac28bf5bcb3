// Two blocks of L x h, one on the other, each with its own points along y = h (so that an
// interface can glue them), meshed alike: the fixture of tests/fem/test_gmsh_mesh.cpp and
// tests/model/test_bodies.cpp.
DefineConstant[ L = {10, Name "L"}, h = {2, Name "h"}, n = {11, Name "n"}, quads = {1, Name "quads"} ];
Point(1) = {0, 0, 0}; Point(2) = {L, 0, 0}; Point(3) = {L, h, 0}; Point(4) = {0, h, 0};
Point(5) = {0, h, 0}; Point(6) = {L, h, 0}; Point(7) = {L, 2 * h, 0}; Point(8) = {0, 2 * h, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{1, 3, 5, 7} = n; Transfinite Curve{2, 4, 6, 8} = 3;
Transfinite Surface{1, 2};
If (quads)
  Recombine Surface{1, 2};
EndIf
Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("bottom") = {1};
Physical Curve("lower_top") = {3};
Physical Curve("upper_bottom") = {5};
Physical Curve("top") = {7};
Physical Curve("lower_left") = {4};
Physical Curve("upper_left") = {8};
Physical Point("corner") = {7};
