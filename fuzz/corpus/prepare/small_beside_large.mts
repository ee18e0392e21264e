# small_beside_large.mts -- spheres of radius 0.03 to 0.1 beside objects 100 units across
# (a cube face as the backdrop, a sphere of radius 100 whose outline crosses the view),
# seen close up: both scales must be exact in one image.
viewport 0 127 0 127
window -0.4 0.4 -0.4 0.4
viewplane 0
perspective 0 0 20
light point 3 4 15
shadows on
cube
  scale 100 100 100
  translate -50 -50 -101
  colour 1
sphere
  scale 100 100 100
  translate 100.25 0 -30
  colour 2
sphere
  scale 0.03 0.03 0.03
  translate -0.2 0.1 0
  colour 3
sphere
  scale 0.05 0.05 0.05
  translate 0 -0.15 0.5
  colour 4
sphere
  scale 0.1 0.1 0.1
  translate -0.1 0.25 -0.5
  colour 5
