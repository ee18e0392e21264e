# cone_parallel_side.mts -- rays parallel to a cone's side: the unit cone turned 45 degrees
# about y has one generator line along z, so rays along -z give A = 0 (a linear equation).
viewport 0 127 0 127
window -3 3 -3 3
viewplane 10
parallel 0 0 -1
light direction -1 1 2
shadows on
cone
  scale 2 2 2
  rotate y 45
  translate -0.5 0 -2
  colour 1
cone
  rotate y -45
  translate 1.5 1.5 -1
  colour 2
cube
  scale 8 8 0.5
  translate -4 -4 -5
  colour 3
