// Bar x0 <= x <= x0 + L, 0 <= y, z <= H for quasi-1D tests in 3D (Sod's shock tube on tetrahedra). The strip of
// strip2d.geo (structured, alternating diagonals, size mesh.size) extruded in z in layers of that size, each prism cut
// into three tetrahedra: every slab of cells along x is the same, so the solution stays 1D.
DefineConstant[ L = 1.0, x0 = -0.5, H = 0.02 ];
h = Mesh.MeshSizeMax;
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
out[] = Extrude {0, 0, H} { Surface{1}; Layers{Ceil(H / h)}; };
Physical Surface("left") = {out[5]};
Physical Surface("right") = {out[3]};
Physical Surface("sides") = {1, out[0], out[2], out[4]};
Physical Volume("gas") = {out[1]};
