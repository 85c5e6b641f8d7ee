projection(cut = false) rotate_extrude(angle = -75, convexity = 2, $fn = 0, $fa = 4, $fs = 2) import(file = "profile.dxf", $fn = 9, $fa = 12, $fs = 2);
