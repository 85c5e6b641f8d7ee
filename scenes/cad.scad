// CAD: a machined bearing bracket, the kind of model the paper calls CAD
// (178-185 parts): a base plate with counterbored holes, adjustment slots,
// a rounded pocket, a T-slot, nut traps and a field of tapped holes; a bearing
// housing with a stepped bore, a bolt circle and gussets; a round boss with
// radial slots. Every feature is cut or added by a boolean, and every edge
// break is a chamfer: a box turned 45 degrees on straight edges, a cone on
// round ones.
//
// cad.csg is this file exported by OpenSCAD 2021.01 (an absolute -o path,
// because OpenSCAD writes a relative one beside the input):
//   openscad -o "$PWD/scenes/cad.csg" scenes/cad.scad
// capsim renders the export as is, with its default view and light.
//
// Units: millimetres. The plate lies on z = 0, 160 along x and 120 along y;
// OpenSCAD's default view looks at its front (-y) and right (+x) faces.

$fn = 48;  // only smooths OpenSCAD's own preview; capsim ignores it

metal = [0.72, 0.74, 0.78];

plate = [160, 120, 18];       // x, y, z
corner_r = 12;                // rounded plate corners
grid = [5, 4];                // tapped holes in the field, along x and y

// ---- features --------------------------------------------------------------
// A 45-degree chamfer cone at the mouth of a hole of radius r whose face is
// at z = top (the cone reaches 1 above the face, so no faces coincide).
module mouth_chamfer(r, c, top) {
  translate([0, 0, top - c]) cylinder(h = c + 1, r1 = r, r2 = r + c + 1);
}

// A drilled hole from the face at z = top down to z = bottom, its mouth
// chamfered (2 primitives).
module hole(r, top, bottom = -1, c = 1) {
  translate([0, 0, bottom]) cylinder(h = top - bottom + 1, r = r);
  mouth_chamfer(r, c, top);
}

// A counterbored through hole (3 primitives).
module counterbored(r, cb_r, cb_depth, top) {
  translate([0, 0, -1]) cylinder(h = top + 2, r = r);
  translate([0, 0, top - cb_depth]) cylinder(h = cb_depth + 1, r = cb_r);
  mouth_chamfer(cb_r, 1, top);
}

// A slot along x, length l between the centres of its round ends, width w,
// from z = bottom to z = top + 1 (3 primitives).
module slot(l, w, bottom, top) {
  translate([-l / 2, -w / 2, bottom]) cube([l, w, top - bottom + 1]);
  for (s = [-1, 1]) translate([s * l / 2, 0, bottom]) cylinder(h = top - bottom + 1, r = w / 2);
}

// A rectangular pocket a x b with corner radius r, from z = bottom up
// through z = top (6 primitives).
module rounded_pocket(a, b, r, bottom, top) {
  translate([-a / 2, -b / 2 + r, bottom]) cube([a, b - 2 * r, top - bottom + 1]);
  translate([-a / 2 + r, -b / 2, bottom]) cube([a - 2 * r, b, top - bottom + 1]);
  for (sx = [-1, 1], sy = [-1, 1])
    translate([sx * (a / 2 - r), sy * (b / 2 - r), bottom]) cylinder(h = top - bottom + 1, r = r);
}

// A straight edge along x at (y, z), chamfered by c: a box turned 45 degrees
// about x, centred on the edge (1 primitive).
module edge_chamfer_x(length, y, z, c) {
  translate([0, y, z]) rotate([45, 0, 0]) cube([length, c * sqrt(2), c * sqrt(2)], center = true);
}
module edge_chamfer_y(length, x, z, c) {
  translate([x, 0, z]) rotate([0, 45, 0]) cube([c * sqrt(2), length, c * sqrt(2)], center = true);
}
module edge_chamfer_z(length, x, y, z, c) {
  translate([x, y, z]) rotate(45) cube([c * sqrt(2), c * sqrt(2), length], center = true);
}

// A pocket for a hex nut, across flats s, from z = bottom up through z = top:
// the intersection of three boxes (3 primitives).
module hex_pocket(s, bottom, top) {
  translate([0, 0, (bottom + top + 1) / 2]) intersection() {
    cube([s, 2 * s, top - bottom + 1], center = true);
    rotate(60) cube([s, 2 * s, top - bottom + 1], center = true);
    rotate(120) cube([s, 2 * s, top - bottom + 1], center = true);
  }
}

// Along y through the point (x, z), centred on y0.
module along_y(x, y0, z, h, r1, r2) {
  translate([x, y0, z]) rotate([-90, 0, 0]) translate([0, 0, -h / 2]) cylinder(h = h, r1 = r1, r2 = r2);
}

// Along x through the point (y, z), from x0 for length h.
module along_x(x0, y, z, h, r1, r2) {
  translate([x0, y, z]) rotate([0, 90, 0]) cylinder(h = h, r1 = r1, r2 = r2);
}

// ---- the base plate ---------------------------------------------------------
px = plate[0] / 2;
py = plate[1] / 2;
t = plate[2];
corners = [[-1, -1], [1, -1], [-1, 1], [1, 1]];

module plate_blank() {
  translate([-px, -py + corner_r, 0]) cube([plate[0], plate[1] - 2 * corner_r, t]);
  translate([-px + corner_r, -py, 0]) cube([plate[0] - 2 * corner_r, plate[1], t]);
  for (c = corners) translate([c[0] * (px - corner_r), c[1] * (py - corner_r), 0]) cylinder(h = t, r = corner_r);
}

module plate_cuts() {
  // The straight top edges, chamfered by boxes turned 45 degrees...
  edge_chamfer_x(plate[0] - 2 * corner_r, -py, t, 2);
  edge_chamfer_x(plate[0] - 2 * corner_r, py, t, 2);
  edge_chamfer_y(plate[1] - 2 * corner_r, -px, t, 2);
  edge_chamfer_y(plate[1] - 2 * corner_r, px, t, 2);
  // ... and the rounded corners' top edges by a ring outside a cone, kept to
  // the corner's quarter.
  for (c = corners) translate([c[0] * (px - corner_r), c[1] * (py - corner_r), 0])
    intersection() {
      difference() {
        translate([0, 0, t - 3]) cylinder(h = 4, r = corner_r + 1);
        translate([0, 0, t - 3]) cylinder(h = 4, r1 = corner_r + 1, r2 = corner_r - 3);
      }
      translate([c[0] > 0 ? 0 : -corner_r - 2, c[1] > 0 ? 0 : -corner_r - 2, t - 4]) cube([corner_r + 2, corner_r + 2, 6]);
    }
  // Mounting holes, counterbored, at the four corners.
  for (c = corners) translate([c[0] * (px - corner_r), c[1] * (py - corner_r), 0]) counterbored(4.5, 8, 6, t);
  // Two adjustment slots along x at the front left, each with a counterbore slot.
  for (y = [-44, -26]) translate([-36, y, 0]) {
    slot(26, 9, -1, t);
    slot(26, 15, t - 5, t);
  }
  // A rounded pocket at the front centre, with two holes in its floor.
  translate([2, -33, 0]) {
    rounded_pocket(30, 40, 6, 8, t);
    for (y = [-10, 10]) translate([0, y, 0]) hole(3, 8);
  }
  // A T-slot along x across the plate, its mouth chamfered on both sides.
  translate([-px - 1, -4, t - 10]) cube([plate[0] + 2, 8, 11]);
  translate([-px - 1, -8, t - 10]) cube([plate[0] + 2, 16, 5]);
  for (s = [-1, 1]) edge_chamfer_x(plate[0] + 2, s * 4, t, 1.5);
  // The field of tapped holes at the front right, chamfered.
  for (i = [0 : grid[0] - 1], j = [0 : grid[1] - 1])
    translate([24 + i * 8, -50 + j * 10, 0]) hole(2.5, t, 4);
  // Two hexagonal nut pockets, with their bolt holes.
  for (x = [-68, 68]) translate([x, -24, 0]) {
    hex_pocket(10, t - 6, t);
    hole(3, t - 6);
  }
  // Dowel holes.
  for (x = [-68, 68]) translate([x, 20, 0]) hole(2.5, t, 6, 0.5);
  // Tapped holes in the front and right faces, chamfered.
  for (x = [-50, -20, 10, 40]) translate([x, -py, t / 2]) rotate([90, 0, 0]) hole(2.5, 0, -6, 1);
  for (y = [-14, 20, 34]) translate([px, y, t / 2]) rotate([0, 90, 0]) hole(2.5, 0, -6, 1);
}

// ---- the bearing housing, at the back left -----------------------------------
housing_x = -30;              // centre of the housing along x
housing_w = 60;               // its width along x
housing_y = [14, 54];         // its front and back faces
bore_z = 58;                  // height of the bearing bore's axis
bore = [16, 21];              // radii of the bore and of the bearing seats
gusset = [16, 50];            // the gussets' length along x and height

module gusset_right() {
  // A box at the housing's right side cut to a triangle by a box turned about y.
  y0 = housing_y[0]; d = housing_y[1] - y0;
  intersection() {
    translate([housing_x + housing_w / 2 - 1, y0 + d / 2 - 5, t - 1]) cube([gusset[0] + 1, 10, gusset[1] + 1]);
    translate([housing_x + housing_w / 2 + gusset[0], y0 + d / 2, t]) rotate([0, -atan(gusset[0] / gusset[1]), 0])
      translate([-40, -6, -10]) cube([40, 12, 80]);
  }
}

module housing_blank() {
  y0 = housing_y[0]; d = housing_y[1] - y0;
  translate([housing_x - housing_w / 2, y0, 0]) cube([housing_w, d, bore_z]);
  along_y(housing_x, y0 + d / 2, bore_z, d, housing_w / 2, housing_w / 2);
  gusset_right();
  translate([housing_x, 0, 0]) mirror([1, 0, 0]) translate([-housing_x, 0, 0]) gusset_right();
}

module housing_cuts() {
  w = housing_w; y0 = housing_y[0]; y1 = housing_y[1]; yc = (y0 + y1) / 2; d = y1 - y0;
  // The block's vertical edges chamfered.
  for (sx = [-1, 1], y = [y0, y1])
    edge_chamfer_z(bore_z - t + 2, housing_x + sx * w / 2, y, (bore_z + t) / 2, 2);
  // The bearing bore, counterbored for a bearing from each side, the seats
  // grooved for circlips, the mouths chamfered.
  along_y(housing_x, yc, bore_z, d + 2, bore[0], bore[0]);
  for (s = [-1, 1]) {
    along_y(housing_x, yc + s * (d / 2 - 5), bore_z, 12, bore[1], bore[1]);
    along_y(housing_x, yc + s * (d / 2 - 7), bore_z, 1.6, bore[1] + 1.5, bore[1] + 1.5);
    along_y(housing_x, yc + s * d / 2, bore_z, 4, s > 0 ? bore[1] - 1 : bore[1] + 3, s > 0 ? bore[1] + 3 : bore[1] - 1);
  }
  // A bolt circle of six tapped holes in the front face, for a cover.
  for (k = [0 : 5])
    translate([housing_x, 0, bore_z]) rotate([0, k * 60 + 30, 0]) translate([26, 0, 0]) {
      along_y(0, y0 + 5.9, 0, 12, 2, 2);
      along_y(0, y0, 0, 2, 3, 1);
    }
  // A lubrication hole from the top, spot-faced.
  translate([housing_x, yc, 0]) hole(2.5, bore_z + w / 2 - 1.5, bore_z, 0.8);
  translate([housing_x, yc, bore_z + w / 2 - 1.5]) cylinder(h = 5, r = 7);
  // Two tapped holes beside it, for a guard.
  for (s = [-1, 1]) translate([housing_x, yc + s * 13, 0]) hole(2, bore_z + w / 2, bore_z + w / 2 - 10);
  // A lightening hole in each gusset.
  for (s = [-1, 1]) along_y(housing_x + s * (w / 2 + 5), yc, t + 10, 12, 3, 3);
}

// ---- the round boss, at the back right -----------------------------------------
boss = [46, 30];              // centre x, y
boss_r = 18;
boss_top = 46;

module boss_blank() {
  translate([boss[0], boss[1], 0]) {
    cylinder(h = boss_top - 2, r = boss_r);
    translate([0, 0, boss_top - 2]) cylinder(h = 2, r1 = boss_r, r2 = boss_r - 2);  // its top edge chamfered
  }
}

module boss_cuts() {
  translate([boss[0], boss[1], 0]) {
    // A stepped bore, chamfered.
    translate([0, 0, -1]) cylinder(h = boss_top + 2, r = 7);
    translate([0, 0, boss_top - 12]) cylinder(h = 13, r = 10);
    mouth_chamfer(10, 1, boss_top);
    translate([-2.5, 5, -1]) cube([5, 4.5, boss_top + 2]);                // a keyway along the bore
    // Four radial slots across the top.
    for (a = [0, 90]) rotate(a) translate([0, 0, boss_top]) cube([2 * boss_r + 2, 5, 12], center = true);
    // Four tapped holes between the slots.
    for (k = [0 : 3]) rotate(k * 90 + 45) translate([14, 0, 0]) hole(1.6, boss_top, boss_top - 12, 0.6);
    // Two flats, and a set-screw hole through the right one.
    for (s = [-1, 1]) translate([s * (boss_r + 2), 0, (boss_top + t) / 2 + 4]) cube([8, 2 * boss_r, boss_top - t], center = true);
    translate([boss_r - 10, 0, 30]) rotate([0, 90, 0]) cylinder(h = 14, r = 2.5);
  }
}

// ---- the part ------------------------------------------------------------------
color(metal) difference() {
  union() {
    plate_blank();
    housing_blank();
    boss_blank();
  }
  plate_cuts();
  housing_cuts();
  boss_cuts();
}
