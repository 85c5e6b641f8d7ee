projection(cut = true) rotate_extrude(angle = 270, convexity = 2, $fn = 16, $fa = 12, $fs = 2) translate([5, -1, 0]) square([3, 2]);
