# cone_apex.mts -- rays through a cone's apex: the middle pixel of this odd-sized image
# samples the apex of a cone pointing at the viewer exactly, where the side's normal vanishes.
viewport 0 126 0 126
window -2 2 -2 2
viewplane 10
parallel 0 0 -1
light direction 1 1 1
shadows on
cone
  scale 1.5 1.5 2
  rotate x 180
  colour 1
cone
  scale 0.5 0.5 1
  rotate y 90
  translate -1.5 1.5 0
  colour 2
