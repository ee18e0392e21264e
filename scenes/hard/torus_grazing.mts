# torus_grazing.mts -- tori seen almost edge-on: the eye 0.5 units above the plane of a ring
# 40 units across, so that most rays that meet it graze the tube (the quartic's double roots),
# a fatter ring tilted behind it and a thin one standing, all casting shadows on each other.
viewport 0 127 0 127
window -24 24 -24 24
viewplane 0
perspective 0 0.5 90
light point 30 60 50
shadows on
torus 0.2
  scale 20 20 20
  rotate x 90
  colour 1
torus 0.6
  scale 8 8 8
  rotate x 80
  translate 6 4 -20
  colour 2
torus 0.05
  scale 12 12 12
  rotate y 60
  translate -10 6 -5
  colour 3
