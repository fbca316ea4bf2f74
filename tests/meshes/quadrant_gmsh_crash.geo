// A valid .geo that Debian bookworm's gmsh 4.8.4 cannot mesh: its 2D algorithm 8 (Frontal-Delaunay for quads)
// dies with a segmentation fault (the gmsh program too). unilag must name the file and exit with 2
// (mesh/GmshCrashGuard.hpp; test error_gmsh_crash).
Mesh.Algorithm = 8;
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
Physical Curve("axis_x") = {1};
Physical Curve("axis_y") = {4};
Physical Curve("outer") = {2, 3};
Physical Surface("gas") = {1};
