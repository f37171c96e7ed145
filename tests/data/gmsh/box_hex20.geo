// Fixture for tests/unit/gmsh_import_test.cpp: a 1.5 m x 0.8 m x 0.6 m box of 3 x 2 x 2 20-node
// (serendipity) hexahedra, structured by extrusion. Units: m.
// Regenerate: gmsh -3 -order 2 -format msh41 box_hex20.geo -o box_hex20.msh
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;  // 20-node hexahedra (type 17), not 27-node
Lx = 1.5; Ly = 0.8; Lz = 0.6;
Point(1) = {0, 0, 0};
l[] = Extrude {Lx, 0, 0} { Point{1}; Layers{3}; };
s[] = Extrude {0, Ly, 0} { Line{l[1]}; Layers{2}; Recombine; };
v[] = Extrude {0, 0, Lz} { Surface{s[1]}; Layers{2}; Recombine; };
e = 1e-6;
Physical Volume("body") = {v[1]};
Physical Surface("fixed") = Surface In BoundingBox{-e, -e, -e, e, Ly + e, Lz + e};     // x = 0
Physical Surface("top") = Surface In BoundingBox{-e, -e, Lz - e, Lx + e, Ly + e, Lz + e};  // z = Lz
