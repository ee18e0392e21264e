# grazing_silhouettes.mts -- grazing and silhouette rays: many curved outlines (spheres,
# cylinders and cones of several sizes) and terminators lit from the side, where a ray
# only just touches or only just misses a surface.
viewport 0 127 0 127
window -30 30 -30 30
viewplane 0
perspective 0 0 200
light direction 1 0.1 0.05
ambient 0.2
shadows on
sphere
  scale 12 12 12
  translate -14 14 0
  colour 1
sphere
  scale 6 6 6
  translate 14 16 -10
  colour 2
sphere
  scale 1.5 1.5 1.5
  translate 4 4 20
  colour 3
cylinder
  scale 7 7 20
  rotate x -70
  rotate y 20
  translate -14 -18 0
  colour 4
cone
  scale 9 9 18
  rotate x 80
  rotate z 15
  translate 16 -4 0
  colour 5
sphere
  scale 3 3 3
  translate 20 -22 5
  colour 6
