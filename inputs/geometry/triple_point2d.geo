// The triple-point domain [0, 7] x [0, 3] in three regions (inputs/triple_point2d.yaml): "left" [0, 1] x [0, 3],
// "bottom" [1, 7] x [0, 1.5], "top" [1, 7] x [1.5, 3], sharing their edges (a conformal mesh), walls all round.
// The mesh size comes from the scene (mesh.size).
h = Mesh.MeshSizeMax;
Point(1) = {0, 0, 0, h};
Point(2) = {1, 0, 0, h};
Point(3) = {7, 0, 0, h};
Point(4) = {7, 1.5, 0, h};
Point(5) = {1, 1.5, 0, h};
Point(6) = {7, 3, 0, h};
Point(7) = {1, 3, 0, h};
Point(8) = {0, 3, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 2};
Line(6) = {4, 6};
Line(7) = {6, 7};
Line(8) = {7, 5};
Line(9) = {7, 8};
Line(10) = {8, 1};
Curve Loop(1) = {1, -5, -8, 9, 10};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, 5};
Plane Surface(2) = {2};
Curve Loop(3) = {-4, 6, 7, 8};
Plane Surface(3) = {3};
Physical Curve("wall") = {1, 2, 3, 6, 7, 9, 10};
Physical Surface("left") = {1};
Physical Surface("bottom") = {2};
Physical Surface("top") = {3};
