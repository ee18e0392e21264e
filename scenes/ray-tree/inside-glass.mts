# inside-glass.mts -- a hard case of the ray tree (chapter 5): the eye inside a glass ball
# (transmit 0.9, ior 1.5), so every primary ray starts inside an object: it leaves through the
# inner surface, refracted from glass into air, or is totally reflected at grazing angles.
viewport 0 63 0 47
window -40 40 -30 30
viewplane 0
perspective 0 0 30
light point 0 100 100
shadows on
depth 5
group 1 15 3 3 up
group 2 3 15 3 up
group 3 12 12 12 up
background 35
sphere                   # the glass around the eye
  scale 60 60 60
  translate 0 0 20
  colour 3
  ka 0.02
  kd 0.02
  ks 0.3
  transmit 0.9
  ior 1.5
sphere                   # a red ball outside it
  scale 20 20 20
  translate 0 0 -100
  colour 1
cube                     # a green floor
  scale 400 2 400
  translate -200 -62 -300
  colour 2
