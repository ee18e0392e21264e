# touching.mts -- touching objects: two spheres touching each other, a sphere resting on a
# cube, a cylinder standing on it, lit from above with shadows near every contact.
viewport 0 127 0 127
window -25 25 -25 25
viewplane 0
perspective 0 30 150
light point 20 80 60
shadows on
cube
  scale 50 5 40
  translate -25 -5 -20
  colour 1
sphere
  scale 8 8 8
  translate -8 8 0
  colour 2
sphere
  scale 8 8 8
  translate 8 8 0
  colour 3
cylinder
  scale 4 4 12
  rotate x -90
  translate 0 0 12
  colour 4
sphere
  scale 4 4 4
  translate 0 20 0
  colour 5
