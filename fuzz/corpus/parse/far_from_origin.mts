# far_from_origin.mts -- a scene far from the origin: objects 10 to 20 units across near
# (15000, -12000, 18000), the eye and the window with them, so every coordinate is large and
# every difference small (beyond fixed16's range of +-16 384).
viewport 0 127 0 127
window 14975 15025 -12025 -11975
viewplane 18000
perspective 15000 -11970 18150
light point 15020 -11920 18060
shadows on
cube
  scale 50 5 40
  translate 14975 -12005 17980
  colour 1
sphere
  scale 8 8 8
  translate 14992 -11992 18000
  colour 2
sphere
  scale 8 8 8
  translate 15008 -11992 18000
  colour 3
cylinder
  scale 4 4 12
  rotate x -90
  translate 15000 -12000 18012
  colour 4
