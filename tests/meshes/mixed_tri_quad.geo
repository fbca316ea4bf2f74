// Two halves of the quadrant in one region, the right one recombined into quadrangles: unilag must refuse the
// quadrangles by name (test error_mixed_elements), not drop them and report the seam as an unnamed boundary.
L = 1.2;
Point(1) = {0, 0, 0}; Point(2) = {L/2, 0, 0}; Point(3) = {L, 0, 0};
Point(4) = {L, L, 0}; Point(5) = {L/2, L, 0}; Point(6) = {0, L, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 1};
Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};
Recombine Surface{2};
Physical Curve("axis_x") = {1, 2};
Physical Curve("axis_y") = {6};
Physical Curve("outer") = {3, 4, 5};
Physical Surface("gas") = {1, 2};
