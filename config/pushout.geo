// Push-out of a fibre from a matrix cylinder (config/pushout.cfg): the meridian section
// (x = r, y = z) of a fibre 0 < r < a and the matrix around it, a < r < R, both 0 < z < H.
// The two bodies have their own points along r = a (so that an interface can join them),
// meshed alike (Transfinite), the matrix finer towards the fibre.
DefineConstant[
  a = {0.07, Name "a"},      // fibre radius, mm (an SCS-6-like SiC fibre is 0.14 mm across)
  R = {0.35, Name "R"},      // matrix cylinder radius, mm
  H = {0.5, Name "H"},       // slice thickness, mm
  nf = {4, Name "nf"},       // cells across the fibre radius
  nm = {8, Name "nm"},       // cells across the matrix
  nz = {20, Name "nz"}       // cells along z (the interface has nz + 1 contact nodes)
];
Point(1) = {0, 0, 0}; Point(2) = {a, 0, 0}; Point(3) = {a, H, 0}; Point(4) = {0, H, 0};
Point(5) = {a, 0, 0}; Point(6) = {R, 0, 0}; Point(7) = {R, H, 0}; Point(8) = {a, H, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};   // fibre
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};   // matrix
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{1, 3} = nf + 1;
Transfinite Curve{5} = nm + 1 Using Progression 1.2;
Transfinite Curve{7} = nm + 1 Using Progression 1 / 1.2;
Transfinite Curve{2, 4, 6, 8} = nz + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Surface("fibre") = {1};
Physical Surface("matrix") = {2};
Physical Curve("fibre_bottom") = {1};
Physical Curve("fibre_side") = {2};
Physical Curve("fibre_top") = {3};
Physical Curve("axis") = {4};
Physical Curve("matrix_bottom") = {5};
Physical Curve("matrix_outer") = {6};
Physical Curve("matrix_top") = {7};
Physical Curve("matrix_side") = {8};
