Primitive
AABB
0 -1 0   0.01 1 2
