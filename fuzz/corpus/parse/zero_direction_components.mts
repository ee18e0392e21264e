# zero_direction_components.mts -- direction components exactly 0: primary rays along -z,
# a light straight down (0, 1, 0) so shadow rays have two zero components, and axis-aligned
# objects, so object-space directions have zeros too (no division may produce infinity).
viewport 0 127 0 127
window -10 10 -10 10
viewplane 20
parallel 0 0 -1
light direction 0 1 0
shadows on
cube
  scale 24 1 20
  translate -12 -8 -10
  colour 1
sphere
  scale 2 2 2
  translate -5 0 0
  colour 2
cylinder
  scale 2 2 4
  translate 0 2 -2
  colour 3
cone
  scale 2 2 3
  translate 5 4 -2
  colour 4
cube
  scale 2 2 2
  translate 2 -4 1
  colour 5
