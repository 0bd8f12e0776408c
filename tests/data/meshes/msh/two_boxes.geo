// Two boxes stacked into the unit cube, each a physical volume, the bottom face a physical
// surface. The .msh files next to this one were written from it by Gmsh 4.8.4 (Debian gmsh):
//   for v in 2.2 4.1; do for b in 0 1; do
//     gmsh -3 two_boxes.geo -format msh$(echo $v | tr -d .) -setnumber Mesh.MshFileVersion $v \
//          -setnumber Mesh.Binary $b -o two_boxes_v${v}_$( [ $b = 1 ] && echo binary || echo ascii ).msh
//   done; done
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 0.5};
Box(2) = {0, 0, 0.5, 1, 1, 0.5};
Coherence;
Physical Volume("lower", 11) = {1};
Physical Volume("upper", 12) = {2};
Physical Surface("bottom", 21) = {5};
Mesh.MeshSizeMin = 0.4;
Mesh.MeshSizeMax = 0.4;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
