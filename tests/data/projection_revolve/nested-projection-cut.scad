projection(cut = true) rotate_extrude(angle = 360, convexity = 2, $fn = 11, $fa = 12, $fs = 2) translate([5, -1, 0]) projection(cut = false) rotate([0, 0, 20]) cube(size = [2, 3, 1], center = false);
