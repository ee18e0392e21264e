# torus_large.mts -- a torus 37 500 units across, tilted, and a small one beside it, seen in a
# window 48 000 units wide (beyond fixed16's range of +-16 384): the object-space ray is the
# world's divided by 15 000, and the quartic must keep its roots where a unit torus has them
# (POV-Ray's roots off by 0.1 on scaled shapes).
viewport 0 127 0 127
window -24000 24000 -24000 24000
viewplane 20000
parallel 0 0 -1
light direction 1 2 3
shadows on
torus 0.25
  scale 15000 15000 15000
  rotate x 60
  colour 1
torus 0.4
  scale 2000 2000 2000
  rotate y 40
  translate 16000 -16000 0
  colour 2
