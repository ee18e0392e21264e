# large_coordinates.mts -- coordinates up to +-22 000: objects thousands of units across
# out to +-20 000, seen in a window 44 000 units wide (beyond fixed16's range of +-16 384).
viewport 0 127 0 127
window -22000 22000 -22000 22000
viewplane 6000
parallel 0 0 -1
light direction 1 2 3
shadows on
sphere
  scale 5000 5000 5000
  translate 15000 15000 0
  colour 1
sphere
  scale 2000 2000 2000
  translate -20000 -20000 0
  colour 2
cube
  scale 8000 8000 8000
  translate 12000 -20000 -4000
  colour 3
cylinder
  scale 4000 4000 8000
  rotate x -90
  translate -16000 13000 0
  colour 4
cone
  scale 7000 7000 12000
  rotate x 90
  translate 0 5000 0
  colour 5
sphere
  scale 3000 3000 3000
  translate -3000 -12000 2000
  colour 6
