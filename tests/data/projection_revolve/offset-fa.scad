projection(cut = false) rotate([0, 0, 30]) rotate_extrude(angle = 90, convexity = 2, $fn = 0, $fa = 7, $fs = 1) offset(r = 1, $fn = 0, $fa = 12, $fs = 2) translate([4, 0, 0]) square([2, 1]);
