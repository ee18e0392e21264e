# specular_power.mts -- a specular power of 100 000: highlights a few pixels across where
# cos^n of an angle near zero is evaluated (n by repeated squaring), beside powers 1000 and 20.
viewport 0 127 0 127
window -15 15 -15 15
viewplane 20
parallel 0 0 -1
light direction 0.2 0.3 1
sphere
  scale 6 6 6
  translate -7 7 0
  colour 1
  ks 1
  kd 0.2
  pwr 100000
sphere
  scale 6 6 6
  translate 7 7 0
  colour 2
  ks 1
  kd 0.2
  pwr 1000
sphere
  scale 6 6 6
  translate 0 -7 0
  colour 3
  ks 1
  kd 0.2
  pwr 20
