# cube_edges_corners.mts -- rays along cube edges and faces and through corners: cube edges
# lie exactly on pixel samples (spacing 0.125), so rays run inside the side faces' planes;
# a rotated cube shows a corner at a sample. Scales are powers of two, so the inverse
# transforms are exact and every type must find the same ties (see docs/hard-cases.md).
viewport 0 128 0 128
window -8 8 -8 8
viewplane 20
parallel 0 0 -1
light direction 1 2 3
shadows on
cube
  scale 4 4 4
  translate -6 -6 -4
  colour 1
cube
  scale 4 4 4
  translate -2 -6 -4
  colour 2
cube
  scale 4 4 4
  rotate x 45
  rotate y 35.26438968
  translate 3 3 0
  colour 3
cube
  scale 2 2 2
  translate 2 -6 -1
  colour 4
