# facing-mirrors.mts -- a hard case of the ray tree (chapter 5): two parallel mirrors
# (reflect 1) facing each other with a red ball between them, seen from above at an angle,
# at the format's full depth 8: the tree's stack reaches its capacity and every generation
# spawns again (the weight never falls below 1/256).
viewport 0 63 0 47
window -100 100 -75 75
viewplane 0
perspective 0 40 200
light point 50 150 150
shadows on
depth 8
group 1 15 2 2 up
group 2 4 8 15 up
background 16
cube                     # the left mirror
  scale 4 100 8000
  translate -64 -50 -7850
  colour 2
  ka 0.1
  kd 0.1
  ks 0.2
  reflect 1
cube                     # the right mirror
  scale 4 100 8000
  translate 60 -50 -7850
  colour 2
  ka 0.1
  kd 0.1
  ks 0.2
  reflect 1
sphere                   # the ball between them
  scale 15 15 15
  translate 10 0 -40
  colour 1
