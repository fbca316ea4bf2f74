// Quarter of a cylindrical beryllium shell, 8 cm <= r <= 10 cm (Howell & Ball collapse, docs/gpr-model.md 3.6), in
// metres. The mesh size comes from the scene (mesh.size).
r0 = 0.08;
r1 = 0.10;
Point(1) = {0, 0, 0};
Point(2) = {r0, 0, 0};
Point(3) = {r1, 0, 0};
Point(4) = {0, r1, 0};
Point(5) = {0, r0, 0};
Line(1) = {2, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("axis_x") = {1};
Physical Curve("outer") = {2};
Physical Curve("axis_y") = {3};
Physical Curve("inner") = {4};
Physical Surface("shell") = {1};
