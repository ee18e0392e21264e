# tree3.mts -- Eric Haines' SPD scene tree3.nff, converted by scripts/nff2mts.py.
# The scene is moved into the NFF camera's frame (eye at the origin looking along -z).
# Approximations: truncated cones become cylinders of the mean radius, the ground
# rectangle a cube 0.01 thick; only the first of 7 lights (the format keeps one).

viewport 0 511 0 511
window -0.414213562 0.414213562 -0.414213562 0.414213562
viewplane -1
perspective 0 0 0
light point 5.42306215 48.7048225 -3.72030417
ambient 0.1
shadows on
dither off
group 1 3 10 3 up
group 2 8 6 3 up
group 3 1 5 11 up
background 59

cube
  scale 100 100 0.01
  rotate x -38.6598083
  rotate y 81.9016525
  rotate z 51.059772
  translate 45.3766425 -7.46637159 49.1900773
  colour 1
  kd 1
  ks 0
  pwr 100000
  cmy 0.8 0.3 0.8
cylinder
  scale 0.12525 0.12525 1
  rotate y -83.6845069
  rotate z -90
  translate 0 -1.49089687 -4.71033189
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
sphere
  scale 0.1005 0.1005 0.1005
  translate 0 -0.496965623 -4.60032881
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
cylinder
  scale 0.0839175 0.0839175 0.650000886
  rotate x 3.2625923
  rotate y -43.7955474
  rotate z -90
  translate 0 -0.496965623 -4.60032881
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
sphere
  scale 0.067335 0.067335 0.067335
  translate -0.0369929869 -0.0478375408 -4.13190952
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
cylinder
  scale 0.05622475 0.05622475 0.422498465
  rotate x -36.6316646
  rotate y -40.6757391
  rotate z -90
  translate -0.0369929869 -0.0478375408 -4.13190952
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
sphere
  scale 0.0451145 0.0451145 0.0451145
  translate 0.215098522 0.173147486 -3.87477056
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
cylinder
  scale 0.0376706 0.0376706 0.274623483
  rotate x -30.0444122
  rotate y -88.3992793
  rotate z -90
  translate 0.215098522 0.173147486 -3.87477056
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
sphere
  scale 0.0302267 0.0302267 0.0302267
  translate 0.352594575 0.410779123 -3.86812992
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
cylinder
  scale 0.0376706 0.0376706 0.295750855
  rotate x -17.5528246
  rotate y -22.3604975
  rotate z -90
  translate 0.215098522 0.173147486 -3.87477056
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
sphere
  scale 0.0302267 0.0302267 0.0302267
  translate 0.304292533 0.28042213 -3.6139926
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
cylinder
  scale 0.05622475 0.05622475 0.45499656
  rotate x 20.8321354
  rotate y -62.0665418
  rotate z -90
  translate -0.0369929869 -0.0478375408 -4.13190952
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
sphere
  scale 0.0451145 0.0451145 0.0451145
  translate -0.198803969 0.327869101 -3.9327021
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
cylinder
  scale 0.0376706 0.0376706 0.295751612
  rotate x -16.3001962
  rotate y -48.3669269
  translate -0.198803969 0.327869101 -3.9327021
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
sphere
  scale 0.0302267 0.0302267 0.0302267
  translate -0.410967862 0.410877705 -3.74411506
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
cylinder
  scale 0.0376706 0.0376706 0.318503074
  rotate x -4.1511905
  rotate y -63.0048497
  rotate z -90
  translate -0.198803969 0.327869101 -3.9327021
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
sphere
  scale 0.0302267 0.0302267 0.0302267
  translate -0.175747986 0.610925107 -3.78850804
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
cylinder
  scale 0.0839175 0.0839175 0.700004199
  rotate x 162.587447
  rotate y -78.0904149
  rotate z 90
  translate 0 -0.496965623 -4.60032881
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
sphere
  scale 0.067335 0.067335 0.067335
  translate 0.209476157 0.156583269 -4.73816736
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
cylinder
  scale 0.05622475 0.05622475 0.454997327
  rotate x -167.017708
  rotate y -51.752475
  rotate z 90
  translate 0.209476157 0.156583269 -4.73816736
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
sphere
  scale 0.0451145 0.0451145 0.0451145
  translate 0.107261053 0.504779041 -5.01263838
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
cylinder
  scale 0.0376706 0.0376706 0.295746325
  rotate x -144.225095
  rotate y -88.3502855
  rotate z 90
  translate 0.107261053 0.504779041 -5.01263838
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
sphere
  scale 0.0302267 0.0302267 0.0302267
  translate -0.0656329528 0.74462448 -5.01954615
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
cylinder
  scale 0.0376706 0.0376706 0.31849685
  rotate x 168.266491
  rotate y -47.9622465
  rotate z 90
  translate 0.107261053 0.504779041 -5.01263838
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
sphere
  scale 0.0302267 0.0302267 0.0302267
  translate 0.172030555 0.736384936 -5.22145377
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
cylinder
  scale 0.05622475 0.05622475 0.489992637
  rotate x -18.9952279
  rotate y -75.6212044
  rotate z -90
  translate 0.209476157 0.156583269 -4.73816736
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
sphere
  scale 0.0451145 0.0451145 0.0451145
  translate 0.368963567 0.605380556 -4.62311282
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
cylinder
  scale 0.0376706 0.0376706 0.318500225
  rotate x -29.8207938
  rotate y 81.0772792
  translate 0.368963567 0.605380556 -4.62311282
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
sphere
  scale 0.0302267 0.0302267 0.0302267
  translate 0.64194562 0.76376717 -4.58025406
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
cylinder
  scale 0.0376706 0.0376706 0.343001115
  rotate x -179.520446
  rotate y -88.4106941
  rotate z 90
  translate 0.368963567 0.605380556 -4.62311282
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
sphere
  scale 0.0302267 0.0302267 0.0302267
  translate 0.366092753 0.948237712 -4.63262565
  colour 2
  kd 1
  ks 0
  pwr 100000
  cmy 0.45 0.6 0.8
