// Strip x0 <= x <= x0 + L, 0 <= y <= H for quasi-1D tests (viscous shock, heat conduction). The mesh size comes
// from the scene (mesh.size): the sides are cut uniformly at that size and the surface is meshed transfinitely
// (structured, alternating diagonals), so every row of cells is identical and the solution stays 1D.
DefineConstant[ L = 1.0, x0 = -0.5, H = 0.02 ];
Point(1) = {x0, 0, 0};
Point(2) = {x0 + L, 0, 0};
Point(3) = {x0 + L, H, 0};
Point(4) = {x0, H, 0};
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
Physical Surface("gas") = {1};
