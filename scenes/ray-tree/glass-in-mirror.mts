# glass-in-mirror.mts -- a hard case of the ray tree (chapter 5): a glass ball (transmit 0.9,
# ior 1.5) inside a larger reflective, partly transparent ball, in front of a striped wall,
# so rays refract in, reflect inside, pass through the inner glass and leave again.
viewport 0 63 0 47
window -40 40 -30 30
viewplane 0
perspective 0 0 150
light point -80 120 160
shadows on
depth 6
group 1 15 3 3 up
group 2 3 15 3 up
group 3 12 12 12 up
background 35
cube                     # the wall behind
  scale 160 120 2
  translate -80 -60 -120
  colour 2
sphere                   # red ball behind the glass
  scale 10 10 10
  translate 12 -6 -60
  colour 1
sphere                   # the outer ball: a mirror that lets light through
  scale 28 28 28
  translate 0 0 -20
  colour 3
  ka 0.05
  kd 0.05
  ks 0.5
  reflect 0.4
  transmit 0.55
  ior 1.2
sphere                   # the glass inside it
  scale 12 12 12
  translate -4 3 -20
  colour 3
  ka 0.02
  kd 0.02
  ks 0.6
  transmit 0.9
  reflect 0.05
  ior 1.5
