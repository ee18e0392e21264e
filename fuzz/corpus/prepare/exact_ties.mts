# exact_ties.mts -- rays exactly on the boundary of cubes whose transforms are not exact in
# binary (scales 3, 6 and 20): edges and faces lie exactly on pixel samples and on the
# window's edges, so whether a ray hits is decided by the last bit of the inverse transform,
# in every number type (f64 included). Measured, not a target (docs/hard-cases.md).
viewport 0 128 0 128
window -8 8 -8 8
viewplane 20
parallel 0 0 -1
light direction 1 2 3
cube
  scale 3 3 3
  translate 2 -6 -2
  colour 1
cube
  scale 6 6 1
  translate -8 2 -4
  colour 2
cube
  scale 20 1 20
  translate -10 -8 -10
  colour 3
cube
  scale 3 6 3
  translate -5 -5 -1
  colour 4
