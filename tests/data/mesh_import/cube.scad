// A box: import() of its STL, AMF and 3MF exports (OpenSCAD 2021.01,
// openscad -o cube.stl cube.scad, and .amf, .3mf) must give one solid.
cube([2, 3, 4]);
