// The meridian section a < r < b, 0 < z < h of a thick cylinder (x = r, y = z), in
// nr x nz quadrilaterals (quads = 0: triangles): the Lame fixture of
// tests/app/test_axisymmetric.cpp.
DefineConstant[ a = {1, Name "a"}, b = {2, Name "b"}, h = {0.25, Name "h"},
                nr = {4, Name "nr"}, nz = {1, Name "nz"}, quads = {1, Name "quads"} ];
Point(1) = {a, 0, 0}; Point(2) = {b, 0, 0}; Point(3) = {b, h, 0}; Point(4) = {a, h, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nr + 1; Transfinite Curve{2, 4} = nz + 1;
Transfinite Surface{1};
If (quads)
  Recombine Surface{1};
EndIf
Physical Surface("wall") = {1};
Physical Curve("bottom") = {1};
Physical Curve("outer") = {2};
Physical Curve("top") = {3};
Physical Curve("inner") = {4};
