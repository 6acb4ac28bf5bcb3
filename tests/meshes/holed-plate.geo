// A square plate (20 x 20 mm, 1 mm thick along y) with a bolt hole of radius 4 through its
// centre, bonded by its face y = 0 and lifted at one top corner: an interface with a hole,
// for tools/plot's beta map (tests/check_beta_map.py). Names as config/disc-peel.geo's.
SetFactory("OpenCASCADE");
DefineConstant[ h = {3, Name "h"} ];
Box(1) = {-10, 0, -10, 20, 1, 20};
Cylinder(2) = {0, 0, 0, 0, 1, 0, 4};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;
e = 1e-6;
Physical Volume("patch") = {3};
Physical Surface("bonded") = Surface In BoundingBox{-10 - e, -e, -10 - e, 10 + e, e, 10 + e};
Physical Point("lift") = Point In BoundingBox{10 - e, 1 - e, 10 - e, 10 + e, 1 + e, 10 + e};
