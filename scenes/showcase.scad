// capsim showcase: a small machined bracket that uses every construct capsim's
// scene format supports. showcase.csg is this file exported by OpenSCAD 2021.01,
// run in this directory (OpenSCAD resolves -o relative to the input file):
//   openscad -o showcase.csg showcase.scad
// capsim renders the export (spheres, boxes and cones traced exactly) from the
// camera statement kept at the top of showcase.csg (docs/models.md).

$fn = 64;  // only smooths OpenSCAD's own preview; capsim ignores it

// A module call is exported as group() { ... }.
module bolt(length) {
  union() {
    cylinder(h = length, d = 1.2);                                      // shank: d=
    translate([0, 0, length]) cylinder(h = 0.7, d1 = 2.4, d2 = 1.8);   // head: d1/d2 cone
  }
}

// Base plate: a box with a bore, a countersink and a slot (difference).
color("SteelBlue")
render(convexity = 4)
difference() {
  cube([14, 9, 2], center = true);
  translate([4.5, -2, 0]) cylinder(h = 3, r = 1.1, center = true);
  translate([4.5, -2, 0.31]) cylinder(h = 0.7, r1 = 1.1, r2 = 1.8);
  translate([-4.5, -2, 0]) scale([2, 1, 1]) cylinder(h = 3, r = 0.8, center = true);
}

// Upright: a block leaning back by a shear (multmatrix) with a cross bore.
color([0.78, 0.8, 0.84])
translate([0, 2, 1])
difference() {
  multmatrix([[1, 0, 0, 0], [0, 1, 0.2, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    translate([-3, 0, 0]) cube([6, 2, 5]);
  translate([0, -1, 3]) rotate([-90, 0, 0]) cylinder(h = 5, r = 1.1);
}

// Knob: the intersection of a sphere and a cube, turned about z.
color("#d2691e")
translate([0, -2, 2]) rotate(30)
intersection() {
  sphere(r = 1.4);
  cube(2, center = true);
}

// Bolts, one mirrored to the other side of the upright.
color("silver") {
  translate([4.8, 3, 1]) bolt(0.6);
  mirror([1, 0, 0]) translate([4.8, 3, 1]) bolt(0.6);
}

// A pointed cone tipped over about a skew axis, and a cone standing on its tip
// (r1 = 0) turned about x, y and z.
translate([2, 0.3, 1]) rotate(a = 25, v = [1, 1, 0])
  color([0.2, 0.6, 0.3]) cylinder(h = 2.5, r1 = 0.8, r2 = 0);
translate([-2, 0.3, 1]) rotate([180, 10, 20])
  color("Gold", 0.9) translate([0, 0, -2]) cylinder(h = 2, r1 = 0, r2 = 0.9);

// A washer (sphere scaled per axis) and a ball (uniform scale).
translate([4.5, 0.8, 1]) scale([1.2, 1.2, 0.3]) color("#8a2be2cc") sphere(d = 2);
translate([-4.5, 0.8, 1.5]) scale(0.5) sphere(1);

// A cube reflected through the tilted plane x + y = 0.
mirror([1, 1, 0]) translate([3.6, 2, 1]) color("crimson") cube([0.6, 0.6, 0.6]);

// Highlighted (#, rendered normally) and background (%, dropped by capsim) parts.
#translate([2.3, -3.6, 1]) cylinder(h = 0.4, r = 0.5);
%translate([0, 0, -1.6]) cube([18, 13, 1.2], center = true);
