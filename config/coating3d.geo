// A coating strip (L x t x W) glued on a thicker substrate, two hexahedral bodies with their
// own nodes along the interface y = 0: config/coating3d.cfg. OpenCASCADE boxes touching on a
// face, left unfused (no BooleanFragments: it would merge the two faces into one, shared by
// both bodies), and meshed alike: every edge Transfinite by the same cell size h, so the
// nodes of the coating's bottom and of the substrate's top coincide pair by pair. (gmsh's
// built-in kernel merges coincident points: extruded bodies would share their nodes there.)
SetFactory("OpenCASCADE");
DefineConstant[ L = {10, Name "L"}, t = {1, Name "t"}, H = {2, Name "H"}, W = {4, Name "W"}, h = {1, Name "h"} ];
Box(1) = {0, 0, 0, L, t, W};    // the coating, y in [0, t]
Box(2) = {0, -H, 0, L, H, W};   // the substrate, y in [-H, 0]
e = 1e-6;
edges() = Curve In BoundingBox{-e, -H - e, -e, L + e, t + e, W + e};
For i In {0:#edges() - 1}
  b() = BoundingBox Curve{edges(i)};
  Transfinite Curve{edges(i)} = Round(Sqrt((b(3) - b(0))^2 + (b(4) - b(1))^2 + (b(5) - b(2))^2) / h) + 1;
EndFor
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{:};
Physical Volume("coating") = {1};
Physical Volume("substrate") = {2};
// Faces by bounding box, each box's own: the plane y = 0 holds one face of each.
coat() = Boundary{ Volume{1}; };
sub() = Boundary{ Volume{2}; };
bottom() = {}; top() = {}; end() = {}; base() = {};
For i In {0:#coat() - 1}
  b() = BoundingBox Surface{coat(i)};
  If (Fabs(b(1)) < e && Fabs(b(4)) < e)
    bottom() += {coat(i)};
  EndIf
  If (Fabs(b(0)) < e && Fabs(b(3)) < e)
    end() += {coat(i)};
  EndIf
EndFor
For i In {0:#sub() - 1}
  b() = BoundingBox Surface{sub(i)};
  If (Fabs(b(1)) < e && Fabs(b(4)) < e)
    top() += {sub(i)};
  EndIf
  If (Fabs(b(1) + H) < e && Fabs(b(4) + H) < e)
    base() += {sub(i)};
  EndIf
EndFor
Physical Surface("coat_bottom") = {bottom()};
Physical Surface("coat_end") = {end()};
Physical Surface("sub_top") = {top()};
Physical Surface("sub_base") = {base()};
