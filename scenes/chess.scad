// CHESS: a middle-game position on a board, the kind of model the paper calls
// CHESS/CHESSE (143-144 objects). Every piece is turned from cones and
// cylinders, with spheres for heads and boxes for crenels, the cross and the
// knight's mane, combined by union, difference and intersection.
//
// chess.csg is this file exported by OpenSCAD 2021.01 (an absolute -o path,
// because OpenSCAD writes a relative one beside the input):
//   openscad -o "$PWD/scenes/chess.csg" scenes/chess.scad
// capsim renders the export with its default light, seen from the camera
// statement kept at the top of chess.csg (docs/models.md).
//
// Units: a square is 10 x 10; file a..h runs along +x, rank 1..8 along +y,
// White at rank 1 (nearest OpenSCAD's default view).
//
// Placement: the whole position is raised 58 degrees about the x axis (the
// board's own file direction), far side up, so that the default view, from
// the front right 35 degrees above the xy plane, looks down on the board at
// 69 degrees, as a player standing over the table does. The paper makes CHES
// about twice as costly as BALLS (Table 5-1: 128 against 60 s on the M380,
// 155 against 72 s on the CAP), and a frame's cost follows the screen the
// model covers: about a millisecond of M380 time for each pixel that meets
// the board or a piece (the ray and its shadow ray test the board's boxes and
// the pieces standing in the voxels they cross), a twentieth of that for one
// that meets nothing, whatever the pieces' size or arrangement. Seen from
// 15 degrees above, as before, the board covered an eighth of the screen;
// facing the view it covers more than a quarter, the most the default view
// allows: it frames the sphere round the bounds of all primitives, and a tip
// about the board's own edge, unlike one about a skew axis, leaves those
// bounds as small as a flat board's. The frame's border is 3 units (was 4)
// for the same reason. That makes a frame 1.4 times as costly as BALLS
// (87 s on the M380 at 512 x 512, 115 s on the CAP at 384 x 384), still
// short of the paper's 2.1 times: the export carries no material, so
// CHESS, unlike BALLS, has no reflection rays. The work still falls unevenly on the screen's rows,
// so line mode spreads it by about 20 % at 384 x 384 while dot mode keeps it
// within a few per cent, as in the paper's Table 4-4 (CHESSE: line mode
// d = 20.1 %, dot mode 4.4 %).
//
// Primitives: board 18; White 69 (king 9, queen 15, rook 8, bishop 7,
// knight 10, four pawns of 5); Black 57 (king 9, two rooks of 8, bishop 7,
// five pawns of 5); 144 in all.

$fn = 48;  // only smooths OpenSCAD's own preview; capsim ignores it

white = [0.93, 0.89, 0.80];
black = [0.20, 0.16, 0.15];
light_square = [0.87, 0.76, 0.58];
dark_square = [0.42, 0.25, 0.14];
frame = [0.30, 0.18, 0.10];

function at(file, rank) = [(file - 4.5) * 10, (rank - 4.5) * 10, 0];

// ---- the board: 18 primitives ----------------------------------------------
// The dark squares are the exclusive or of two sets of stripes:
// (odd files and odd ranks) + (even files and even ranks), each an
// intersection of two unions of four stripes; 16 boxes instead of 32.
// Stripes along y are 0.2 high and those along x 0.3, so the square's top is
// always the y-stripe's face (no coincident faces).
module stripes_x(first_rank) {  // four stripes along x at ranks first, first+2, ...
  for (k = [0 : 3])
    translate([-40, (first_rank - 1 + 2 * k) * 10 - 40, -0.2]) cube([80, 10, 0.5]);
}
module stripes_y(first_file) {
  for (k = [0 : 3])
    translate([(first_file - 1 + 2 * k) * 10 - 40, -40, -0.1]) cube([10, 80, 0.3]);
}
module board() {
  color(frame) translate([-43, -43, -4]) cube([86, 86, 3.5]);
  color(light_square) translate([-40, -40, -3]) cube([80, 80, 3]);
  color(dark_square) union() {
    intersection() { stripes_y(1); stripes_x(1); }  // a1 is dark
    intersection() { stripes_y(2); stripes_x(2); }
  }
}

// ---- the pieces --------------------------------------------------------------
// A foot: a disc and a bevel (2 primitives).
module foot(r) {
  cylinder(h = 1.2, r = r);
  translate([0, 0, 1.2]) cylinder(h = 1.0, r1 = r, r2 = r * 0.78);
}

// Pawn: foot, tapering body, collar, ball (5).
module pawn() {
  foot(3.4);
  translate([0, 0, 2.2]) cylinder(h = 5.2, r1 = 2.3, r2 = 1.1);
  translate([0, 0, 7.0]) cylinder(h = 0.7, r = 1.9);
  translate([0, 0, 9.4]) sphere(r = 2.1);
}

// Rook: foot, body, collar, and a hollow turret with two crossing crenel cuts (8).
module rook() {
  foot(3.8);
  translate([0, 0, 2.2]) cylinder(h = 7.5, r1 = 2.9, r2 = 2.3);
  translate([0, 0, 9.2]) cylinder(h = 0.8, r = 2.9);
  difference() {
    translate([0, 0, 10]) cylinder(h = 3.2, r = 3.0);
    translate([0, 0, 11]) cylinder(h = 3, r = 2.0);
    translate([0, 0, 12.4]) cube([8, 1.3, 2], center = true);
    translate([0, 0, 12.4]) cube([1.3, 8, 2], center = true);
  }
}

// Bishop: foot, body, collar, a mitre (stretched ball) with a slanting slit,
// and a small finial (7).
module bishop() {
  foot(3.5);
  translate([0, 0, 2.2]) cylinder(h = 8, r1 = 2.4, r2 = 1.1);
  translate([0, 0, 9.6]) cylinder(h = 0.8, r = 2.2);
  difference() {
    translate([0, 0, 13]) scale([1, 1, 1.5]) sphere(r = 2.3);
    translate([0.6, 0, 14.2]) rotate([0, 35, 0]) cube([0.7, 6, 4], center = true);
  }
  translate([0, 0, 16.8]) sphere(r = 0.8);
}

// Knight: foot, a neck and a head of cones flattened sideways, a mane (a box
// rounded by a ball), a mouth cut and eyes drilled, and two ears (10). It
// looks along +x.
module knight() {
  foot(3.6);
  difference() {
    union() {
      translate([0, 0, 2]) rotate([0, 14, 0]) scale([1, 0.62, 1]) cylinder(h = 9.5, r1 = 3.0, r2 = 2.1);  // neck, leaning forward
      translate([1.6, 0, 11.3]) rotate([0, 118, 0]) scale([1, 0.7, 1]) cylinder(h = 6.0, r1 = 2.3, r2 = 1.3);  // head, muzzle forward-down
      intersection() {  // mane: a ridge down the back of the neck
        translate([-1.7, 0, 7.4]) rotate([0, 19, 0]) cube([1.8, 1.1, 10], center = true);
        translate([0.2, 0, 7.4]) scale([0.75, 1, 1.25]) sphere(r = 4.8);
      }
    }
    translate([6.6, 0, 8.2]) rotate([0, 28, 0]) cube([3, 4, 0.4], center = true);  // mouth
    translate([2.6, 0, 11.0]) rotate([90, 0, 0]) cylinder(h = 5, r = 0.4, center = true);  // eyes
  }
  translate([1.3, -0.7, 12.2]) rotate([0, -10, 0]) cylinder(h = 1.8, r1 = 0.6, r2 = 0);  // ears
  translate([1.3, 0.7, 12.2]) rotate([0, -10, 0]) cylinder(h = 1.8, r1 = 0.6, r2 = 0);
}
// Queen: foot, body, two collars, a crown (a flared cone with eight balls
// cut from its rim) and a ball on top (15).
module queen() {
  foot(3.9);
  translate([0, 0, 2.2]) cylinder(h = 10, r1 = 2.6, r2 = 1.2);
  translate([0, 0, 10.6]) cylinder(h = 0.7, r = 2.3);
  translate([0, 0, 11.3]) cylinder(h = 0.8, r1 = 2.3, r2 = 1.5);
  difference() {
    translate([0, 0, 12.1]) cylinder(h = 3.4, r1 = 1.5, r2 = 2.9);
    for (k = [0 : 7])
      rotate(k * 45 + 22.5) translate([2.9, 0, 15.6]) sphere(r = 0.9);
  }
  translate([0, 0, 15.6]) sphere(r = 1.2);
}

// King: foot, body, collar, flared crown with a cap, an orb and a cross of two
// boxes (9).
module king() {
  foot(4.0);
  translate([0, 0, 2.2]) cylinder(h = 11, r1 = 2.7, r2 = 1.3);
  translate([0, 0, 11.6]) cylinder(h = 0.8, r = 2.4);
  translate([0, 0, 12.4]) cylinder(h = 3.0, r1 = 1.5, r2 = 2.6);
  translate([0, 0, 15.4]) cylinder(h = 0.9, r1 = 2.6, r2 = 1.6);
  translate([0, 0, 16.5]) sphere(r = 0.9);
  translate([0, 0, 18.8]) cube([0.9, 0.9, 4.0], center = true);
  translate([0, 0, 19.4]) cube([2.6, 0.9, 0.9], center = true);
}

// ---- the position, raised towards the viewer ---------------------------------------
rotate([58, 0, 0]) {
  board();

  color(white) {
    translate(at(7, 1)) king();
    translate(at(4, 3)) queen();
    translate(at(6, 1)) rook();
    translate(at(3, 4)) bishop();
    translate(at(6, 3)) knight();
    for (f = [1, 6, 7, 8]) translate(at(f, 2)) pawn();
  }

  color(black) {
    translate(at(7, 8)) king();
    translate(at(5, 8)) rook();
    translate(at(1, 8)) rook();
    translate(at(4, 6)) bishop();
    for (f = [1, 6, 7]) translate(at(f, 7)) pawn();
    translate(at(4, 5)) pawn();
    translate(at(8, 6)) pawn();
  }
}
