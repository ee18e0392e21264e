# nut.mts -- a hexagonal nut by constructive solid geometry (thesis chapter 3): a hexagonal
# prism made as the intersection of three slabs turned 60 degrees apart, its corners rounded
# off by a cylinder, minus the hole (a cylinder through it); a bolt (a cylinder) stands in a
# second nut.

viewport 0 255 0 191
window -80 80 -50 70
viewplane 0
perspective 0 160 220
light point -120 260 200
ambient 0.25
shadows on

group 1 12 12 13 up    # steel
group 2 8 8 9 up       # the bolt
group 3 10 6 2 up      # the bench
background 0

cube                   # the bench
  scale 400 10 320   # to z = 120: short of the eye (a bound past it would cover the screen)
  translate -200 -10 -200
  colour 3
difference             # a nut lying on the bench
  intersection
    cube               # three slabs 40 across the flats, 16 thick
      translate -0.5 -0.5 -0.5
      scale 60 16 40
    cube
      translate -0.5 -0.5 -0.5
      scale 60 16 40
      rotate y 60
    cube
      translate -0.5 -0.5 -0.5
      scale 60 16 40
      rotate y 120
    cylinder           # the corners turned off
      scale 22 22 16
      rotate x 90
      translate 0 8 0
  end
  cylinder             # the hole
    scale 11 11 30
    rotate x -90
    translate 0 -15 0
end
  rotate y 15
  translate -30 8 10
  colour 1
  rnd 0.3
union                  # a bolt standing in a second nut
  difference
    intersection
      cube
        translate -0.5 -0.5 -0.5
        scale 60 16 40
      cube
        translate -0.5 -0.5 -0.5
        scale 60 16 40
        rotate y 60
      cube
        translate -0.5 -0.5 -0.5
        scale 60 16 40
        rotate y 120
    end
    cylinder
      scale 11 11 30
      rotate x -90
      translate 0 -15 0
  end
  cylinder             # the bolt's shank, through the hole
    scale 10.5 10.5 44
    rotate x -90
    translate 0 -8 0
    colour 2
end
  rotate y -20
  translate 40 8 -20
  colour 1
  rnd 0.3
