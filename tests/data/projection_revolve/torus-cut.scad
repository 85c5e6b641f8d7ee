projection(cut = true) translate([0, 0, 1.5]) rotate_extrude(angle = 360, convexity = 2, $fn = 0, $fa = 12, $fs = 2) translate([10, 0, 0]) circle(r = 3, $fn = 0, $fa = 12, $fs = 2);
