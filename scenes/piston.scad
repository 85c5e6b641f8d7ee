// PISTON: an engine piston kit drawn exploded: the piston with its rings and
// wrist pin, the connecting rod with its cap, bearing shells and bolts, and
// the air-cooled cylinder barrel it runs in, each part lifted off the next
// along the piston's axis or laid out beside it, as in an exploded assembly
// drawing. It is the kind of model the paper calls PISTON (179 parts).
//
// Primitives: piston 45 (blank 2, cavity and pin bosses 5, ring grooves and
// heat dam 8, cooling gallery and its feed holes 4, oil holes 12 + 2, pin bore
// and circlip grooves 3, skirt reliefs 4, bowl and valve reliefs 5); rings 14
// (two compression rings and the oil ring's two rails, 3 each: an annulus and
// its end gap; the oil ring's expander, an annulus, 2); barrel 34 (core and 18
// fins, bore, 2 stud holes; 2 studs with hexagonal nuts, 10; the base gasket,
// 2); wrist pin 10 (the hollow pin with tapered bore ends 4, two circlips of
// 3); connecting rod 76 (small end and bushing 11, beam 9, the rod's half of
// the big end 7 and its bearing shell 5, the cap 8 and its shell 4, two bolts
// of 16: shank, three thread cones, two washers, and head and nut each a
// hexagon of 4); 179 in all, under 33 differences and 14 intersections.
//
// Why exploded: Table 4-3 of the paper (PISTON on the M380, one processor,
// full ray tracing) spends 108.5 / 11.4 / 7.8 s on intersection at 2 / 16 / 32
// grid divisions per axis. At Table 4-1's M380 test costs (sphere 18.2 us,
// cone 31.8 us, box 42.2 us) and a 512 x 512 screen that is about 3.7 M /
// 0.39 M / 0.27 M intersection tests. A piston assembled inside its barrel,
// every part nested in the next, makes three to four times as many: a ray
// meets the overlapping bounds of nearly half the primitives. Laid out apart,
// the parts share few voxels: a tall column (barrel, rings, piston; rod and
// cap below), with the wrist pin and the two bolts beside it, and gaps where
// the grid's middle planes across the view fall at 2 divisions (between the
// piston and the rod, and between the column and the small parts); only the
// one in depth cuts parts. docs/models.md gives the counts.
//
// piston.csg is this file exported by OpenSCAD 2021.01 (an absolute -o path,
// because OpenSCAD writes a relative one beside the input):
//   openscad -o "$PWD/scenes/piston.csg" scenes/piston.scad
// capsim renders the export with its default light, seen from the camera
// statement kept at the top of piston.csg (docs/models.md).
//
// Units: millimetres. The column's axis is z at x = y = 0: the piston's skirt
// at z = 30, the rod's small end at z = -47; the wrist pin lies along y, as in
// its bore; the rod and the cap stand in the x-z plane, the bolts upright.

$fn = 64;  // only smooths OpenSCAD's own preview; capsim ignores it

aluminium = [0.78, 0.79, 0.80];
steel = [0.55, 0.57, 0.62];
ring_steel = [0.36, 0.37, 0.40];
bronze = [0.80, 0.55, 0.25];
forged = [0.50, 0.52, 0.56];
cast_iron = [0.42, 0.41, 0.40];
gasket = [0.78, 0.33, 0.27];

bore_r = 40;        // piston radius
pin_z = 28;         // wrist pin axis above the piston's skirt
pin_r = 10;         // wrist pin radius
rod_length = 140;   // small end to big end, centre to centre
oil_holes = 12;     // drilled through the oil ring groove, each giving two holes

// The layout of the exploded kit.
piston_z = 30;              // the piston's skirt
rings_z = [100, 110, 122, 136, 152];  // above the skirt: lower rail, expander,
                                      // upper rail, second ring, top ring
gasket_z = 249;             // the barrel's base gasket
barrel_z = 280.5;           // the barrel's fins start 11 mm above this
small_end_z = -47;          // the rod's small end (the pin's axis)
cap_drop = 145;             // the cap below the rod's big end
side_x = -179;              // the wrist pin and the bolts, beside the column

// Along y, centred on the origin.
module along_y(h, r) { rotate([90, 0, 0]) cylinder(h = h, r = r, center = true); }

// An annulus from z0 to z0 + h between radii r_in and r_out (2 primitives).
module annulus(z0, h, r_in, r_out) {
  difference() {
    translate([0, 0, z0]) cylinder(h = h, r = r_out);
    translate([0, 0, z0 - 1]) cylinder(h = h + 2, r = r_in);
  }
}

// ---- the piston -----------------------------------------------------------
// Ring grooves: two compression grooves and an oil groove.
groove_z = [[61, 2.2], [54, 2.4], [45, 4.0]];  // bottom and height of each

module piston_blank() {
  // The outer surface, its crown edge chamfered at 45 degrees by a cone.
  cylinder(h = 68.5, r = bore_r);
  translate([0, 0, 68.5]) cylinder(h = 1.5, r1 = bore_r, r2 = bore_r - 1.5);
}

module cavity() {
  // The hollow under the crown, less the pin bosses and two ribs that stay.
  difference() {
    translate([0, 0, -1]) cylinder(h = 56, r = 34);
    for (s = [-1, 1]) translate([0, s * 24, pin_z]) along_y(20, 15);  // pin bosses
    for (s = [-1, 1]) translate([0, s * 17, 48]) cube([60, 4, 16], center = true);  // ribs
  }
}

module piston() {
  difference() {
    piston_blank();
    cavity();
    for (g = groove_z) annulus(g[0], g[1], 36.5, bore_r + 1);            // ring grooves
    annulus(66.5, 0.8, 39.2, bore_r + 1);                                 // heat dam in the top land
    annulus(57, 5, 27, 33);                                               // cooling gallery in the crown
    for (s = [-1, 1]) translate([s * 30, 0, 50]) cylinder(h = 8, r = 1.8);  // its inlet and outlet
    for (k = [0 : oil_holes - 1])                                         // oil drain holes
      rotate(k * 180 / oil_holes + 90 / oil_holes) translate([0, 0, 47]) rotate([0, 90, 0])
        cylinder(h = 2 * bore_r + 4, r = 1.1, center = true);
    translate([0, 0, pin_z]) along_y(2 * bore_r + 4, pin_r);             // pin bore
    for (s = [-1, 1]) translate([0, s * 35.5, pin_z]) along_y(1.4, 11.2);  // circlip grooves
    for (s = [-1, 1]) translate([0, s * 24, pin_z]) cylinder(h = 22, r = 1.2);  // oil feeds to the pin
    for (s = [-1, 1])                                                     // skirt reliefs at the pin bosses
      intersection() {
        translate([0, s * 40, 14]) cube([44, 8, 44], center = true);
        translate([0, s * 40, -1]) cylinder(h = 38, r = 26);
      }
    translate([0, 0, 96]) sphere(r = 29);                                 // combustion bowl
    for (a = [45, 135, 225, 315])                                         // valve reliefs
      rotate(a) translate([22, 0, 69]) rotate([0, -8, 0]) cylinder(h = 5, r = 10);
  }
}

// A ring of height h from z = 0 between radii r_in and r_out, its end gap
// towards -x (3 primitives).
module ring(h, r_in, r_out) {
  difference() {
    annulus(0, h, r_in, r_out);
    translate([-r_out + 3, 0, h / 2]) cube([8, 1.2, h + 2], center = true);
  }
}

// Two compression rings and a three-piece oil ring, lifted off the piston in
// the order they come off: the top ring highest.
module rings() {
  color(ring_steel) {
    translate([0, 0, rings_z[0]]) ring(0.6, 37.5, 39.9);           // oil ring: lower rail
    translate([0, 0, rings_z[1]]) annulus(0, 2.4, 36.8, 39.2);     //           expander
    translate([0, 0, rings_z[2]]) ring(0.6, 37.5, 39.9);           //           upper rail
    translate([0, 0, rings_z[3]]) ring(2.2, 37.0, 39.9);           // second ring
    translate([0, 0, rings_z[4]]) ring(2.0, 37.0, 39.9);           // top ring
  }
}

// ---- the cylinder barrel ---------------------------------------------------
// An air-cooled barrel with its cooling fins; two studs with nuts on the far
// side hold it down.
fins = 18;
fin_pitch = 84 / (fins - 1);
stud_at = [[36.8, 36.8], [-36.8, 36.8]];  // radius 52, at 45 and 135 degrees

// A hexagon of across-flats s and height h, centred, axis z, with its top
// edge chamfered: an intersection of three boxes and a cone (4 primitives).
module hex(s, h) {
  intersection() {
    // Written out: a for loop here would be their union (OpenSCAD's for
    // yields a group), not their intersection.
    cube([s, 2 * s, h], center = true);
    rotate(60) cube([s, 2 * s, h], center = true);
    rotate(120) cube([s, 2 * s, h], center = true);
    translate([0, 0, -h / 2]) cylinder(h = h + 0.5, r1 = 0.5 * s + h, r2 = 0.5 * s - 0.5);
  }
}

module barrel() {
  color(cast_iron) difference() {
    union() {
      translate([0, 0, -12]) cylinder(h = 90, r = 46);
      for (k = [0 : fins - 1]) translate([0, 0, -11 + k * fin_pitch]) cylinder(h = 2.2, r = 58);
    }
    translate([0, 0, -13]) cylinder(h = 92, r = bore_r + 0.1);            // bore
    for (p = stud_at) translate([p[0], p[1], -13]) cylinder(h = 92, r = 4.3);  // stud holes
  }
  color(steel) for (p = stud_at) translate([p[0], p[1], 0]) {
    translate([0, 0, -12]) cylinder(h = 98, r = 4);
    translate([0, 0, 81]) hex(11, 6);
  }
}

// ---- the wrist pin and its circlips -------------------------------------------
module wrist_pin() {
  color(steel) difference() {
    along_y(70, pin_r - 0.05);
    along_y(72, 5.5);
    for (s = [-1, 1]) translate([0, s * 33.5, 0]) rotate([s * 90 - 90, 0, 0])  // tapered ends of the bore
      rotate([-90, 0, 0]) cylinder(h = 2.1, r1 = 5.5, r2 = 7.5);
  }
}

module circlip() {
  color(steel) difference() {
    along_y(1.2, 11.0);
    along_y(2, 8.6);
    translate([0, 0, -10]) cube([3, 3, 6], center = true);  // the circlip's gap
  }
}

// ---- the connecting rod ---------------------------------------------------------
// Built hanging along -z from the small end's centre.
module small_end() {
  difference() {
    intersection() {
      union() {
        along_y(24, 15);
        translate([0, 0, -14]) cube([22, 24, 14], center = true);   // neck into the beam
        translate([0, 0, 15]) cube([10, 16, 4], center = true);     // balance pad
      }
      rotate([10, 0, 0]) translate([0, -12, 0]) cube([40, 24, 44], center = true);   // the end tapers
      rotate([-10, 0, 0]) translate([0, 12, 0]) cube([40, 24, 44], center = true);   // towards the top
    }
    along_y(26, 11.6);                                             // bushing bore
    translate([0, 0, 10]) cylinder(h = 12, r = 2);                // oil hole
  }
  color(bronze) difference() {                                   // bronze bushing
    along_y(24.2, 11.6);
    along_y(26, pin_r);
    difference() { along_y(4, 10.6); along_y(5, 9.9); }           // its oil groove
  }
}

module beam() {
  // An I-section: a tapered bar with a pocket on each face, the pockets'
  // ends rounded by cylinders, and the oil passage drilled along it.
  difference() {
    intersection() {
      translate([0, 0, -rod_length / 2]) cube([34, 20, rod_length - 20], center = true);
      translate([0, 0, -rod_length + 8]) cylinder(h = rod_length - 16, r1 = 22, r2 = 12);
    }
    for (s = [-1, 1]) translate([0, s * 10, 0]) {
      pocket = rod_length - 66;
      translate([0, 0, -rod_length / 2]) cube([12, 12, pocket], center = true);
      translate([0, 0, -rod_length / 2 + pocket / 2]) along_y(12, 6);
      translate([0, 0, -rod_length / 2 - pocket / 2]) along_y(12, 6);
    }
    translate([0, 0, -rod_length + 20]) cylinder(h = rod_length - 30, r = 1.5);  // oil passage
  }
}

// One half of the big end, centred on the crankpin's axis: half = 1 the rod's
// (7 primitives), half = -1 the cap with its balance pad (8). Each is the
// bored ring with its bolt bosses, cut at the split line by a half-space box.
module big_end_half(half) {
  intersection() {
    difference() {
      union() {
        along_y(24, 33);
        for (s = [-1, 1]) translate([s * 35, 0, 0]) cube([16, 24, 30], center = true);  // bolt bosses
        if (half < 0) translate([0, 0, -33]) cube([16, 12, 6], center = true);  // balance pad
      }
      along_y(26, 26);                                            // crankpin bore
      for (s = [-1, 1]) translate([s * 36, 0, 0]) cylinder(h = 40, r = 4.6, center = true);  // bolt holes
    }
    translate([0, 0, half * 20.2]) cube([90, 30, 40], center = true);
  }
}

// A bearing shell with its tang, seated in its half of the big end: half = 1
// the rod's, with an oil hole (5 primitives), half = -1 the cap's (4).
module shell(half) {
  color(bronze) intersection() {
    difference() {
      union() {
        along_y(22, 26);
        translate([half * 25, 0, half * 2]) cube([3, 4, 4], center = true);  // tang
      }
      along_y(24, 24);
      if (half > 0) translate([0, 0, 20]) cylinder(h = 8, r = 2);  // oil hole
    }
    translate([0, 0, half * 15.1]) cube([60, 30, 30], center = true);
  }
}

// A big-end bolt, its head up, with its nut and washers on as it comes out
// of the box, z = 0 at the split line (16 primitives): shank, head and nut,
// two washers and three turns of thread below the nut.
module bolt() {
  color(steel) {
    translate([0, 0, -23]) cylinder(h = 41, r = 4.5);
    translate([0, 0, 19]) hex(13, 6);
    translate([0, 0, -19.5]) rotate([180, 0, 0]) hex(13, 7);
    annulus(15, 1, 4.6, 7.5);                                     // washers
    annulus(-16, 1, 4.6, 7.5);
    for (k = [0 : 2]) translate([0, 0, -26 + 1.2 * k]) cylinder(h = 1.2, r1 = 3.8, r2 = 4.5);  // thread
  }
}

// ---- the exploded kit ------------------------------------------------------------
// The column, top to bottom: the barrel lifted off with its base gasket, the
// rings, the piston; then the rod hanging straight with its shell in the big
// end, and the cap with its shell, dropped off the rod.
translate([0, 0, barrel_z]) barrel();
translate([0, 0, gasket_z]) color(gasket) annulus(0, 1.5, 40.5, 50);
translate([0, 0, piston_z]) {
  color(aluminium) piston();
  rings();
}
translate([0, 0, small_end_z]) {
  color(forged) {
    small_end();
    beam();
    translate([0, 0, -rod_length]) big_end_half(1);
  }
  translate([0, 0, -rod_length]) shell(1);
  translate([0, 0, -rod_length - cap_drop]) {
    color(forged) big_end_half(-1);
    shell(-1);
  }
}
// Beside the column: the wrist pin at the height of its bore, its circlips
// drawn off its ends, and the two bolts at the height of the cap.
translate([side_x, 0, piston_z + pin_z]) {
  wrist_pin();
  for (s = [-1, 1]) translate([0, s * 48, 0]) circlip();
}
for (s = [-1, 1]) translate([side_x, s * 20, small_end_z - rod_length - cap_drop]) bolt();
