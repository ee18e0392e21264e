# torus_axis_hole.mts -- rays along a torus's axis through its hole: a parallel view straight
# down the axis of a stack of tori (a ray through the hole meets nothing of them), a sphere
# seen through the holes, and a light on the axis so shadow rays start on tori's surfaces and
# pass through the holes.
viewport 0 127 0 127
window -30 30 -30 30
viewplane 50
parallel 0 0 -1
light point 0 0 200
shadows on
torus 0.3
  scale 25 25 25
  colour 1
torus 0.5
  scale 12 12 12
  translate 0 0 -20
  colour 2
torus 0.1
  scale 6 6 6
  translate 0 0 -30
  colour 3
sphere
  scale 3 3 3
  translate 0 0 -60
  colour 4
cube
  scale 80 80 2
  translate -40 -40 -70
  colour 5
