Primitive
Sphere
0 0 0 0.0975
