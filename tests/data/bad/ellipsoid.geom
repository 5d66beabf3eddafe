Primitive
Ellipsoid
0 0 0  1 0 0  0 1 0  0 0 1  1 2 3
