# eye_inside.mts -- the eye inside objects: inside a sphere of radius 50 that is itself
# inside a cube, with a point light and small objects inside too; every ray starts inside.
viewport 0 127 0 127
window -10 10 -10 10
viewplane -10
perspective 0 0 0
light point 10 20 5
shadows on
cube
  scale 120 120 120
  translate -60 -60 -60
  colour 1
sphere
  scale 50 50 50
  colour 2
sphere
  scale 4 4 4
  translate 6 -3 -25
  colour 3
cylinder
  scale 3 3 10
  rotate y 30
  translate -8 2 -30
  colour 4
