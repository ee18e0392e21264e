# small_far_sphere_1e-4.mts -- a sphere of radius 1 seen from 10 000 units (radius/distance
# 1e-4), and a shadow-casting companion.
viewport 0 127 0 127
window -1.5 1.5 -1.5 1.5
viewplane 0
perspective 0 0 10000
light point 20 20 20
shadows on
sphere
  colour 1
sphere
  scale 0.7 0.7 0.7
  translate 1.2 1.2 2
  colour 2
