// The plane annulus a < r < b about the origin, four quarter sectors in a polar grid of nr
// cells across and nq along each quarter (quads = 0: triangles): the fixture of the Lame
// tests of tests/app/test_curved.cpp. The grid is the same under a turn by one cell angle,
// so every node of a circle r = const is like every other.
DefineConstant[ a = {1, Name "a"}, b = {2, Name "b"}, nr = {4, Name "nr"}, nq = {6, Name "nq"},
                quads = {1, Name "quads"} ];
Point(1) = {0, 0, 0};
For k In {0:3}
  Point(10 + k) = {a * Cos(k * Pi / 2), a * Sin(k * Pi / 2), 0};
  Point(20 + k) = {b * Cos(k * Pi / 2), b * Sin(k * Pi / 2), 0};
EndFor
For k In {0:3}
  Line(10 + k) = {10 + k, 20 + k};                    // radial, at k * 90 degrees
  Circle(20 + k) = {10 + k, 1, 10 + (k + 1) % 4};     // the inner arc of quarter k
  Circle(30 + k) = {20 + k, 1, 20 + (k + 1) % 4};     // the outer arc of quarter k
EndFor
For k In {0:3}
  Curve Loop(k + 1) = {10 + k, 30 + k, -(10 + (k + 1) % 4), -(20 + k)};
  Plane Surface(k + 1) = {k + 1};
EndFor
Transfinite Curve{10:13} = nr + 1;
Transfinite Curve{20:23, 30:33} = nq + 1;
Transfinite Surface{1:4};
If (quads)
  Recombine Surface{1:4};
EndIf
Physical Surface("annulus") = {1:4};
Physical Curve("inner") = {20:23};
Physical Curve("outer") = {30:33};
