projection(cut = false) rotate_extrude(angle = 180, convexity = 2, $fn = 12, $fa = 12, $fs = 2) translate([2, 0, 0]) text(text = "S", size = 6, font = "Liberation Sans", $fn = 4, $fa = 12, $fs = 2);
