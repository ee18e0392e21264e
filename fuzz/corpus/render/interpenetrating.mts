# interpenetrating.mts -- interpenetrating objects: overlapping spheres, a cylinder through
# a sphere, a cone sunk into a cube, with shadows across the intersection curves.
viewport 0 127 0 127
window -25 25 -25 25
viewplane 0
perspective 0 20 150
light point -30 60 80
shadows on
sphere
  scale 10 10 10
  translate -8 5 0
  colour 1
sphere
  scale 8 8 8
  translate 2 8 3
  colour 2
cylinder
  scale 3 3 40
  rotate y 90
  translate -20 5 0
  colour 3
cube
  scale 14 10 14
  translate 6 -15 -7
  colour 4
cone
  scale 6 6 14
  rotate x 90
  translate 13 4 0
  colour 5
