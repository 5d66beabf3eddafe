Primitive
AABB
-1 -1 -0.01   1 1 0
