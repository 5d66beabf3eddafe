Primitive
AABB
-0.01 -0.01 -0.2   0.01 0.01 0
