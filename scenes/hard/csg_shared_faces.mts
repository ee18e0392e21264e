# csg_shared_faces.mts -- solids whose operands share faces (constructive solid geometry,
# thesis chapter 3): a block with a pocket flush with its top face and a slot flush with its
# front, turned 17 degrees; a plate drilled by a cylinder exactly as long as the plate is thick
# (its caps on the plate's faces); and two cubes united along a common face. Each operand's
# crossings are computed in its own space, so a shared face is met at t values a few units in
# the last place apart: without the rule for shared faces (docs/scene-format.md, "Solids")
# these speckle.
viewport 0 127 0 127
window -100 100 -120 80
viewplane 0
perspective 30 140 160
light point -80 200 150
shadows on
group 1 15 12 4 up
group 2 4 9 15 up
group 3 3 14 6 up
background 0
difference
 cube
  scale 80 40 80
  translate -40 -20 -40
 cube
  scale 40 16 40
  translate -20 4 -20
  colour 2
 cube
  scale 20 20 32
  translate -10 -10 8
  colour 2
end
 rotate y 17
 translate -20 0 -30
 colour 1
difference
 cube
  scale 50 6 50
  translate 30 -20 10
 cylinder
  scale 10 10 6
  rotate x -90
  translate 55 -20 35
  colour 2
end
 colour 3
union
 cube
  scale 20 20 20
  translate -70 -20 30
 cube
  scale 20 20 20
  translate -50 -20 30
  colour 2
end
 rotate y -10
 colour 3
