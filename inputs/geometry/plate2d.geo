// Beryllium plate [-3, 3] x [-0.5, 0.5] cm (elastic vibration, docs/gpr-model.md 3.9), in metres. The mesh size comes
// from the scene (mesh.size); the rectangle is meshed transfinitely (structured, alternating diagonals) so the mesh is
// symmetric about both axes.
Point(1) = {-0.03, -0.005, 0};
Point(2) = {0.03, -0.005, 0};
Point(3) = {0.03, 0.005, 0};
Point(4) = {-0.03, 0.005, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Surface{1} Alternate;
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Surface("plate") = {1};
