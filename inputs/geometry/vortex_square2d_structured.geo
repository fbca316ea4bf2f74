// The isentropic vortex's square [0, 10]^2 (docs/gpr-model.md 3.1) as a structured mesh: n x n squares of side
// about mesh.size, each cut into two triangles with alternating diagonals. On it the specific volume converges at
// about 1.5 (the paper's order), against 1 on the unstructured square: docs/gpr-model.md 3.1 says why.
h = Mesh.MeshSizeMax;
n = Ceil(10 / h);
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
Transfinite Curve{1:4} = n + 1;
Transfinite Surface{1} = {1, 2, 3, 4} Alternate;
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Surface("gas") = {1};
