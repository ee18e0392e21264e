# coincident.mts -- coincident objects: two spheres with the same transform (the first in
# the scene wins the tie), two cubes whose front faces share a plane, and a cylinder cap
# lying on a cube face. Coplanar surfaces share a colour so the image does not depend on
# which one wins; the identical spheres differ so the tie-break shows.
viewport 0 127 0 127
window -20 20 -20 20
viewplane 30
parallel 0 0 -1
light direction 1 1 2
shadows on
sphere
  scale 6 6 6
  translate -8 8 0
  colour 1
sphere
  scale 6 6 6
  translate -8 8 0
  colour 2
cube
  scale 10 10 10
  translate 2 2 -10
  colour 3
cube
  scale 5 14 10
  translate 6 0 -10
  colour 3
cube
  scale 16 8 4
  translate -18 -16 -4
  colour 4
cylinder
  scale 4 4 3
  translate -10 -12 0
  colour 4
