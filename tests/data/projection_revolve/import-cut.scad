projection(cut = true) translate([0, 0, -10]) rotate_extrude(angle = 300, convexity = 2, $fn = 0, $fa = 12, $fs = 2) import(file = "profile.svg", $fn = 10, $fa = 12, $fs = 2);
