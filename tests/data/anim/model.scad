// An animation for `openscad --animate 4` and `capsim --frames 4` alike: it
// uses only module calls whose arguments are expressions over $t, so capsim
// reads this file as it is. The test compares capsim's frames of it with its
// frames of OpenSCAD's exports f00000.csg ... f00003.csg.
translate([lookup($t, [[0, -2], [0.5, 1], [1, 2]]), 0, 0])
  rotate([0, 0, 360 * $t])
    cube([2, 1, 1], center = true);
translate([0, 3 * sin(90 * $t + 30), 1])
  color([0.9, 0.3, 0.2])
    sphere(r = $t < 0.5 ? 1 : 0.6);
rotate([30 * $t, 0, 45 * $t])
  translate([0, 0, -2.5])
    cylinder(h = 1 + $t, r1 = 1, r2 = 0.5 + 0.25 * cos(360 * $t));
