// A layer one of whose points has a negative mesh size: gmsh 4.8 aborts on it from its
// OpenMP threads. The fixture of tests/bad/gmsh_point_size_negative.cfg: gmsh's process
// ends, rccm says so (exit 2) and writes nothing.
Point(1) = {0, 0, 0, 1}; Point(2) = {10, 0, 0, -1}; Point(3) = {10, 2, 0, 1}; Point(4) = {0, 2, 0, 1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Surface("layer") = {1}; Physical Curve("bonded") = {1}; Physical Curve("top") = {3};
