// The meridian section 0 < r < a, 0 < z < L of a solid cylinder (x = r, y = z) in
// nr x nz quadrilaterals: the shear-lag fibre of tests/app/test_axisymmetric.cpp.
DefineConstant[ a = {1, Name "a"}, L = {50, Name "L"}, nr = {4, Name "nr"}, nz = {50, Name "nz"} ];
Point(1) = {0, 0, 0}; Point(2) = {a, 0, 0}; Point(3) = {a, L, 0}; Point(4) = {0, L, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nr + 1; Transfinite Curve{2, 4} = nz + 1;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("fibre") = {1};
Physical Curve("bottom") = {1};
Physical Curve("surface") = {2};
Physical Curve("top") = {3};
Physical Curve("axis") = {4};
