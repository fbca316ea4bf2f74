// Octant [0, L]^3 (3D Sedov). The mesh size comes from the scene (mesh.size). unilag has gmsh optimise the
// tetrahedra below quality 0.6 (Mesh.OptimizeThreshold; gmsh's own default 0.3 left flat cells that capped the
// time step and overheated at the shock: docs/sedov.md, session 29); a line here would override it.
SetFactory("OpenCASCADE");
L = 1.2;
Box(1) = {0, 0, 0, L, L, L};
// OpenCASCADE numbers the box faces x = 0, x = L, y = 0, y = L, z = 0, z = L.
Physical Surface("symmetry_x") = {1};
Physical Surface("symmetry_y") = {3};
Physical Surface("symmetry_z") = {5};
Physical Surface("outer") = {2, 4, 6};
Physical Volume("gas") = {1};
