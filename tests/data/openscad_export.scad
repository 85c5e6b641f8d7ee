// Source of openscad_export.csg, written by OpenSCAD 2021.01 with
//   openscad -o openscad_export.csg openscad_export.scad
// parser_test.cpp checks the parsed export against the values below, so keep
// the order of the statements.
module pair() { sphere(0.5); translate([2, 0, 0]) sphere(0.5); }

sphere(2);                                           // primitive 0
sphere(d = 3, $fn = 20);                             // 1
cube(2);                                             // 2
cube([1, 2, 3], center = true);                      // 3
cylinder(5, 1, 2);                                   // 4: h, r1, r2
cylinder(h = 2, d = 4, center = true);               // 5
cylinder(h = 2, d1 = 4, d2 = 0);                     // 6
translate([1, 2, 3]) sphere();                       // 7
rotate(45) cube();                                   // 8
rotate([10, 20, 30]) cube();                         // 9
rotate(a = 30, v = [1, 1, 0]) cube();                // 10
rotate(a = [0, 0, 0]) cube();                        // 11
scale(2) cube();                                     // 12
scale([1, 2, 3]) cube();                             // 13
mirror([1, 1, 0]) cube();                            // 14
multmatrix([[1, 0.5, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]) cube();  // 15
color("red") sphere();                               // 16
color([0, 1, 0]) sphere();                           // 17
color("#ff000080") sphere();                         // 18
color(c = "blue", alpha = 0.5) sphere();             // 19
color("#abc") sphere();                              // 20
color(alpha = 0.25) sphere();                        // 21: colour unset, alpha only
%sphere(5);                                          // dropped
#cube(3);                                            // 22
*cube(7);                                            // not exported
union() { sphere(); cube(); }                        // 23, 24
difference() { cube(); sphere(); }                   // 25, 26
intersection() { cube(); sphere(); }                 // 27, 28
render(convexity = 4) cube();                        // 29
pair();                                              // 30, 31 (a group)
group();                                             // empty
union() {}                                           // empty
