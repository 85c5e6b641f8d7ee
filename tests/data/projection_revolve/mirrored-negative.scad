projection(cut = false) rotate_extrude(angle = -120, convexity = 2, $fn = 0, $fa = 5, $fs = 0.5) translate([-6, 0, 0]) circle(r = 2, $fn = 8, $fa = 12, $fs = 2);
