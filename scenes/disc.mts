# disc.mts -- the disc primitive (`disc`: radius 1 in the plane z = 0, open, seen from both
# sides): a table top, a coin standing on edge, a tilted disc seen almost edge-on, and a ball
# whose shadow falls on them.
viewport 0 255 0 191
window -4 4 -3 3
viewplane 0
perspective 0 3 14
light point 6 10 8
shadows on

disc                  # the table top, seen from above
  scale 4 4 1
  rotate x -90
  colour 7
disc                  # a coin on edge
  scale 0.8 0.8 1
  rotate y 30
  translate -1.5 0.8 0.5
  colour 2
disc                  # nearly edge-on: the thin ellipse is where fixed point is tested hardest
  rotate x 88
  translate 1.8 1.2 -0.5
  colour 5
sphere
  scale 0.6 0.6 0.6
  translate 0.3 0.6 1.2
  colour 1
