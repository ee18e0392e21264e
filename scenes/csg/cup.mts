# cup.mts -- a cup by constructive solid geometry (thesis chapter 3) with a torus for its
# handle (§5.2.1): the body is a cylinder united with the handle, minus a smaller cylinder
# that hollows it out (and cuts away the part of the handle inside the wall). A saucer below
# is a flat cylinder minus a shallow one.

viewport 0 255 0 191
window -76 76 -44 70
viewplane 0
perspective 0 170 210
light point -100 260 200
ambient 0.25
shadows on

group 1 15 15 15 up    # white china
group 2 15 6 1 up      # the rim's orange band
group 3 4 9 14 up      # the table
background 0

cube                   # the table top
  scale 400 10 320   # to z = 120: short of the eye (a bound past it would cover the screen)
  translate -200 -10 -200
  colour 3
difference             # the cup
  union
    cylinder           # its body, standing on the saucer
      scale 24 24 44
      rotate x -90
      translate 0 6 0
    torus 0.22         # the handle, upright on the right
      scale 14 14 14
      rotate x 90
      translate 24 30 0
  end
  cylinder             # the hollow, leaving a wall of 3 and a base of 4
    scale 21 21 50
    rotate x -90
    translate 0 10 0
end
  rotate y -25
  colour 1
  rnd 0.2
difference             # the saucer
  cylinder
    scale 42 42 6
    rotate x -90
  cylinder
    scale 36 36 3
    rotate x -90
    translate 0 4 0
    colour 2
end
  colour 1
  rnd 0.2
