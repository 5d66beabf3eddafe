Primitive
AABB
-0.01 -0.01 -1   0.01 0.01 0
