# die.mts -- a die by constructive solid geometry (thesis chapter 3): a cube rounded by
# intersecting it with a sphere, minus spherical pips; shadows on. The pips are subtracted, so
# their hollows show their own colour (an operand's material) with the normal turned inward.

viewport 0 255 0 191
window -64 64 -30 66
viewplane -10
perspective 60 90 150
light point 160 300 220
ambient 0.25
shadows on

group 1 15 15 14 up    # the die's ivory
group 2 12 1 1 up      # the pips
group 3 3 8 12 up      # the table
background 0

cube                   # the table top
  scale 260 10 215
  translate -160 -10 -170
  colour 3
difference             # the die: a rounded cube ...
  intersection
    cube
      scale 2 2 2
      translate -1 -1 -1
    sphere
      scale 1.38 1.38 1.38
  end
  sphere               # ... minus one pip on the front face (the 1)
    scale 0.22 0.22 0.22
    translate 0 0 1.08
    colour 2
  sphere               # two on top
    scale 0.2 0.2 0.2
    translate -0.45 1.08 -0.45
    colour 2
  sphere
    scale 0.2 0.2 0.2
    translate 0.45 1.08 0.45
    colour 2
  sphere               # three on the right
    scale 0.19 0.19 0.19
    translate 1.08 0.5 -0.5
    colour 2
  sphere
    scale 0.19 0.19 0.19
    translate 1.08 0 0
    colour 2
  sphere
    scale 0.19 0.19 0.19
    translate 1.08 -0.5 0.5
    colour 2
end
  scale 24 24 24
  rotate y -30
  translate 0 24 0
  colour 1
