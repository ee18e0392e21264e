# near_singular.mts -- near-singular transforms: a cube, a sphere, a cylinder and a cone
# each 1e-4 thick (plates and discs about 1 unit across), tilted toward the eye. The inverse
# transforms hold entries of 10 000, and the eye is 20 000 thicknesses away.
viewport 0 127 0 127
window -1.2 1.2 -1.2 1.2
viewplane 0
perspective 0 0 2
light direction 1 1 2
cube
  scale 1 1 0.0001
  rotate x -50
  translate -1 0.1 -0.5
  colour 1
sphere
  scale 0.5 0.5 0.0001
  rotate y 40
  translate 0.5 0.6 -0.5
  colour 2
cylinder
  scale 0.5 0.5 0.0001
  rotate x 60
  translate -0.5 -0.6 -0.5
  colour 3
cone
  scale 0.0001 0.5 0.5
  rotate y 20
  translate 0.4 -0.8 -0.6
  colour 4
