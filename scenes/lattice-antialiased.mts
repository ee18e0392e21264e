# lattice-antialiased.mts -- the thesis's lattice scene (lattice.mts) with adaptive
# antialiasing (chapter 5, fig 2.9): at 128x64 its thin rods are stairs of single pixels;
# corners that differ by more than 6 % of full scale split down to 4x4 squares.
antialias 0.06 2
# lattice.mts -- the thesis's second test image (fig 4.13, table 4.4):
# a chemical lattice of 27 spheres (a 3 x 3 x 3 crystal, three tiers)
# threaded by 27 cylinders (9 rods along each axis).
# y up, viewer above and in front,
# looking along -z.  The window just encloses the scene and the viewport
# is 466 x 480 = 223,680 pixels.

viewport 0 465 0 479
window -41.9467 48.4416 205.0303 298.1399
viewplane 500
perspective 0 340 650
light point -300 800 700
ambient 0.2
shadows on
dither off

group 1 15 2 2 up      # atoms of the first kind: red
group 2 3 9 15 up      # atoms of the second kind: blue
group 3 15 15 13 up    # rods: ivory
group 7 1 2 6 up       # background: dark blue
background 115

sphere
  scale 22 22 22
  translate -100 -100 -100
  rotate y 20
  colour 1
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 0 -100 -100
  rotate y 20
  colour 2
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 100 -100 -100
  rotate y 20
  colour 1
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate -100 -100 0
  rotate y 20
  colour 2
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 0 -100 0
  rotate y 20
  colour 1
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 100 -100 0
  rotate y 20
  colour 2
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate -100 -100 100
  rotate y 20
  colour 1
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 0 -100 100
  rotate y 20
  colour 2
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 100 -100 100
  rotate y 20
  colour 1
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate -100 0 -100
  rotate y 20
  colour 2
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 0 0 -100
  rotate y 20
  colour 1
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 100 0 -100
  rotate y 20
  colour 2
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate -100 0 0
  rotate y 20
  colour 1
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 0 0 0
  rotate y 20
  colour 2
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 100 0 0
  rotate y 20
  colour 1
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate -100 0 100
  rotate y 20
  colour 2
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 0 0 100
  rotate y 20
  colour 1
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 100 0 100
  rotate y 20
  colour 2
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate -100 100 -100
  rotate y 20
  colour 1
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 0 100 -100
  rotate y 20
  colour 2
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 100 100 -100
  rotate y 20
  colour 1
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate -100 100 0
  rotate y 20
  colour 2
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 0 100 0
  rotate y 20
  colour 1
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 100 100 0
  rotate y 20
  colour 2
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate -100 100 100
  rotate y 20
  colour 1
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 0 100 100
  rotate y 20
  colour 2
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
sphere
  scale 22 22 22
  translate 100 100 100
  rotate y 20
  colour 1
  kd 0.6
  ks 0.4
  pwr 30
  rnd 0.3
cylinder               # rod along x
  scale 5 5 200
  rotate y 90
  translate -100 -100 -100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along x
  scale 5 5 200
  rotate y 90
  translate -100 -100 0
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along x
  scale 5 5 200
  rotate y 90
  translate -100 -100 100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along x
  scale 5 5 200
  rotate y 90
  translate -100 0 -100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along x
  scale 5 5 200
  rotate y 90
  translate -100 0 0
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along x
  scale 5 5 200
  rotate y 90
  translate -100 0 100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along x
  scale 5 5 200
  rotate y 90
  translate -100 100 -100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along x
  scale 5 5 200
  rotate y 90
  translate -100 100 0
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along x
  scale 5 5 200
  rotate y 90
  translate -100 100 100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along y
  scale 5 5 200
  rotate x -90
  translate -100 -100 -100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along y
  scale 5 5 200
  rotate x -90
  translate -100 -100 0
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along y
  scale 5 5 200
  rotate x -90
  translate -100 -100 100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along y
  scale 5 5 200
  rotate x -90
  translate 0 -100 -100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along y
  scale 5 5 200
  rotate x -90
  translate 0 -100 0
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along y
  scale 5 5 200
  rotate x -90
  translate 0 -100 100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along y
  scale 5 5 200
  rotate x -90
  translate 100 -100 -100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along y
  scale 5 5 200
  rotate x -90
  translate 100 -100 0
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along y
  scale 5 5 200
  rotate x -90
  translate 100 -100 100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along z
  scale 5 5 200
  translate -100 -100 -100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along z
  scale 5 5 200
  translate -100 0 -100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along z
  scale 5 5 200
  translate -100 100 -100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along z
  scale 5 5 200
  translate 0 -100 -100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along z
  scale 5 5 200
  translate 0 0 -100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along z
  scale 5 5 200
  translate 0 100 -100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along z
  scale 5 5 200
  translate 100 -100 -100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along z
  scale 5 5 200
  translate 100 0 -100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
cylinder               # rod along z
  scale 5 5 200
  translate 100 100 -100
  rotate y 20
  colour 3
  kd 0.7
  ks 0.3
  pwr 20
  rnd 0.3
