# cylinder_parallel_axis.mts -- rays exactly parallel to a cylinder's axis (the quadratic's
# A = 0 for the side): only the caps are seen; one cylinder is tilted by a hair so A is tiny.
viewport 0 127 0 127
window -20 20 -20 20
viewplane 50
parallel 0 0 -1
light direction 1 1 2
shadows on
cylinder
  scale 8 8 20
  translate -9 9 -20
  colour 1
cylinder
  scale 6 6 10
  rotate z 30
  translate 9 9 -5
  colour 2
cylinder
  scale 7 7 15
  rotate x 0.001
  translate -9 -9 -15
  colour 3
cube
  scale 40 40 1
  translate -20 -20 -30
  colour 4
