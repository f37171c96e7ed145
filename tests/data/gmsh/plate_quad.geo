// Fixture for tests/unit/gmsh_import_test.cpp: a 2 m x 0.5 m plate in the plane z = 0 of 4 x 2
// bilinear quadrilaterals. Units: m.
// Regenerate: gmsh -2 -format msh41 plate_quad.geo -o plate_quad.msh
Lx = 2.0; Ly = 0.5;
Point(1) = {0, 0, 0};
l[] = Extrude {Lx, 0, 0} { Point{1}; Layers{4}; };
s[] = Extrude {0, Ly, 0} { Line{l[1]}; Layers{2}; Recombine; };
e = 1e-6;
Physical Surface("plate") = {s[1]};
Physical Curve("clamped") = Curve In BoundingBox{-e, -e, -e, e, Ly + e, e};  // x = 0
