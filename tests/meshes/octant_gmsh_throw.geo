// A valid .geo on which Debian bookworm's gmsh 4.8.4 throws from its meshing threads (Mesh.RandomFactor = 0.5
// in 3D): unilag must name the file and exit with 2 (mesh/GmshCrashGuard.hpp; test error_gmsh_throw).
Mesh.RandomFactor = 0.5;
SetFactory("OpenCASCADE");
L = 1.2;
Box(1) = {0, 0, 0, L, L, L};
Physical Surface("symmetry_x") = {1};
Physical Surface("symmetry_y") = {3};
Physical Surface("symmetry_z") = {5};
Physical Surface("outer") = {2, 4, 6};
Physical Volume("gas") = {1};
