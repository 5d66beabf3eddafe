Primitive
Sphere
0 0 0 0.10795
