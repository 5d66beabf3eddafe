Primitive
AABB
-1 -2 -0.1   24 1 0
