Primitive
AABB
-0.05 -0.2 -0.45   0.05 0.2 0.45
