# Fails (exit 1) when a motion record below Z0 ends with its X Y within r of the box x0..x1 y0..y1
# (the box grown by r along the axes: the rounded corners left out), less 1e-6.
/^(linear|rapid|arc) / {
  x = substr($2, 2) + 0; y = substr($3, 2) + 0; z = substr($4, 2) + 0
  if (z >= 0) next
  e = r - 1e-6
  if ((x > x0 - e && x < x1 + e && y >= y0 && y <= y1) || (x >= x0 && x <= x1 && y > y0 - e && y < y1 + e)) {
    print "inside the island: " $0; bad = 1
  }
}
END { exit bad }
