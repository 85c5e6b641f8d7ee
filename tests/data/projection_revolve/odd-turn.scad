projection(cut = false) rotate_extrude(angle = 360, convexity = 2, $fn = 7, $fa = 12, $fs = 2) polygon(points = [[2, 0], [6, -1], [4, 3]]);
