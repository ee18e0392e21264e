# lattice1.mts -- Eric Haines' SPD scene lattice1.nff, converted by scripts/nff2mts.py.
# The scene is moved into the NFF camera's frame (eye at the origin looking along -z).
# Approximations: truncated cones become cylinders of the mean radius, the ground
# rectangle a cube 0.01 thick; only the first of 6 lights (the format keeps one).

viewport 0 511 0 511
window -0.577350269 0.577350269 -0.577350269 0.577350269
viewplane -1
perspective 0 0 0
light point 1.53960072 0.0680413817 -0.353553391
ambient 0.1
shadows on
dither off
group 1 14 14 14 up
group 2 14 2 2 up
group 3 2 14 2 up
group 4 2 2 14 up
group 5 1 5 11 up
background 91

sphere
  scale 0.25 0.25 0.25
  translate -0.384900179 -0.476289672 -1.06066017
  colour 1
  kd 0.5
  ks 0.5
  pwr 3.0827
  cmy 0.1 0.1 0.1
cylinder
  scale 0.0625 0.0625 0.7525
  rotate x -15.793169
  rotate y 90
  translate -0.265821686 -0.442609188 -1.06066017
  colour 2
  kd 0.99
  ks 0
  pwr 100000
  cmy 0.1 0.9 0.9
cylinder
  scale 0.0625 0.0625 0.7525
  rotate x 11.0958033
  rotate y -43.8978862
  rotate z -90
  translate -0.408715878 -0.392088462 -0.973155708
  colour 3
  kd 0.99
  ks 0
  pwr 100000
  cmy 0.9 0.1 0.9
cylinder
  scale 0.0625 0.0625 0.7525
  rotate x -11.0958033
  rotate y 43.8978862
  rotate z -90
  translate -0.361084481 -0.560490882 -0.973155708
  colour 4
  kd 0.99
  ks 0
  pwr 100000
  cmy 0.9 0.9 0.1
sphere
  scale 0.25 0.25 0.25
  translate -0.19245009 -1.15670349 -0.353553391
  colour 1
  kd 0.5
  ks 0.5
  pwr 3.0827
  cmy 0.1 0.1 0.1
cylinder
  scale 0.0625 0.0625 0.7525
  rotate x -15.793169
  rotate y 90
  translate -0.0733715967 -1.12302301 -0.353553391
  colour 2
  kd 0.99
  ks 0
  pwr 100000
  cmy 0.1 0.9 0.9
cylinder
  scale 0.0625 0.0625 0.7525
  rotate x 11.0958033
  rotate y -43.8978862
  rotate z -90
  translate -0.216265788 -1.07250228 -0.266048926
  colour 3
  kd 0.99
  ks 0
  pwr 100000
  cmy 0.9 0.1 0.9
sphere
  scale 0.25 0.25 0.25
  translate -0.577350269 0.204124145 -0.353553391
  colour 1
  kd 0.5
  ks 0.5
  pwr 3.0827
  cmy 0.1 0.1 0.1
cylinder
  scale 0.0625 0.0625 0.7525
  rotate x -15.793169
  rotate y 90
  translate -0.458271776 0.237804629 -0.353553391
  colour 2
  kd 0.99
  ks 0
  pwr 100000
  cmy 0.1 0.9 0.9
cylinder
  scale 0.0625 0.0625 0.7525
  rotate x -11.0958033
  rotate y 43.8978862
  rotate z -90
  translate -0.553534571 0.119922935 -0.266048926
  colour 4
  kd 0.99
  ks 0
  pwr 100000
  cmy 0.9 0.9 0.1
sphere
  scale 0.25 0.25 0.25
  translate -0.384900179 -0.476289672 0.353553391
  colour 1
  kd 0.5
  ks 0.5
  pwr 3.0827
  cmy 0.1 0.1 0.1
cylinder
  scale 0.0625 0.0625 0.7525
  rotate x -15.793169
  rotate y 90
  translate -0.265821686 -0.442609188 0.353553391
  colour 2
  kd 0.99
  ks 0
  pwr 100000
  cmy 0.1 0.9 0.9
sphere
  scale 0.25 0.25 0.25
  translate 0.577350269 -0.204124145 -1.06066017
  colour 1
  kd 0.5
  ks 0.5
  pwr 3.0827
  cmy 0.1 0.1 0.1
cylinder
  scale 0.0625 0.0625 0.7525
  rotate x 11.0958033
  rotate y -43.8978862
  rotate z -90
  translate 0.553534571 -0.119922935 -0.973155708
  colour 3
  kd 0.99
  ks 0
  pwr 100000
  cmy 0.9 0.1 0.9
cylinder
  scale 0.0625 0.0625 0.7525
  rotate x -11.0958033
  rotate y 43.8978862
  rotate z -90
  translate 0.601165968 -0.288325355 -0.973155708
  colour 4
  kd 0.99
  ks 0
  pwr 100000
  cmy 0.9 0.9 0.1
sphere
  scale 0.25 0.25 0.25
  translate 0.769800359 -0.884537963 -0.353553391
  colour 1
  kd 0.5
  ks 0.5
  pwr 3.0827
  cmy 0.1 0.1 0.1
cylinder
  scale 0.0625 0.0625 0.7525
  rotate x 11.0958033
  rotate y -43.8978862
  rotate z -90
  translate 0.74598466 -0.800336753 -0.266048926
  colour 3
  kd 0.99
  ks 0
  pwr 100000
  cmy 0.9 0.1 0.9
sphere
  scale 0.25 0.25 0.25
  translate 0.384900179 0.476289672 -0.353553391
  colour 1
  kd 0.5
  ks 0.5
  pwr 3.0827
  cmy 0.1 0.1 0.1
cylinder
  scale 0.0625 0.0625 0.7525
  rotate x -11.0958033
  rotate y 43.8978862
  rotate z -90
  translate 0.408715878 0.392088462 -0.266048926
  colour 4
  kd 0.99
  ks 0
  pwr 100000
  cmy 0.9 0.9 0.1
sphere
  scale 0.25 0.25 0.25
  translate 0.577350269 -0.204124145 0.353553391
  colour 1
  kd 0.5
  ks 0.5
  pwr 3.0827
  cmy 0.1 0.1 0.1
