# small_far_sphere_1e-3.mts -- a sphere of radius 1 seen from 1000 units (radius/distance
# 1e-3): the quadratic's terms are a million times the discriminant at the silhouette.
viewport 0 127 0 127
window -1.5 1.5 -1.5 1.5
viewplane 0
perspective 0 0 1000
light point 20 20 20
shadows on
sphere
  colour 1
sphere
  scale 0.3 0.3 0.3
  translate 0.9 0.9 1.5
  colour 2
