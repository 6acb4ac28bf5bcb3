// A block of Lx x H x Lz meshed with unstructured tetrahedra (OpenCASCADE kernel), its faces
// and two top edges as physical groups: the fixture of tests/model/test_gmsh_solid.cpp (a T4
// patch test and a block pressed onto a frictionless base).
SetFactory("OpenCASCADE");
DefineConstant[ Lx = {3, Name "Lx"}, H = {2, Name "H"}, Lz = {1.5, Name "Lz"}, h = {0.6, Name "h"} ];
Box(1) = {0, 0, 0, Lx, H, Lz};
Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;
e = 1e-6;
Physical Volume("block") = {1};
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, Lx + e, e, Lz + e};
Physical Surface("top") = Surface In BoundingBox{-e, H - e, -e, Lx + e, H + e, Lz + e};
Physical Surface("left") = Surface In BoundingBox{-e, -e, -e, e, H + e, Lz + e};
Physical Surface("back") = Surface In BoundingBox{-e, -e, -e, Lx + e, H + e, e};
Physical Curve("top_left") = Curve In BoundingBox{-e, H - e, -e, e, H + e, Lz + e};
Physical Curve("top_back") = Curve In BoundingBox{-e, H - e, -e, Lx + e, H + e, e};
