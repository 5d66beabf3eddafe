Primitive
AABB
-5 -5 -0.1   5 5 0
