projection(cut = true) rotate_extrude(angle = 200, convexity = 2, $fn = 24, $fa = 12, $fs = 2) difference() { translate([3, -2, 0]) square([6, 4]); translate([5, -1, 0]) square([2, 2]); }
