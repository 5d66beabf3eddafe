Primitive
AABB
-0.2 -0.2 -0.2   0.2 0.2 0.2
