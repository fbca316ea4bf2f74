// The bar [0, 1.25] x [0, 0.2]^2 with gmsh's unstructured tetrahedra (size from the scene), for a strong planar
// shock in 3D (tests/scenes/piston3d_tets.yaml): wide enough that most cells behind the shock touch no wall.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1.25, 0.2, 0.2};
Physical Surface("left") = {1};
Physical Surface("right") = {2};
Physical Surface("sides") = {3, 4, 5, 6};
Physical Volume("gas") = {1};
