# torus.mts -- the ring torus (`torus R`, the thesis's §5.2.1 proposal): a ring lying on a
# table, a thinner one standing up through it, and a ball beside them; one light,
# shadows on. Major radius 1 and tube R in object space, scaled like any primitive.

viewport 0 255 0 191
window -80 80 -60 60
viewplane 0
perspective 0 120 260
light point 150 300 200
ambient 0.2
shadows on

group 1 15 1 1 up      # red ring
group 2 2 5 15 up      # blue ring
group 3 15 14 0 up     # yellow ball
group 4 2 10 3 up      # the table
background 0

cube                   # the table top
  scale 300 10 300
  translate -150 -10 -150
  colour 4
torus 0.3              # lying flat: its axis (z) turned to y
  scale 40 40 40
  rotate x 90
  translate -20 12 0
  colour 1
torus 0.15             # standing up, through the first ring
  scale 30 30 30
  translate -20 30 0
  rotate y 35
  colour 2
sphere
  scale 10 10 10
  translate 40 10 20
  colour 3
