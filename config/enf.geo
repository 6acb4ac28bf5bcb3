// End-notched flexure (config/enf.cfg): a beam 2L long made of two arms of thickness h, one on
// each side of the midplane y = 0, glued along it beyond a precrack 0 < x < a0; it rests on
// supports at its bottom corners (0, -h) and (2L, -h) and is pushed down at midspan through
// the top segment L - e < x < L + e. Each arm is five rectangles along x, with cells dx long
// from x = a0 - back to x = L + e (around the crack tip, where the crack grows, and under
// the load) and about dxc long elsewhere. A node sits at the crack tip x = a0. ny cells
// through each arm, growing by the ratio q from the midplane out. The arms have their own
// points along y = 0 (an interface joins them), meshed alike (Transfinite); Q4 cells.
DefineConstant[
  L = {50, Name "L"},         // half span, mm (supports at x = 0 and x = 2L)
  h = {3, Name "h"},          // arm thickness (half the beam's thickness), mm
  a0 = {35, Name "a0"},       // precrack length from the left support, mm
  back = {5, Name "back"},    // fine cells this far behind the crack tip, mm
  e = {1, Name "e"},          // half width of the loaded segment, mm
  dx = {0.25, Name "dx"},     // cell length in the fine zone, mm
  dxc = {1, Name "dxc"},      // cell length elsewhere, mm
  ny = {6, Name "ny"},        // cells through an arm
  q = {1.2, Name "q"}         // growth ratio of the cells from the midplane out
];
X[] = {0, a0 - back, a0, L - e, L + e, 2 * L};
N[] = {Ceil((a0 - back) / dxc - 1e-9), Ceil(back / dx - 1e-9), Ceil((L - e - a0) / dx - 1e-9),
       Ceil(2 * e / dx - 1e-9), Ceil((L - e) / dxc - 1e-9)};

// upper arm (0 < y < h): points 1-6 on y = 0, 11-16 on y = h; lower arm (-h < y < 0): its own
// points 21-26 on y = 0, 31-36 on y = -h
For k In {0:5}
  Point(1 + k) = {X[k], 0, 0}; Point(11 + k) = {X[k], h, 0};
  Point(21 + k) = {X[k], 0, 0}; Point(31 + k) = {X[k], -h, 0};
  Line(41 + k) = {1 + k, 11 + k};    // upper arm, upwards from the midplane
  Line(51 + k) = {21 + k, 31 + k};   // lower arm, downwards from the midplane
EndFor
For k In {0:4}
  Line(1 + k) = {1 + k, 2 + k}; Line(11 + k) = {11 + k, 12 + k};    // upper: y = 0, y = h
  Line(21 + k) = {21 + k, 22 + k}; Line(31 + k) = {31 + k, 32 + k}; // lower: y = 0, y = -h
  Transfinite Curve{1 + k, 11 + k, 21 + k, 31 + k} = N[k] + 1;
  Curve Loop(1 + k) = {1 + k, 42 + k, -(11 + k), -(41 + k)}; Plane Surface(1 + k) = {1 + k};
  Curve Loop(21 + k) = {21 + k, 52 + k, -(31 + k), -(51 + k)}; Plane Surface(21 + k) = {21 + k};
EndFor
Transfinite Curve{41:46, 51:56} = ny + 1 Using Progression q;   // fine at the midplane
Transfinite Surface{1:5, 21:25};
Recombine Surface{1:5, 21:25};

Physical Surface("upper") = {1:5};
Physical Surface("lower") = {21:25};
Physical Curve("upper_bottom") = {1:5};     // the interface, upper side (precrack and bonded)
Physical Curve("lower_top") = {21:25};      // the interface, lower side
Physical Curve("load") = {14};              // the loaded top segment, L - e < x < L + e
Physical Point("left_support") = {31};      // (0, -h)
Physical Point("right_support") = {36};     // (2L, -h)
