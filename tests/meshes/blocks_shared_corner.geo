// Two blocks of 10 x 2, one on the other, each with its own points along y = 2 but the corner
// (0, 2), which both share: an interface between them meets a node of both bodies there
// (tests/hostile/interface_bodies_share_a_node.cfg).
Point(1) = {0, 0, 0}; Point(2) = {10, 0, 0}; Point(3) = {10, 2, 0}; Point(4) = {0, 2, 0};
Point(6) = {10, 2, 0}; Point(7) = {10, 4, 0}; Point(8) = {0, 4, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {4, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 4};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{1, 3, 5, 7} = 11; Transfinite Curve{2, 4, 6, 8} = 3;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("bottom") = {1};
Physical Curve("lower_top") = {3};
Physical Curve("upper_bottom") = {5};
