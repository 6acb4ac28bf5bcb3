// A plate whose volume is in no Physical Volume (only a face and a corner are named): the
// fixture of tests/bad/gmsh_no_physical_volume.cfg, refused as such, not read as a 2D mesh.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 10, 1, 10};
Mesh.MeshSizeMin = 2; Mesh.MeshSizeMax = 2;
e = 1e-6;
Physical Surface("glued") = Surface In BoundingBox{-e, -e, -e, 10 + e, e, 10 + e};
Physical Point("lift") = Point In BoundingBox{-e, 1 - e, -e, e, 1 + e, e};
