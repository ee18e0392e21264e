# snooker-polished.mts -- the thesis's snooker scene (snooker.mts) with its chapter-5 future
# work (§5.2.2): every ball polished (reflect 0.25), so the reds mirror each other, a glass
# cue ball (transmit 0.8, ior 1.5) in front of the pink, and a second, dimmer light.
# Everything else is snooker.mts.
# millimetres, table surface y = 0,
# long axis along z (baulk cushion z = -1784.5, top cushion z = +1784.5).
# The window just encloses the balls (as the thesis's scene program did)
# and the viewport is 528 x 480 = 253,440 pixels.

viewport 0 527 0 479
window -50.845 50.845 124.9296 217.3575
viewplane 1280
perspective 0 220 1380
light point 300 1400 900
light point -600 900 1500 0.35
depth 4
ambient 0.2
shadows on
dither off

# colour groups: 16 shades each, walking up from black
group 1 15 1 1 up      # red
group 2 15 14 0 up     # yellow
group 3 1 12 4 up      # green ball
group 4 11 6 2 up      # brown
group 5 2 5 15 up      # blue
group 6 15 8 10 up     # pink
group 7 2 10 3 up      # table cloth (background)
group 8 15 15 15 up    # black ball (dark material, white highlight)
group 9 15 15 14 up    # the cue ball
background 120          # group 7, shade 8: the green cloth

sphere                 # red
  scale 26.25 26.25 26.25
  translate 0 26.25 945.75
  colour 1
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # red
  scale 26.25 26.25 26.25
  translate -26.25 26.25 991.2163
  colour 1
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # red
  scale 26.25 26.25 26.25
  translate 26.25 26.25 991.2163
  colour 1
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # red
  scale 26.25 26.25 26.25
  translate -52.5 26.25 1036.6827
  colour 1
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # red
  scale 26.25 26.25 26.25
  translate 0 26.25 1036.6827
  colour 1
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # red
  scale 26.25 26.25 26.25
  translate 52.5 26.25 1036.6827
  colour 1
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # red
  scale 26.25 26.25 26.25
  translate -78.75 26.25 1082.149
  colour 1
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # red
  scale 26.25 26.25 26.25
  translate -26.25 26.25 1082.149
  colour 1
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # red
  scale 26.25 26.25 26.25
  translate 26.25 26.25 1082.149
  colour 1
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # red
  scale 26.25 26.25 26.25
  translate 78.75 26.25 1082.149
  colour 1
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # red
  scale 26.25 26.25 26.25
  translate -105 26.25 1127.6153
  colour 1
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # red
  scale 26.25 26.25 26.25
  translate -52.5 26.25 1127.6153
  colour 1
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # red
  scale 26.25 26.25 26.25
  translate 0 26.25 1127.6153
  colour 1
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # red
  scale 26.25 26.25 26.25
  translate 52.5 26.25 1127.6153
  colour 1
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # red
  scale 26.25 26.25 26.25
  translate 105 26.25 1127.6153
  colour 1
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # yellow
  scale 26.25 26.25 26.25
  translate -292 26.25 -1047.5
  colour 2
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # green
  scale 26.25 26.25 26.25
  translate 292 26.25 -1047.5
  colour 3
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # brown
  scale 26.25 26.25 26.25
  translate 0 26.25 -1047.5
  colour 4
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # blue
  scale 26.25 26.25 26.25
  translate 0 26.25 0
  colour 5
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # pink
  scale 26.25 26.25 26.25
  translate 0 26.25 892.25
  colour 6
  ka 1.0
  kd 0.6
  ks 0.35
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # black
  scale 26.25 26.25 26.25
  translate 0 26.25 1460.5
  colour 8
  ka 0.5
  kd 0.12
  ks 0.55
  pwr 40
  rnd 0.3
  reflect 0.25
sphere                 # the cue ball, glass
  scale 26.25 26.25 26.25
  translate -45 26.25 830
  colour 9
  ka 0.15
  kd 0.1
  ks 0.6
  pwr 60
  rnd 0
  reflect 0.1
  transmit 0.8
  ior 1.5
