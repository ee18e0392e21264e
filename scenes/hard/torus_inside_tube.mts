# torus_inside_tube.mts -- the eye inside the tube of a large torus: every primary ray starts
# inside it (a ray from inside the tube must leave by the tube's wall, not report a hit beyond
# it), with a smaller torus and a sphere inside the tube too and a light inside as well.
viewport 0 127 0 127
window -10 10 -10 10
viewplane -8
perspective 0 0 0
light point 2 3 -4
shadows on
torus 0.4
  scale 100 100 100
  rotate y 90
  translate 0 -100 0
  colour 1
torus 0.3
  scale 6 6 6
  rotate x 30
  translate 3 -2 -25
  colour 2
sphere
  scale 3 3 3
  translate -6 2 -30
  colour 3
