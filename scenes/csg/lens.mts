# lens.mts -- a lens of glass by constructive solid geometry (thesis chapter 3 and chapter 5's
# ray tree): the intersection of two large spheres, a biconvex lens standing upright over a
# striped floor, in front of three coloured posts. Light passing through the glass leaves by
# the far side of the combined spans, so the lens shows the posts upside down and magnified.

viewport 0 255 0 191
window -60 60 -45 45
viewplane 0
perspective 0 20 220
light point -120 200 240
ambient 0.25
shadows on
depth 5

group 1 15 2 2 up      # red post
group 2 2 13 3 up      # green post
group 3 3 5 15 up      # blue post
group 4 14 14 12 up    # floor, light stripes
group 5 6 6 8 up       # floor, dark stripes
group 6 12 14 15 up    # the glass
background 0

cube                   # the floor
  scale 400 4 400
  translate -200 -44 -300
  colour 4
cube                   # dark stripes across it
  scale 400 4 14
  translate -200 -43.9 -30
  colour 5
cube
  scale 400 4 14
  translate -200 -43.9 -90
  colour 5
cube
  scale 400 4 14
  translate -200 -43.9 30
  colour 5
cylinder               # three posts behind the lens
  scale 7 7 60
  rotate x -90
  translate -30 -40 -110
  colour 1
cylinder
  scale 7 7 60
  rotate x -90
  translate 0 -40 -110
  colour 2
cylinder
  scale 7 7 60
  rotate x -90
  translate 30 -40 -110
  colour 3
intersection           # the lens: two spheres of radius 60 whose centres are 100 apart
  sphere
    scale 60 60 60
    translate 0 0 -50
  sphere
    scale 60 60 60
    translate 0 0 50
end
  rotate y 50
  translate 0 -2 20
  colour 6
  ka 0.1
  kd 0.1
  ks 0.9
  pwr 60
  rnd 0
  reflect 0.1
  transmit 0.85
  ior 1.5
