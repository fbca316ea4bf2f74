// Full annulus r0 <= r <= r1 (Kidder shell) with a structured polar mesh that is invariant under rotation by one
// cell's angle: transfinite quadrilaterals of size about h = mesh.size, each split by the same diagonal.
h = Mesh.MeshSizeMax;
r0 = 0.9;
r1 = 1.0;
Point(1) = {0, 0, 0};
For k In {0:3}
  Point(10 + k) = {r0 * Cos(k * Pi / 2), r0 * Sin(k * Pi / 2), 0};
  Point(20 + k) = {r1 * Cos(k * Pi / 2), r1 * Sin(k * Pi / 2), 0};
  Line(10 + k) = {10 + k, 20 + k};
EndFor
For k In {0:3}
  k1 = (k + 1) % 4;
  Circle(20 + k) = {10 + k, 1, 10 + k1};
  Circle(30 + k) = {20 + k, 1, 20 + k1};
  Curve Loop(40 + k) = {10 + k, 30 + k, -(10 + k1), -(20 + k)};
  Plane Surface(40 + k) = {40 + k};
EndFor
nr = Ceil((r1 - r0) / h) + 1;
nt = Ceil(0.5 * Pi * 0.5 * (r0 + r1) / h) + 1;
Transfinite Curve{10:13} = nr;
Transfinite Curve{20:23, 30:33} = nt;
For k In {0:3}
  Transfinite Surface{40 + k} = {10 + k, 20 + k, 20 + (k + 1) % 4, 10 + (k + 1) % 4} Left;
EndFor
Physical Curve("outer") = {30:33};
Physical Curve("inner") = {20:23};
Physical Surface("gas") = {40:43};
