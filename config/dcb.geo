// Double cantilever beam (config/dcb.cfg): two arms of thickness h and length L, one on each
// side of the midplane y = 0, glued along it beyond a precrack 0 < x < a0, loaded on their
// end faces x = 0. Each arm is four rectangles along x, with cells dx long from x = a0 - back
// to x = a0 + grow (around the crack tip and where the crack grows: the cohesive zone must
// span several cells) and about dxc long elsewhere. A node sits at the crack tip x = a0.
// ny cells through each arm, growing by the ratio q from the midplane out. The arms have
// their own points along y = 0 (an interface joins them), meshed alike (Transfinite); Q4.
DefineConstant[
  L = {100, Name "L"},        // arm length, mm
  h = {3, Name "h"},          // arm thickness, mm
  a0 = {30, Name "a0"},       // precrack length from the loaded end, mm
  back = {5, Name "back"},    // fine cells this far behind the crack tip, mm
  grow = {40, Name "grow"},   // and this far ahead of it, mm
  dx = {0.25, Name "dx"},     // cell length in the fine zone, mm
  dxc = {1, Name "dxc"},      // cell length elsewhere, mm
  ny = {6, Name "ny"},        // cells through an arm
  q = {1.2, Name "q"}         // growth ratio of the cells from the midplane out
];
x0 = a0 - back; x1 = a0 + grow;
n0 = Ceil(x0 / dxc - 1e-9);         // cells along the coarse part of the precrack
n1 = Ceil(back / dx - 1e-9);        // fine cells behind the tip
n2 = Ceil(grow / dx - 1e-9);        // fine cells ahead of the tip
n3 = Ceil((L - x1) / dxc - 1e-9);   // cells along the far end
X[] = {0, x0, a0, x1, L};

// upper arm (0 < y < h): points 1-5 on y = 0, 6-10 on y = h; lower arm (-h < y < 0): its own
// points 11-15 on y = 0, 16-20 on y = -h
For k In {0:4}
  Point(1 + k) = {X[k], 0, 0}; Point(6 + k) = {X[k], h, 0};
  Point(11 + k) = {X[k], 0, 0}; Point(16 + k) = {X[k], -h, 0};
  Line(21 + k) = {1 + k, 6 + k};     // upper arm, upwards from the midplane
  Line(31 + k) = {11 + k, 16 + k};   // lower arm, downwards from the midplane
EndFor
For k In {0:3}
  Line(1 + k) = {1 + k, 2 + k}; Line(6 + k) = {6 + k, 7 + k};        // upper: y = 0, y = h
  Line(11 + k) = {11 + k, 12 + k}; Line(16 + k) = {16 + k, 17 + k};  // lower: y = 0, y = -h
  Curve Loop(1 + k) = {1 + k, 22 + k, -(6 + k), -(21 + k)}; Plane Surface(1 + k) = {1 + k};
  Curve Loop(11 + k) = {11 + k, 32 + k, -(16 + k), -(31 + k)}; Plane Surface(11 + k) = {11 + k};
EndFor
Transfinite Curve{1, 6, 11, 16} = n0 + 1;
Transfinite Curve{2, 7, 12, 17} = n1 + 1;
Transfinite Curve{3, 8, 13, 18} = n2 + 1;
Transfinite Curve{4, 9, 14, 19} = n3 + 1;
Transfinite Curve{21:25, 31:35} = ny + 1 Using Progression q;   // fine at the midplane
Transfinite Surface{1:4, 11:14};
Recombine Surface{1:4, 11:14};

Physical Surface("upper") = {1:4};
Physical Surface("lower") = {11:14};
Physical Curve("upper_bottom") = {1:4};     // the interface, upper side (precrack and bonded)
Physical Curve("lower_top") = {11:14};      // the interface, lower side
Physical Curve("upper_end") = {21};         // loaded end face of the upper arm, x = 0
Physical Curve("lower_end") = {31};         // loaded end face of the lower arm
Physical Point("upper_tip") = {6};          // (0, h)
Physical Point("lower_tip") = {16};         // (0, -h)
Physical Point("far") = {20};               // (L, -h): holds the rigid-body motions
