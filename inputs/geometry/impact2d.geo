// Copper square projectile (1 cm side) resting on an aluminium plate (4 cm x 1 cm), in metres, for the
// multi-material plastic impact (gpr.md 3.7). The two surfaces share the interface segment y = 0, |x| <= 5 mm
// (conformal mesh: the interface nodes belong to both materials). The mesh size comes from the scene (mesh.size).
a = 0.005;   // projectile half width
w = 0.02;    // plate half width
t = 0.01;    // plate thickness
Point(1) = {-w, -t, 0};
Point(2) = {w, -t, 0};
Point(3) = {w, 0, 0};
Point(4) = {a, 0, 0};
Point(5) = {-a, 0, 0};
Point(6) = {-w, 0, 0};
Point(7) = {a, 2 * a, 0};
Point(8) = {-a, 2 * a, 0};
Line(1) = {1, 2};  // plate bottom
Line(2) = {2, 3};  // plate right side
Line(3) = {3, 4};  // plate top, right of the projectile
Line(4) = {4, 5};  // interface
Line(5) = {5, 6};  // plate top, left of the projectile
Line(6) = {6, 1};  // plate left side
Line(7) = {4, 7};  // projectile right side
Line(8) = {7, 8};  // projectile top
Line(9) = {8, 5};  // projectile left side
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {-4, 7, 8, 9};
Plane Surface(2) = {2};
Physical Curve("plate_bottom") = {1};
Physical Curve("free") = {2, 3, 5, 6, 7, 8, 9};
Physical Surface("plate") = {1};
Physical Surface("projectile") = {2};
