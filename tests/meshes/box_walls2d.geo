// Unit square whose four sides are one boundary group, "walls": a slip wall made of several planes
// (docs/gpr-model.md 3.3). The mesh size comes from the scene (mesh.size).
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("walls") = {1, 2, 3, 4};
Physical Surface("gas") = {1};
