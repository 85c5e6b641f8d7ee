// A non-convex solid, a block with a slot cut through it: import() of its
// STL, AMF and 3MF exports (OpenSCAD 2021.01) must give one solid.
difference() {
  cube([4, 3, 2]);
  translate([1, 1, -1]) cube([2, 3, 4]);
}
