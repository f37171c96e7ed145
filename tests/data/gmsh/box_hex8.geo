// Fixture for tests/unit/gmsh_import_test.cpp: a 2 m x 1 m x 0.5 m box of 4 x 2 x 2 trilinear
// hexahedra, structured by extrusion. Units: m.
// Regenerate: gmsh -3 -format msh41 box_hex8.geo -o box_hex8.msh
Lx = 2.0; Ly = 1.0; Lz = 0.5;
Point(1) = {0, 0, 0};
l[] = Extrude {Lx, 0, 0} { Point{1}; Layers{4}; };
s[] = Extrude {0, Ly, 0} { Line{l[1]}; Layers{2}; Recombine; };
v[] = Extrude {0, 0, Lz} { Surface{s[1]}; Layers{2}; Recombine; };
e = 1e-6;
Physical Volume("body") = {v[1]};
Physical Surface("fixed") = Surface In BoundingBox{-e, -e, -e, e, Ly + e, Lz + e};     // x = 0
Physical Surface("tip") = Surface In BoundingBox{Lx - e, -e, -e, Lx + e, Ly + e, Lz + e};  // x = Lx
Physical Curve(7) = Curve In BoundingBox{-e, -e, -e, e, e, Lz + e};  // unnamed: the z edge at x = y = 0
