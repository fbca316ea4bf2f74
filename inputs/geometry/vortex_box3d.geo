// The isentropic vortex extruded in z (docs/gpr-model.md 3.1): the box [0, 10]^2 x [0, 1] with six named faces.
// The square's unstructured triangles (size mesh.size) extruded in layers of about that height, each prism cut into
// three tetrahedra. The talk does not give the height; 1 keeps the volume L2 errors equal to the 2D ones for a
// z-independent error, and the finest of the paper's 3D meshes affordable. (Free tetrahedra in so thin a box were
// measured and not kept: slivers, and errors that did not converge.)
h = Mesh.MeshSizeMax;
Point(1) = {0, 0, 0};
Point(2) = {10, 0, 0};
Point(3) = {10, 10, 0};
Point(4) = {0, 10, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
out[] = Extrude {0, 0, 1} { Surface{1}; Layers{Ceil(1 / h)}; };
Physical Surface("bottom") = {out[2]};
Physical Surface("right") = {out[3]};
Physical Surface("top") = {out[4]};
Physical Surface("left") = {out[5]};
Physical Surface("back") = {1};
Physical Surface("front") = {out[0]};
Physical Volume("gas") = {out[1]};
