// DISB: an animated scene of the kind the paper's Table 4-5 measured: many
// small objects with sharp edges, bunched in one part of the screen and
// moving through it, so that antialiasing work is local and moves from frame
// to frame. A cluster of boxes, cones, cylinders, rounded and drilled cubes
// tumbles across a plain floor in front of a plain wall; each object also
// spins on its own. The floor and the wall fix the scene's bounds, so
// capsim's default view is the same in every frame.
//
// The 64 frames are this file exported by OpenSCAD 2021.01's animation
// ($t = k / 64 for frame k), written as scenes/disb/f00000.csg ...
// f00063.csg (an absolute -o path, because OpenSCAD writes a relative one
// beside the input):
//   openscad --animate 64 -o "$PWD/scenes/disb/f.csg" scenes/disb.scad
//
// Units: the floor is 160 x 100, the wall 84 high; the cluster is about 70
// across. Every frame has the same 86 primitives (the floor and the wall, 84
// in the cluster); only their placements change.

$fn = 24;  // only smooths OpenSCAD's own preview; capsim ignores it

n = 60;                    // objects in the cluster
golden = 137.50776405;     // the golden angle, in degrees

// The cluster's centre over the sequence, t in [0, 1): across the floor from
// back left to front right, bobbing up and down twice.
function centre(t) = [-44 + 88 * t, 14 - 28 * t, 41 + 5 * sin(720 * t)];

// Where object k sits in the cluster: on a Fibonacci sphere, on one of three
// shells (radius 15, 22 or 29), so the objects spread evenly.
function place(k) =
  let (z = 1 - 2 * (k + 0.5) / n, r = sqrt(1 - z * z), phi = k * golden, shell = 15 + 7 * (k % 3))
  shell * [r * cos(phi), r * sin(phi), z];

// A colour per object, turning round the hue circle.
function hue(k) = let (h = k * 47) [0.5 + 0.45 * cos(h), 0.5 + 0.45 * cos(h - 120), 0.5 + 0.45 * cos(h + 120)];

// The objects, by k mod 5: a box, a cone, a cylinder, a cube rounded by a
// sphere (intersection, 2 primitives) and a cube drilled by a sphere
// (difference, 2 primitives): 12 of each, 84 primitives.
module object(k) {
  kind = k % 5;
  if (kind == 0) cube([9, 6.5, 4.5], center = true);
  else if (kind == 1) cylinder(h = 9, r1 = 4.5, r2 = 0, center = true);
  else if (kind == 2) cylinder(h = 4, r = 4.5, center = true);
  else if (kind == 3) intersection() { cube(7, center = true); sphere(r = 4.6); }
  else difference() { cube(6.5, center = true); sphere(r = 4.2); }
}

// The plain floor and wall.
color([0.80, 0.82, 0.86]) {
  translate([-80, -50, -2]) cube([160, 100, 2]);
  translate([-80, 50, -2]) cube([160, 2, 86]);
}

// The cluster: carried along its path, tumbling as a whole about a tilted
// axis (one turn over the sequence), each object spinning twice on its own.
translate(centre($t)) rotate(a = 360 * $t, v = [1, 0.6, 0.3])
  for (k = [0 : n - 1])
    translate(place(k)) rotate([k * 37 + 720 * $t, k * 53, k * 11 + 360 * $t])
      color(hue(k)) object(k);
