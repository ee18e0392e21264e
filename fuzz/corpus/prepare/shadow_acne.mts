# shadow_acne.mts -- shadow acne: curved and flat surfaces 100 units from the eye lit by a
# point light close by, so shadow rays leave every lit point at all angles; a lit point
# that shadows itself (or its neighbour through rounding) darkens.
viewport 0 127 0 127
window -4 4 -4 4
viewplane 0
perspective 0 0 100
light point 10 12 20
shadows on
sphere
  translate -2 2 0
  colour 1
cylinder
  rotate x -60
  translate 2 2 0
  colour 2
cone
  scale 1 1 1.5
  rotate x -100
  translate -2 -1 0
  colour 3
cube
  scale 1.5 1.5 1.5
  rotate y 30
  rotate x 20
  translate 1.5 -2.5 0
  colour 4
sphere
  scale 0.5 0.5 0.5
  translate 0 0 1
  colour 5
