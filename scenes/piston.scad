// PISTON: an engine piston with its rings, wrist pin and connecting rod, in
// an air-cooled cylinder barrel: the kind of model the paper calls PISTON
// (179 parts). A quarter of the piston and its rings and the half of the
// barrel towards the viewer are cut away, to show the ring grooves, the crown's
// cooling gallery and the pin bosses in section and the rod's small end inside.
//
// Primitives: piston 45 (blank 2, cavity and bosses 5, grooves 8, gallery 4,
// oil holes 12 + 2, pin bore and circlip grooves 3, skirt reliefs 4, bowl and
// valve reliefs 5), rings 14, the quarter cut 1, barrel 33 (core and 18 fins,
// bore, 2 stud holes, the half cut, 2 studs with nuts), wrist pin 10, rod 76
// (small end and bushing 11, beam 9, big end 56 with its shells and two bolts
// of 16); 179 in all, under 33 differences and 14 intersections.
//
// piston.csg is this file exported by OpenSCAD 2021.01 (an absolute -o path,
// because OpenSCAD writes a relative one beside the input):
//   openscad -o "$PWD/scenes/piston.csg" scenes/piston.scad
// capsim renders the export as is, with its default view and light.
//
// Units: millimetres. The piston's axis is z (skirt at z = 0, crown at
// z = 70), the wrist pin runs along y at z = 28, and the rod swings in the
// x-z plane, 12 degrees off the axis.

$fn = 64;  // only smooths OpenSCAD's own preview; capsim ignores it

aluminium = [0.78, 0.79, 0.80];
steel = [0.55, 0.57, 0.62];
ring_steel = [0.36, 0.37, 0.40];
bronze = [0.80, 0.55, 0.25];
forged = [0.50, 0.52, 0.56];
section = [0.78, 0.33, 0.27];  // the faces the cutaways leave
cast_iron = [0.42, 0.41, 0.40];

bore_r = 40;        // piston radius
pin_z = 28;         // wrist pin axis height
pin_r = 10;         // wrist pin radius
rod_length = 140;   // small end to big end, centre to centre
rod_angle = 12;     // degrees off the piston axis
oil_holes = 12;     // drilled through the oil ring groove, each giving two holes

// Along y, centred on the pin axis.
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

// Rings: two compression rings and a three-piece oil ring, each with its end
// gap on the far side.
module ring(z0, h, r_in, r_out) {
  difference() {
    annulus(z0, h, r_in, r_out);
    translate([-bore_r, 0, z0 + h / 2]) cube([12, 0.8, h + 2], center = true);
  }
}
module rings() {
  color(ring_steel) {
    ring(61.1, 2.0, 37.0, 39.9);
    ring(54.1, 2.2, 37.0, 39.9);
    ring(45.1, 0.6, 37.5, 39.9);                 // oil ring: upper rail
    ring(48.3, 0.6, 37.5, 39.9);                 //           lower rail
    annulus(45.8, 2.4, 36.8, 39.2);              //           expander
  }
}

// The piston and its rings, with the quarter towards the viewer cut away.
module piston_cut() {
  difference() {
    union() {
      color(aluminium) piston();
      rings();
    }
    color(section) translate([0, -bore_r - 2, -2]) cube([bore_r + 2, bore_r + 2, 80]);
  }
}

// ---- the cylinder barrel ---------------------------------------------------
// An air-cooled barrel with its cooling fins, its half towards the viewer cut
// away; two studs with nuts on the far side hold it down.
fins = 18;
fin_pitch = 84 / (fins - 1);
stud_at = [[36.8, 36.8], [-36.8, 36.8]];  // radius 52, at 45 and 135 degrees

module barrel() {
  color(cast_iron) difference() {
    union() {
      translate([0, 0, -12]) cylinder(h = 90, r = 46);
      for (k = [0 : fins - 1]) translate([0, 0, -11 + k * fin_pitch]) cylinder(h = 2.2, r = 58);
    }
    translate([0, 0, -13]) cylinder(h = 92, r = bore_r + 0.1);            // bore
    for (p = stud_at) translate([p[0], p[1], -13]) cylinder(h = 92, r = 4.3);  // stud holes
    color(section) translate([-60, -60, -14]) cube([120, 60, 94]);        // the half towards the viewer
  }
  color(steel) for (p = stud_at) translate([p[0], p[1], 0]) {
    translate([0, 0, -12]) cylinder(h = 98, r = 4);
    translate([0, 0, 81]) hex(11, 6);
  }
}

// ---- the wrist pin and its circlips -------------------------------------------
module wrist_pin() {
  color(steel) translate([0, 0, pin_z]) {
    difference() {
      along_y(70, pin_r - 0.05);
      along_y(72, 5.5);
      for (s = [-1, 1]) translate([0, s * 33.5, 0]) rotate([s * 90 - 90, 0, 0])  // tapered ends of the bore
        rotate([-90, 0, 0]) cylinder(h = 2.1, r1 = 5.5, r2 = 7.5);
    }
    for (s = [-1, 1])
      translate([0, s * 35.5, 0]) difference() {
        along_y(1.2, 11.0);
        along_y(2, 8.6);
        translate([0, 0, -10]) cube([3, 3, 6], center = true);  // the circlip's gap
      }
  }
}

// ---- the connecting rod ---------------------------------------------------------
// Built hanging along -z from the pin axis, then swung by rod_angle.
module small_end() {
  difference() {
    intersection() {
      union() {
        along_y(24, 15);
        translate([0, 0, -14]) cube([22, 24, 14], center = true);   // neck into the beam
        translate([0, 0, 15]) cube([10, 16, 4], center = true);     // balance pad
      }
      rotate([10, 0, 0]) translate([0, -12, 0]) cube([40, 24, 60], center = true);   // the end tapers
      rotate([-10, 0, 0]) translate([0, 12, 0]) cube([40, 24, 60], center = true);   // towards the top
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

// A bolt through the big end: shank, head and nut on washers, and three turns
// of thread showing below the nut (16 primitives).
module bolt() {
  translate([0, 0, -23]) cylinder(h = 41, r = 4.5);
  translate([0, 0, 19]) hex(13, 6);
  translate([0, 0, -19.5]) rotate([180, 0, 0]) hex(13, 7);
  annulus(15, 1, 4.6, 7.5);                                       // washers
  annulus(-16, 1, 4.6, 7.5);
  for (k = [0 : 2]) translate([0, 0, -26 + 1.2 * k]) cylinder(h = 1.2, r1 = 3.8, r2 = 4.5);  // thread
}

module big_end() {
  // The rod half and the cap, each a ring with bolt bosses, cut apart at the
  // split line; the cap has a balance pad.
  for (half = [1, -1])
    intersection() {
      difference() {
        union() {
          along_y(24, 33);
          for (s = [-1, 1]) translate([s * 35, 0, 0]) cube([16, 24, 30], center = true);  // bolt bosses
          if (half < 0) translate([0, 0, -33]) cube([16, 12, 6], center = true);  // balance pad
        }
        along_y(26, 26);                                          // crankpin bore
        for (s = [-1, 1]) translate([s * 36, 0, 0]) cylinder(h = 40, r = 4.6, center = true);  // bolt holes
      }
      translate([0, 0, half * 20.2]) cube([90, 30, 40], center = true);  // each half stops 0.2 short of the split
    }
  color(bronze) for (half = [1, -1])                              // bearing shells, each with its tang
    intersection() {
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
  color(steel) for (s = [-1, 1]) translate([s * 36, 0, 0]) bolt();
}

module rod() {
  color(forged) {
    small_end();
    beam();
    translate([0, 0, -rod_length]) big_end();
  }
}

// ---- the assembly -------------------------------------------------------------
piston_cut();
barrel();
wrist_pin();
translate([0, 0, pin_z]) rotate([0, -rod_angle, 0]) rod();
