Primitive
AABB
-1 -1 -0.1   24 1 0
