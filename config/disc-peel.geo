// A circular coating patch (radius R, thickness t) meshed with tetrahedra, bonded by its
// face y = 0 and lifted at one point of its top rim: config/disc-peel.cfg.
SetFactory("OpenCASCADE");
DefineConstant[ R = {10, Name "R"}, t = {1, Name "t"}, h = {2, Name "h"} ];
Cylinder(1) = {0, 0, 0, 0, t, 0, R};   // the axis along y, from y = 0 to y = t
Point(100) = {R, t, 0};                 // where the patch is lifted, on the top rim
BooleanFragments{ Volume{1}; Delete; }{ Point{100}; Delete; }
Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;
e = 1e-6;
Physical Volume("patch") = {1};
Physical Surface("bonded") = Surface In BoundingBox{-R - e, -e, -R - e, R + e, e, R + e};
Physical Point("lift") = Point In BoundingBox{R - e, t - e, -e, R + e, t + e, e};
