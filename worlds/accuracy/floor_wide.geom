Primitive
AABB
-30 -30 -0.1   30 30 0
