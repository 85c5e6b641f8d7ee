// CAD: a gearbox countershaft as it comes off the assembly bench, the kind of
// model the paper calls CAD (178 parts in Table 5-1, 185 in Table 4-4): a
// long, slender stepped shaft with circlip grooves, keyways and a key, two
// spur gears and a pinion cut on the shaft, a V-belt pulley, two ball
// bearings with shields, two set collars, a flange coupling with its bolts,
// and a locknut.
//
// Primitives (178):
//   shaft 19 (seven steps, six shoulder cones, two end chamfers, each a ring
//     outside a cone, two centre holes); circlips 20 (four grooves, each an
//     annulus cut from the shaft, and four clips, each a ring with its gap
//     cut); keyways 9 (two keyways of a box and two round ends, a key, a
//     radial cross hole and a grease hole); coupling 19 (flange, hub, two
//     edge chamfers of two, six bolt heads and six washers, a set-screw
//     hole); bearings 10 (two of 5: outer ring, its bore, inner ring, two
//     shields); collars 10 (two of 5: ring, two chamfers, set-screw hole and
//     screw); large gear 36 (disc, 24 teeth, hub, six lightening holes,
//     set-screw hole, two hub chamfers, spacer); small gear 22 (disc, 16
//     teeth, hub, set-screw hole, two hub chamfers, spacer); pinion 13 (root
//     disc and 12 teeth); pulley 12 (body, hub, two V grooves of two cones,
//     four spoke holes, a set-screw hole, a hub chamfer); locknut 8 (three
//     boxes of a hexagon, a countersink cone in its face, a tab washer, two
//     thread cones and the tab).
//   19 + 20 + 9 + 19 + 10 + 10 + 36 + 22 + 13 + 12 + 8 = 178.
//
// Why it is laid out so: the paper's CAD is its cheapest model per image
// (Table 5-1: 20 s on the M380 with 178 objects, against BALLS's 60 s with
// 125 and CHES's 128 s with 144), so most rays must meet nothing, or a voxel
// with few primitives. In Table 4-4 line mode spreads its work by 19.6 %
// where dot mode spreads it by 3.5 %, so its work lies in a band of screen
// rows. A slender shaft lying across the screen does both: its parts are
// strung out along it, few to a voxel, and most of the screen is empty.
//
// What changed, and why: the first countershaft of this size had every
// radius 1.8 times as large (the large gear 82 across) and its axis tipped
// 16.5 degrees up at its +x end, so that it ran straight across the screen.
// It cost about twice the paper's figure: 37.8 s on the M380 at 512 x 512
// (56 % of it intersection tests: 498,000 cone and 129,000 box tests for
// 110,000 rays that met the grid, 5.7 a ray; every hit's shadow ray, back
// to the light at the eye, made about 9 more) and 54.6 s on 8 x 8 CAP cells
// at 384 x 384, where BALLS costs 64.3 and 89.1 s; and its band of rows,
// about one and a half rounds of line mode's interleave (64 rows at
// 384 x 384) high, gave line mode d = 32 % (dot 4.2 %). So every radius and
// every offset from the axis is now 0.55 of what it was, the lengths along
// the axis unchanged: the view still frames the shaft's length, so the part
// is slimmer on the screen and covers about half the pixels it did; 64,000
// rays meet the grid (269,000 cone and 79,000 box tests). And the axis is
// tipped 7.5 degrees down at its +x end instead, so that the shaft falls to
// the right across the screen at about 20 degrees and its band of rows is
// about two rounds of line mode's interleave high. The locknut's hexagon
// is now the intersection of its three boxes, written out (a for loop inside
// intersection() is one operand, and made it their union, a star). With
// the recalibrated cost profiles: 24.0 s on the M380 at 512 x 512, 34.5 s
// on the CAP at 384 x 384 (about 0.37 and 0.39 of BALLS), line mode
// d = 19.0 % and dot mode d = 4.1 % at 384 x 384.
//
// cad.csg is this file exported by OpenSCAD 2021.01 (an absolute -o path,
// because OpenSCAD writes a relative one beside the input):
//   openscad -o "$PWD/scenes/cad.csg" scenes/cad.scad
// capsim renders the export with its default light, seen from the camera
// statement kept at the top of cad.csg (docs/models.md).
//
// Units: millimetres. The shaft's axis is the x axis (before the tip), from
// x = -165 to 165; the shaft's steps are 6.6 to 8.8 in radius, and the
// largest part, the large gear, is 45 across.

$fn = 48;  // only smooths OpenSCAD's own preview; capsim ignores it

steel = [0.72, 0.74, 0.78];
dark = [0.35, 0.37, 0.42];
bronze = [0.80, 0.58, 0.30];
blue = [0.30, 0.42, 0.66];

// A cylinder or cone along x from x0, h long (1 primitive).
module xcyl(x0, h, r1, r2 = -1) {
  translate([x0, 0, 0]) rotate([0, 90, 0]) cylinder(h = h, r1 = r1, r2 = r2 < 0 ? r1 : r2);
}
// A radial hole or pin along z through the point (x, 0, z0), h long, turned
// by a about x (1 primitive).
module radial(x, a, z0, h, r) {
  rotate([a, 0, 0]) translate([x, 0, z0]) cylinder(h = h, r = r);
}

// ---- the shaft: 19 + grooves 8 + keyways 8 (the key is in the assembly) -----
steps = [[-165, 6.6], [-130, 7.2], [-102, 8.3], [-44, 8.8], [26, 8.3], [96, 7.2], [131, 6.6], [165, 0]];
grooves = [-129, -109, 110, 130];  // circlip grooves, just outside the bearings' and collars' seats

module shaft_blank() {
  for (i = [0 : 6]) xcyl(steps[i][0], steps[i + 1][0] - steps[i][0], steps[i][1]);
  for (i = [1 : 6])  // shoulder cones: a short taper at every step
    let (r = min(steps[i - 1][1], steps[i][1]), R = max(steps[i - 1][1], steps[i][1]))
      if (steps[i][1] > steps[i - 1][1]) xcyl(steps[i][0] - 2, 2.01, r, R);
      else xcyl(steps[i][0] - 0.01, 2.01, R, r);
}
module shaft_cuts() {
  // end chamfers: a ring outside a cone at each end
  difference() { xcyl(-166, 3, 7.7); xcyl(-166, 3, 5.8, 7.4); }
  difference() { xcyl(163, 3, 7.7); xcyl(163, 3, 7.4, 5.8); }
  // centre holes
  xcyl(-166, 7, 1.6, 0);
  xcyl(159, 7, 0, 1.6);
  // circlip grooves: an annulus each
  for (g = grooves) difference() { xcyl(g - 0.8, 1.6, 9.4); xcyl(g - 1, 2, steps[g < 0 ? 1 : 5][1] - 0.7); }
  // keyway in the body between the small gear and the pinion, on top, and one at the output end
  translate([6, -1.4, 7.2]) cube([16, 2.8, 2.2]);
  for (x = [6, 22]) translate([x, 0, 7.2]) cylinder(h = 2.2, r = 1.4);
  translate([145, -1.1, 5.2]) cube([16, 2.2, 1.7]);
  for (x = [145, 161]) translate([x, 0, 5.2]) cylinder(h = 1.7, r = 1.1);
  // a cross hole between the pinion and the pulley, a grease hole in the body
  radial(49.5, 90, -9.4, 18.8, 1.4);
  radial(-40.5, 60, 5.5, 3.9, 0.8);
}

// ---- circlips: 12 -----------------------------------------------------------
module circlip(g) {
  r = steps[g < 0 ? 1 : 5][1];
  difference() {
    xcyl(g - 0.6, 1.2, r + 1.65);
    xcyl(g - 1, 2, r - 0.55);
    rotate([-35, 0, 0]) translate([g - 1, -1.1, r - 1.1]) cube([2, 2.2, 3.3]);
  }
}

// ---- flange coupling at the input end: 19 -----------------------------------
module coupling() {
  difference() {
    union() {
      xcyl(-165, 12, 18.7);  // flange
      xcyl(-153.01, 22, 11);  // hub
    }
    difference() { xcyl(-166, 3, 19.3); xcyl(-166, 3, 17.1, 18.7); }  // flange edge chamfers
    difference() { xcyl(-156, 3.01, 19.3); xcyl(-156, 3.01, 18.7, 17.1); }
    radial(-140, 20, 7.7, 4.4, 1.4);  // set-screw hole in the hub
  }
  for (k = [0 : 5]) rotate([30 + 60 * k, 0, 0]) {
    color(dark) translate([-153.2, 0, 13.8]) rotate([0, 90, 0]) cylinder(h = 5, r = 2.4, $fn = 6);  // bolt head
    translate([-153.5, 0, 13.8]) rotate([0, 90, 0]) cylinder(h = 1.2, r = 3);  // washer
  }
}

// ---- bearings: 10 (two of 5) ------------------------------------------------
module bearing(x0) {
  color(dark) difference() {
    xcyl(x0, 16, 14.3);
    xcyl(x0 - 1, 18, 12.1);
  }
  color(steel) xcyl(x0 + 0.01, 15.98, 9.4);  // inner ring
  color(blue) {  // shields, set back 0.8 from the faces
    xcyl(x0 + 0.8, 0.6, 12.2);
    xcyl(x0 + 14.6, 0.6, 12.2);
  }
}

// ---- set collars: 10 --------------------------------------------------------
module collar(x0) {
  difference() {
    xcyl(x0, 10, 11.6);
    xcyl(x0 - 0.01, 1.5, 10.7, 11.61);
    xcyl(x0 + 8.51, 1.5, 11.61, 10.7);
    radial(x0 + 5, 0, 8.3, 3.9, 1.2);
  }
  color(dark) radial(x0 + 5, 0, 7.2, 3.3, 1);  // set screw, below the face
}

// ---- gears: large 36, small 22, pinion 13 -----------------------------------
// A toothed disc of n teeth, face width w, root radius rr, tooth height th,
// centred at x0 (1 + n primitives).
module toothed(x0, w, n, rr, th) {
  xcyl(x0 - w / 2, w, rr);
  for (k = [0 : n - 1])
    rotate([360 * k / n, 0, 0])
      translate([x0 - w / 2, -PI * rr / n / 2, rr - 0.3]) cube([w, PI * rr / n, th + 0.3]);
}
module large_gear(x0) {
  color(bronze) difference() {
    union() {
      toothed(x0, 16, 24, 19.8, 2.8);
      xcyl(x0 - 15, 30, 12.1);  // hub
    }
    for (k = [0 : 5]) rotate([60 * k, 0, 0]) translate([x0 - 9, 0, 16]) rotate([0, 90, 0]) cylinder(h = 18, r = 1.9);
    radial(x0 - 11, 0, 9.9, 3.3, 1.1);  // set-screw hole in the hub
    xcyl(x0 - 15.01, 2, 11, 12.11);  // hub chamfers
    xcyl(x0 + 13.01, 2, 12.11, 11);
  }
  color(steel) xcyl(x0 + 15, 12, 10.45);  // spacer to the next step
}
module small_gear(x0) {
  color(bronze) difference() {
    union() {
      toothed(x0, 14, 16, 12.65, 2.5);
      xcyl(x0 - 13, 26, 11.55);  // hub
    }
    radial(x0 + 10, 0, 9.35, 3.3, 1.1);
    xcyl(x0 - 13.01, 2, 10.45, 11.56);
    xcyl(x0 + 11.01, 2, 11.56, 10.45);
  }
  color(steel) xcyl(x0 - 25, 12, 10.45);  // spacer
}
module pinion(x0) {
  toothed(x0, 18, 12, 9.1, 2.2);
}

// ---- V-belt pulley: 12 ------------------------------------------------------
module pulley(x0) {
  color(blue) difference() {
    union() {
      xcyl(x0, 24, 17.6);  // body
      xcyl(x0 - 8, 40, 11);  // hub
    }
    for (g = [x0 + 6, x0 + 18]) {  // two V grooves, each two cones meeting at the groove's root
      xcyl(g - 4.5, 4.51, 18.15, 13.75);
      xcyl(g - 0.01, 4.51, 13.75, 18.15);
    }
    for (k = [0 : 3]) rotate([45 + 90 * k, 0, 0]) translate([x0 - 1, 0, 13.2]) rotate([0, 90, 0]) cylinder(h = 26, r = 1.65);
    radial(x0 + 27, 0, 8.25, 3.85, 1.1);  // set-screw hole in the hub
    xcyl(x0 + 30.01, 2, 11.01, 9.9);  // hub chamfer
  }
}

// ---- locknut at the output end: 8 -------------------------------------------
module locknut(x0) {
  color(dark) difference() {
    intersection() {  // the operands written out: a for loop here would be one operand, their union
      translate([x0, -11, -5.72]) cube([8, 22, 11.44]);
      rotate([60, 0, 0]) translate([x0, -11, -5.72]) cube([8, 22, 11.44]);
      rotate([120, 0, 0]) translate([x0, -11, -5.72]) cube([8, 22, 11.44]);
    }
    xcyl(x0 + 6.01, 2, 4.4, 5.5);  // countersink in the nut's face
  }
  xcyl(x0 - 2, 2, 8.8);  // tab washer
  color(steel) {  // the shaft's thread ends
    xcyl(x0 + 8, 1, 6.6, 6.05);
    xcyl(x0 - 3, 1, 6.05, 6.6);
  }
  translate([x0 - 2, -0.8, 7.15]) cube([2, 1.6, 2.2]);  // the tab bent into the keyway of the nut
}

// ---- the assembly -----------------------------------------------------------
rotate([0, 7.5, 0]) {
  color(steel) difference() { shaft_blank(); shaft_cuts(); }
  color(steel) for (g = grooves) circlip(g);
  color(steel) translate([147, -1.1, 5]) cube([12, 2.2, 2.8]);  // key in the output keyway
  color(steel) coupling();
  bearing(-127);
  bearing(112);
  color(steel) collar(-107);
  color(steel) collar(97);
  large_gear(-72);
  small_gear(-12);
  color(steel) pinion(36);
  pulley(62);
  locknut(133);
}
