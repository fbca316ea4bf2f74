// Quarter annulus r0 <= r <= r1 (Kidder shell) with a structured polar mesh: transfinite quadrilaterals of size
// about h = mesh.size, split into triangles with alternating diagonals, so the mesh is symmetric about the quarter's
// diagonal and every ring of nodes starts on one radius. For studies of Kidder's shell without the irregularity of
// quarter_annulus2d.geo (--set mesh.geometry=geometry/quarter_annulus_polar2d.geo); see the README on its
// Rayleigh-Taylor unstable outer surface.
h = Mesh.MeshSizeMax;
r0 = 0.9;
r1 = 1.0;
Point(1) = {0, 0, 0};
Point(2) = {r0, 0, 0};
Point(3) = {r1, 0, 0};
Point(4) = {0, r1, 0};
Point(5) = {0, r0, 0};
Line(1) = {2, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
nr = Ceil((r1 - r0) / h) + 1;
nt = Ceil(0.5 * Pi * 0.5 * (r0 + r1) / h) + 1;
Transfinite Curve{1, 3} = nr;
Transfinite Curve{2, 4} = nt;
Transfinite Surface{1} Alternate;
Physical Curve("axis_x") = {1};
Physical Curve("outer") = {2};
Physical Curve("axis_y") = {3};
Physical Curve("inner") = {4};
Physical Surface("gas") = {1};
