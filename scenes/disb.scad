// DISB: the animation of the paper's Table 4-5, remade from its figures.
// The paper's own model is lost; these are the constraints its figures set
// (docs/models.md, DISB):
//
// - Table 4-5 against Table 5-1: a frame without antialiasing costs
//   1336 s / 64 = 20.9 s, as much as a frame of CAD (20 s, 178 objects):
//   DISB is cheap, a few primitives.
// - Table 4-5, antialiasing: the time grows 3.46 times and the largest
//   deviation from 6.5 % to 60.4 %. Antialiasing traces sub-pixels only at
//   edges (section 3.3), so in a typical frame the edges fall on the pixels of
//   a few cells: in dot mode cell (r, c) owns the pixels (x, y) with
//   y mod 8 = r and x mod 8 = c (fig. 3-3), so a long edge along a pixel row
//   loads one row of 8 cells, an edge along a pixel column one column of 8
//   cells, and the cell at the crossing gets both.
// - Table 4-5, frame averaging: with the dot pattern turned from frame to
//   frame the deviation falls back to 8.8 % and the time by 44 %. That needs
//   the load to stay on the same cells' pixels from frame to frame: every
//   cell then takes its turn at the loaded pixels, whatever the number of
//   frames in a unit (8, 16 or 64), as long as the unit turns the pattern
//   through every row and column position equally often.
//
// So: two light bars, each sliding along a dark rail, the rails crossing
// against the plain background; 4 primitives. Everything lies in planes
// facing the eye of capsim's default view (OpenSCAD's rotation [55, 0, 25];
// rotate([55, 0, 25]) below turns x, y, z into the screen's right, up and
// towards the eye), so every long edge lies along a pixel row or column.
// The model is laid out for a 384 x 384 screen (--size 384x384): the
// functions below redo capsim's default camera (src/trace/prepared_scene.cpp:
// 40 degrees, centred on the bounds, at 1.05 times their half diagonal over
// sin 20) and put every long edge 0.35 pixel below or right of a pixel
// boundary of the rows and columns 176 and 208 (the rails', = 0 mod 8) and
// 180 and 204 (the bars', = 4 mod 8):
// - the horizontal rail spans rows 176.35 to 208.35, its bar 180.35 to
//   204.35; the vertical rail and its bar span the same columns;
// - so the rails' long edges load cell row 0 and cell column 0, the bars'
//   cell row 4 and cell column 4; cell (0, 0) carries both rails' edges and
//   is the slowest. Putting the bars' edges on other cells than the rails'
//   keeps the slowest cell's antialiasing to the rails' edges: with all
//   edges on one row and column of cells, antialiasing made a frame 4.9
//   times as long, against the paper's 3.46. 0.35 keeps each edge off the
//   corner samples (whole pixels) and off the depth-2 sub-samples (quarters).
// At another size the edges fall on other rows and columns and spread over
// more cells.
//
// Motion, over $t = k / 64 for frame k: the horizontal bar slides along its
// rail from the left end to the right end, the vertical bar along its rail
// from the top to the bottom, each 78 units (1.22 units, about 2.4 pixels, a
// frame); the rails stay. The bars move along their own length, so their
// long edges stay on the same pixel rows and columns in every frame: the
// antialiasing work stays on the same cells, as frame averaging assumes.
// The rails span the scene's bounds in every frame, so capsim's default view
// is the same in each.
//
// The 64 frames are this file exported by OpenSCAD 2021.01's animation,
// written as scenes/disb/f00000.csg ... f00063.csg (an absolute -o path,
// because OpenSCAD writes a relative one beside the input):
//   openscad --animate 64 -o "$PWD/scenes/disb/f.csg" scenes/disb.scad

W = 384;            // the screen's side in pixels (--size 384x384)
A = 64;             // half the length of a rail
HT = 1;             // thickness of the horizontal rail
VT = 3;             // thickness of the vertical rail, in front of the other
BL = 46;            // length of a bar
travel = 2 * A - BL - 4;  // how far a bar slides, end to end of its rail
hrail = [176.35, 208.35];  // screen rows of the horizontal rail's edges
hbar = [180.35, 204.35];   // and of its bar's
vrail = [176.35, 208.35];  // screen columns of the vertical rail's edges
vbar = [180.35, 204.35];   // and of its bar's

// The screen's right, up and towards-the-eye directions in world space
// (the columns of rotate([55, 0, 25])).
X = [cos(25), sin(25), 0];
Y = [-sin(25) * sin(35), cos(25) * sin(35), cos(35)];
Z = [sin(25) * cos(35), -cos(25) * cos(35), sin(35)];
function world(q) = q[0] * X + q[1] * Y + q[2] * Z;

// The corners of a box of size s centred at c, in the screen-facing frame.
function corners(c, s) = [for (i = [-1, 1], j = [-1, 1], l = [-1, 1]) world(c + [i * s[0], j * s[1], l * s[2]] / 2)];
// The rails' corners; r = [centre y, width] of the horizontal rail and
// [centre x, width] of the vertical one. The rails alone make the bounds.
function rail_corners(r) = concat(corners([0, r[0], 0], [2 * A, r[1], HT]), corners([r[2], 0, 0], [r[3], 2 * A, VT]));
function lo(ps) = [for (i = [0 : 2]) min([for (p = ps) p[i]])];
function hi(ps) = [for (i = [0 : 2]) max([for (p = ps) p[i]])];
// capsim's default view of those bounds: the centre (in the screen-facing
// frame) and the eye's distance from it.
function view(r) = let (ps = rail_corners(r), c = (lo(ps) + hi(ps)) / 2, e = hi(ps) - lo(ps))
  [[c * X, c * Y, c * Z], 1.05 * norm(e) / 2 / sin(20)];
// Pixels per unit at depth z, and the coordinate of a screen row or column.
function scale(v, z) = (W / 2) / ((v[1] - (z - v[0][2])) * tan(20));
function row_y(v, row, z) = v[0][1] + (W / 2 - row) / scale(v, z);
function col_x(v, col, z) = v[0][0] + (col - W / 2) / scale(v, z);
// The rails placed so that their edges fall on hrail and vrail; as the rails
// make the bounds, the view moves a little with them: repeat until it stays.
function place(r) = let (v = view(r), t = row_y(v, hrail[0], HT / 2), b = row_y(v, hrail[1], HT / 2),
                         l = col_x(v, vrail[0], VT / 2), rt = col_x(v, vrail[1], VT / 2))
  [(t + b) / 2, t - b, (l + rt) / 2, rt - l];
function settle(r, n) = n == 0 ? r : settle(place(r), n - 1);
R = settle([0, 16, 0, 16], 8);
V = view(R);

rotate([55, 0, 25]) {
  // The rails, mid grey.
  color([0.50, 0.52, 0.56]) {
    translate([0, R[0], 0]) cube([2 * A, R[1], HT], center = true);
    translate([R[2], 0, 0]) cube([R[3], 2 * A, VT], center = true);
  }
  // The horizontal bar, warm white, just in front of its rail, from left to
  // right; it passes behind the vertical rail.
  hz = HT / 2 + 0.75;  // its front face
  color([1.0, 0.93, 0.72])
    translate([-travel / 2 + travel * $t - BL / 2, row_y(V, hbar[1], hz), hz - 0.5])
      cube([BL, row_y(V, hbar[0], hz) - row_y(V, hbar[1], hz), 0.5]);
  // The vertical bar, cool white, just in front of its rail, from top to
  // bottom; it passes in front of the horizontal rail.
  vz = VT / 2 + 0.75;
  color([0.80, 0.92, 1.0])
    translate([col_x(V, vbar[0], vz), travel / 2 - travel * $t - BL / 2, vz - 0.5])
      cube([col_x(V, vbar[1], vz) - col_x(V, vbar[0], vz), BL, 0.5]);
}
