// The duct of seed 002 paper 3 §3(3) (1 m x 0.2 m x 0.1 m) as an unstructured hexahedral mesh:
// a recombined (all-quadrangle) unstructured mesh of the x-y cross-section, extruded in z.
//   gmsh -3 -format msh41 -setnumber lc 0.05 -setnumber layers 2 duct.geo -o duct_lc050.msh
If (!Exists(lc))
  lc = 0.05;
EndIf
If (!Exists(layers))
  layers = 2;
EndIf
Point(1) = {0, 0, 0, lc};
Point(2) = {1, 0, 0, lc};
Point(3) = {1, 0.2, 0, lc};
Point(4) = {0, 0.2, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Mesh.Algorithm = 6;          // frontal-Delaunay, then Blossom recombination into quadrangles
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.ElementOrder = 1;
Recombine Surface{1};
out[] = Extrude {0, 0, 0.1} { Surface{1}; Layers{layers}; Recombine; };
// out[0]: top, out[1]: volume, out[2..5]: the sides extruded from lines 1..4
Physical Surface("inlet") = {out[5]};    // x = 0 (from line 4)
Physical Surface("outlet") = {out[3]};   // x = 1 (from line 2)
Physical Surface("walls") = {1, out[0], out[2], out[4]};
Physical Volume("air") = {out[1]};
