// corlab example mesh for `mesh.file` (read by corlab::fem::read_gmsh, gmsh_reader.hpp).
// Sphere R = 10 mm, 0.1 mm above a 20 mm x 20 mm substrate; coordinates x = r, y = z [m].
// Structured quads only (transfinite + recombine): a core square plus three ring blocks in the
// sphere, one graded rectangle for the substrate. Regenerate the .msh with
//   gmsh -2 -format msh41 example_impact.geo -o example_impact.msh
// (or corlab::fem::read_gmsh("example_impact.geo"), which meshes it on the fly).
// SPDX-License-Identifier: BSD-3-Clause
R = 0.01; gap = 1e-4; W = 0.02; D = 0.02;
zc = gap + R; c = 0.45 * R; s = Sqrt(2) / 2;
n = 13;  // nodes along each ring arc / core edge
m = 7;   // nodes across the ring

// substrate 0 <= r <= W, -D <= z <= 0
Point(1) = {0, -D, 0}; Point(2) = {W, -D, 0}; Point(3) = {W, 0, 0}; Point(4) = {0, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1} = 17 Using Progression 1.12;
Transfinite Curve{3} = 17 Using Progression 1 / 1.12;
Transfinite Curve{2} = 17 Using Progression 1 / 1.12;
Transfinite Curve{4} = 17 Using Progression 1.12;
Transfinite Surface{1};
Recombine Surface{1};

// sphere: centre (0, zc), lowest point P, ring points Q (-45 deg), Q2 (+45 deg), top T
Point(10) = {0, zc, 0};
Point(11) = {0, gap, 0};               // P
Point(12) = {R * s, zc - R * s, 0};    // Q
Point(13) = {R * s, zc + R * s, 0};    // Q2
Point(14) = {0, zc + R, 0};            // T
Point(15) = {0, zc - c, 0};            // A
Point(16) = {c, zc - c, 0};            // K
Point(17) = {c, zc + c, 0};            // K2
Point(18) = {0, zc + c, 0};            // A2
Circle(11) = {11, 10, 12};
Circle(12) = {12, 10, 13};
Circle(13) = {13, 10, 14};
Line(14) = {11, 15};  // axis P -> A
Line(15) = {15, 18};  // axis A -> A2
Line(16) = {18, 14};  // axis A2 -> T
Line(17) = {12, 16};  // Q -> K
Line(18) = {13, 17};  // Q2 -> K2
Line(19) = {15, 16};  // A -> K
Line(20) = {16, 17};  // K -> K2
Line(21) = {17, 18};  // K2 -> A2
Curve Loop(11) = {11, 17, -19, -14}; Plane Surface(11) = {11};  // bottom ring block
Curve Loop(12) = {12, 18, -20, -17}; Plane Surface(12) = {12};  // right ring block
Curve Loop(13) = {13, -16, -21, -18}; Plane Surface(13) = {13}; // top ring block
Curve Loop(14) = {19, 20, 21, -15}; Plane Surface(14) = {14};   // core
Transfinite Curve{11, 12, 13, 19, 20, 21, 15} = n;
Transfinite Curve{14, 17, 18} = m Using Progression 1.2;  // fine at the surface
Transfinite Curve{16} = m Using Progression 1 / 1.2;
Transfinite Surface{11, 12, 13, 14};
Recombine Surface{11, 12, 13, 14};

Physical Surface("sphere") = {11, 12, 13, 14};
Physical Surface("substrate") = {1};
Physical Curve("axis") = {4, 14, 15, 16};
Physical Curve("base") = {1};
Physical Curve("sphere_contact") = {11, 12};
Physical Curve("substrate_contact") = {3};
