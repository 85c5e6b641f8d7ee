// CAD: a gearbox countershaft as it comes off the assembly bench, the kind of
// model the paper calls CAD (178 parts in Table 5-1, 185 in Table 4-4): a
// stepped shaft with circlip grooves, keyways and a key, two spur gears and a
// pinion cut on the shaft, a V-belt pulley, two ball bearings with shields,
// two set collars, a flange coupling with its bolts, and a locknut.
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
//     boxes of a hexagon, its chamfer cone, a tab washer, two thread cones and
//     the tab). 19 + 20 + 9 + 19 + 10 + 10 + 36 + 22 + 13 + 12 + 8 = 178.
//
// Why it is laid out so: the paper's CAD is its cheapest model per image
// (Table 5-1: 20 s on the M380 with 178 objects, against CHES's 128 s with
// 144), so most rays must meet nothing, or a voxel with few primitives; and
// in Table 4-4 line mode spreads its work by 19.6 % where dot mode spreads
// it by 3.5 %, so its work lies in a band of screen rows. A slender shaft
// lying across the screen does both: its parts are strung out along it, few
// to a voxel, most of the screen is empty, and it covers a band of rows
// about one and a half rounds of line mode's interleave (64 rows) high. The
// shaft's axis is tipped 16.5 degrees up at its +x end, so that it lies in
// the plane of the screen's horizontal and the view direction of OpenSCAD's
// default view (the viewport rotation [55, 0, 25]): it runs straight across
// the screen, and the grid's bounds stay as thin as the parts are across.
//
// cad.csg is this file exported by OpenSCAD 2021.01 (an absolute -o path,
// because OpenSCAD writes a relative one beside the input):
//   openscad -o "$PWD/scenes/cad.csg" scenes/cad.scad
// capsim renders the export as is, with its default view and light.
//
// Units: millimetres. The shaft's axis is the x axis (before the tip), from
// x = -165 to 165; the largest part, the large gear, is 82 across.

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

// ---- the shaft: 17 + grooves 8 + keyways 9 ---------------------------------
steps = [[-165, 12], [-130, 13], [-102, 15], [-44, 16], [26, 15], [96, 13], [131, 12], [165, 0]];
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
  difference() { xcyl(-166, 3, 14); xcyl(-166, 3, 10.5, 13.5); }
  difference() { xcyl(163, 3, 14); xcyl(163, 3, 13.5, 10.5); }
  // centre holes
  xcyl(-166, 7, 3, 0);
  xcyl(159, 7, 0, 3);
  // circlip grooves: an annulus each
  for (g = grooves) difference() { xcyl(g - 0.8, 1.6, 17); xcyl(g - 1, 2, steps[g < 0 ? 1 : 5][1] - 1.2); }
  // keyway in the body between the small gear and the pinion, on top, and one at the output end
  translate([6, -2.5, 13]) cube([16, 5, 4]);
  for (x = [6, 22]) translate([x, 0, 13]) cylinder(h = 4, r = 2.5);
  translate([145, -2, 9.5]) cube([16, 4, 3]);
  for (x = [145, 161]) translate([x, 0, 9.5]) cylinder(h = 3, r = 2);
  // a cross hole between the pinion and the pulley, a grease hole in the body
  radial(49.5, 90, -17, 34, 2.5);
  radial(-40.5, 60, 10, 7, 1.5);
}

// ---- circlips: 12 ----------------------------------------------------------
module circlip(g) {
  r = steps[g < 0 ? 1 : 5][1];
  difference() {
    xcyl(g - 0.6, 1.2, r + 3);
    xcyl(g - 1, 2, r - 1);
    rotate([-35, 0, 0]) translate([g - 1, -2, r - 2]) cube([2, 4, 6]);
  }
}

// ---- flange coupling at the input end: 17 ---------------------------------
module coupling() {
  difference() {
    union() {
      xcyl(-165, 12, 34);  // flange
      xcyl(-153.01, 22, 20);  // hub
    }
    difference() { xcyl(-166, 3, 35); xcyl(-166, 3, 31, 34); }  // flange edge chamfers
    difference() { xcyl(-156, 3.01, 35); xcyl(-156, 3.01, 34, 31); }
    radial(-140, 20, 14, 8, 2.5);  // set-screw hole in the hub
  }
  for (k = [0 : 5]) rotate([30 + 60 * k, 0, 0]) {
    color(dark) translate([-153.2, 0, 25]) rotate([0, 90, 0]) cylinder(h = 5, r = 4.3, $fn = 6);  // bolt head
    translate([-153.5, 0, 25]) rotate([0, 90, 0]) cylinder(h = 1.2, r = 5.5);  // washer
  }
}

// ---- bearings: 14 ------------------------------------------------------------
module bearing(x0) {
  color(dark) difference() {
    xcyl(x0, 16, 26);
    xcyl(x0 - 1, 18, 22);
  }
  color(steel) xcyl(x0 + 0.01, 15.98, 17);  // inner ring
  color(blue) {  // shields, set back 0.8 from the faces
    xcyl(x0 + 0.8, 0.6, 22.2);
    xcyl(x0 + 14.6, 0.6, 22.2);
  }
}

// ---- set collars: 10 -----------------------------------------------------------
module collar(x0) {
  difference() {
    xcyl(x0, 10, 21);
    xcyl(x0 - 0.01, 1.5, 19.5, 21.01);
    xcyl(x0 + 8.51, 1.5, 21.01, 19.5);
    radial(x0 + 5, 0, 15, 7, 2.2);
  }
  color(dark) radial(x0 + 5, 0, 13, 6, 1.8);  // set screw, below the face
}

// ---- gears: large 36, small 22, pinion 13 --------------------------------------
// A toothed disc of n teeth, face width w, root radius rr, tooth height th,
// centred at x0 (1 + n primitives).
module toothed(x0, w, n, rr, th) {
  xcyl(x0 - w / 2, w, rr);
  for (k = [0 : n - 1])
    rotate([360 * k / n, 0, 0])
      translate([x0 - w / 2, -PI * rr / n / 2, rr - 0.5]) cube([w, PI * rr / n, th + 0.5]);
}
module large_gear(x0) {
  color(bronze) difference() {
    union() {
      toothed(x0, 16, 24, 36, 5);
      xcyl(x0 - 15, 30, 22);  // hub
    }
    for (k = [0 : 5]) rotate([60 * k, 0, 0]) translate([x0 - 9, 0, 29]) rotate([0, 90, 0]) cylinder(h = 18, r = 3.5);
    radial(x0 - 11, 0, 18, 6, 2);  // set-screw hole in the hub
    xcyl(x0 - 15.01, 2, 20, 22.01);  // hub chamfers
    xcyl(x0 + 13.01, 2, 22.01, 20);
  }
  color(steel) xcyl(x0 + 15, 12, 19);  // spacer to the next step
}
module small_gear(x0) {
  color(bronze) difference() {
    union() {
      toothed(x0, 14, 16, 23, 4.5);
      xcyl(x0 - 13, 26, 21);  // hub
    }
    radial(x0 + 10, 0, 17, 6, 2);
    xcyl(x0 - 13.01, 2, 19, 21.01);
    xcyl(x0 + 11.01, 2, 21.01, 19);
  }
  color(steel) xcyl(x0 - 25, 12, 19);  // spacer
}
module pinion(x0) {
  toothed(x0, 18, 12, 16.5, 4);
}

// ---- V-belt pulley: 12 ---------------------------------------------------------
module pulley(x0) {
  color(blue) difference() {
    union() {
      xcyl(x0, 24, 32);  // body
      xcyl(x0 - 8, 40, 20);  // hub
    }
    for (g = [x0 + 6, x0 + 18]) {  // two V grooves, each two cones meeting at the groove's root
      xcyl(g - 4.5, 4.51, 33, 25);
      xcyl(g - 0.01, 4.51, 25, 33);
    }
    for (k = [0 : 3]) rotate([45 + 90 * k, 0, 0]) translate([x0 - 1, 0, 24]) rotate([0, 90, 0]) cylinder(h = 26, r = 3);
    radial(x0 + 27, 0, 15, 7, 2);  // set-screw hole in the hub
    xcyl(x0 + 30.01, 2, 20.01, 18);  // hub chamfer
  }
}

// ---- locknut at the output end: 8 ----------------------------------------------
module locknut(x0) {
  color(dark) difference() {
    intersection() {
      for (a = [0, 60, 120]) rotate([a, 0, 0]) translate([x0, -20, -10.4]) cube([8, 40, 20.8]);
    }
    xcyl(x0 + 6.01, 2, 11, 13);  // chamfer at the nut's face
  }
  xcyl(x0 - 2, 2, 16);  // tab washer
  color(steel) {  // the shaft's thread ends
    xcyl(x0 + 8, 1, 12, 11);
    xcyl(x0 - 3, 1, 11, 12);
  }
  translate([x0 - 2, -1.5, 13]) cube([2, 3, 4]);  // the tab bent into the keyway of the nut
}

// ---- the assembly ------------------------------------------------------------------
rotate([0, -16.5, 0]) {
  color(steel) difference() { shaft_blank(); shaft_cuts(); }
  color(steel) for (g = grooves) circlip(g);
  color(steel) translate([147, -2, 9]) cube([12, 4, 5]);  // key in the output keyway
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
