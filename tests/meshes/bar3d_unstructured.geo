// The bar [-0.5, 0.5] x [0, 0.02]^2 of inputs/geometry/bar3d.geo with gmsh's unstructured (Delaunay) tetrahedra:
// flat cells (lambda_max(sum_k M_ik) up to 2.9 sum_k |c_k|) in every orientation. Test sod3d_tets: at order 1 a
// cell at the contact was crushed to 80 times its density before the time step's relaxation length.
SetFactory("OpenCASCADE");
Box(1) = {-0.5, 0, 0, 1, 0.02, 0.02};
Physical Surface("left") = {1};
Physical Surface("right") = {2};
Physical Surface("sides") = {3, 4, 5, 6};
Physical Volume("gas") = {1};
