// Sector 0 <= phi <= 5.625 degrees (1/64 of the circle) of the cylindrical beryllium shell 8 cm <= r <= 10 cm, in
// metres: the collapse is radial, so a thin wedge between two symmetry planes gives the same solution as the
// quarter (shell_quarter2d.geo) at a sixteenth of the cost. The slanted side is named axis_y so that the quarter-shell
// scenes run on this geometry unchanged (--set mesh.geometry=geometry/shell_wedge2d.geo). The mesh size comes from
// the scene (mesh.size).
r0 = 0.08;
r1 = 0.10;
phi = Pi / 32;
Point(1) = {0, 0, 0};
Point(2) = {r0, 0, 0};
Point(3) = {r1, 0, 0};
Point(4) = {r1 * Cos(phi), r1 * Sin(phi), 0};
Point(5) = {r0 * Cos(phi), r0 * Sin(phi), 0};
Line(1) = {2, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("axis_x") = {1};
Physical Curve("outer") = {2};
Physical Curve("axis_y") = {3};
Physical Curve("inner") = {4};
Physical Surface("shell") = {1};
