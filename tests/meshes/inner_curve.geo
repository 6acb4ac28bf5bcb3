// A square with a curve inside it (Line In Surface): a node set that bounds no body, the
// fixture of tests/hostile/interface_inside_body.cfg.
Point(1) = {0, 0, 0}; Point(2) = {4, 0, 0}; Point(3) = {4, 4, 0}; Point(4) = {0, 4, 0};
Point(5) = {1, 2, 0}; Point(6) = {3, 2, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1}; Line(5) = {5, 6};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Line {5} In Surface {1};
Transfinite Curve{5} = 5;
Physical Surface("square") = {1};
Physical Curve("bottom") = {1};
Physical Curve("inner") = {5};
