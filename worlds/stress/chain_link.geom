Primitive
AABB
0 -0.01 -0.01   0.1 0.01 0.01
