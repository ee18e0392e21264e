# mirror-balls.mts -- many reflective objects for the ray tree's acceleration (chapter 5,
# §5.2.1): 64 polished balls (reflect 0.6) in a 4 x 4 x 4 block over a mirror floor, seen from
# above at an angle, so most secondary rays travel between balls. tests/tests/ray_tree.rs
# counts the ray-object tests per secondary ray with the uniform 3-D grid, with bounding
# spheres alone and by brute force.
viewport 0 127 0 95
window -60 60 -45 45
viewplane 0
perspective 0 120 260
light point 150 300 200
light point -200 150 100 0.4
shadows on
depth 4
group 1 15 3 3 up
group 2 3 6 15 up
group 3 3 14 4 up
group 4 14 12 2 up
group 5 10 10 10 up
background 85
cube                     # the floor, a dim mirror
  scale 400 2 400
  translate -200 -42 -300
  colour 5
  ka 0.3
  kd 0.4
  ks 0
  rnd 0
  reflect 0.3
sphere
  scale 9 9 9
  translate -45 -25 -100
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -45 -25 -70
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -45 -25 -40
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -45 -25 -10
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -45 -3 -100
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -45 -3 -70
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -45 -3 -40
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -45 -3 -10
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -45 19 -100
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -45 19 -70
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -45 19 -40
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -45 19 -10
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -45 41 -100
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -45 41 -70
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -45 41 -40
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -45 41 -10
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 -25 -100
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 -25 -70
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 -25 -40
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 -25 -10
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 -3 -100
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 -3 -70
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 -3 -40
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 -3 -10
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 19 -100
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 19 -70
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 19 -40
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 19 -10
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 41 -100
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 41 -70
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 41 -40
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate -15 41 -10
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 -25 -100
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 -25 -70
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 -25 -40
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 -25 -10
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 -3 -100
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 -3 -70
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 -3 -40
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 -3 -10
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 19 -100
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 19 -70
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 19 -40
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 19 -10
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 41 -100
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 41 -70
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 41 -40
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 15 41 -10
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 -25 -100
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 -25 -70
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 -25 -40
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 -25 -10
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 -3 -100
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 -3 -70
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 -3 -40
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 -3 -10
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 19 -100
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 19 -70
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 19 -40
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 19 -10
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 41 -100
  colour 3
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 41 -70
  colour 4
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 41 -40
  colour 1
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
sphere
  scale 9 9 9
  translate 45 41 -10
  colour 2
  ka 0.4
  kd 0.5
  ks 0.5
  pwr 40
  rnd 0
  reflect 0.6
