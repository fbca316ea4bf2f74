// Quadrant [0, L]^2 (2D Sedov). The mesh size comes from the scene (mesh.size).
L = 1.2;
Point(1) = {0, 0, 0};
Point(2) = {L, 0, 0};
Point(3) = {L, L, 0};
Point(4) = {0, L, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("axis_x") = {1};   // y = 0
Physical Curve("axis_y") = {4};   // x = 0
Physical Curve("outer") = {2, 3};
Physical Surface("gas") = {1};
