// A coating on a rigid cylinder (config/coating-curved.cfg): a circular-arc layer
// Rc < r < Rc + t about the origin, from the angle th0 (its free end, pulled) down to th1,
// in na x nt quadrilaterals (Transfinite: a polar grid).
DefineConstant[
  Rc = {20, Name "Rc"},             // cylinder radius, mm
  t = {2, Name "t"},                // coating thickness, mm
  th0 = {90, Name "th0"},           // angle of the pulled end, degrees (90: the top)
  th1 = {-30, Name "th1"},          // angle of the far end, degrees
  na = {60, Name "na"},             // cells along the arc
  nt = {4, Name "nt"}               // cells through the thickness
];
a0 = th0 * Pi / 180; a1 = th1 * Pi / 180;
Point(1) = {0, 0, 0};
Point(2) = {Rc * Cos(a0), Rc * Sin(a0), 0};               // the pulled end, on the cylinder
Point(3) = {(Rc + t) * Cos(a0), (Rc + t) * Sin(a0), 0};   // the pulled end, outside: the tip
Point(4) = {(Rc + t) * Cos(a1), (Rc + t) * Sin(a1), 0};
Point(5) = {Rc * Cos(a1), Rc * Sin(a1), 0};
Line(1) = {2, 3};          // the pulled end
Circle(2) = {3, 1, 4};     // the outer surface (an arc below 180 degrees)
Line(3) = {4, 5};          // the far end
Circle(4) = {5, 1, 2};     // the bonded face, on the cylinder
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nt + 1;
Transfinite Curve{2, 4} = na + 1;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("coating") = {1};
Physical Curve("bonded") = {4};
Physical Curve("outer") = {2};
Physical Curve("pulled_end") = {1};
Physical Curve("far_end") = {3};
Physical Point("tip") = {3};
Physical Point("heel") = {2};
