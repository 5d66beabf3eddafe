Primitive
AABB
-0.5 -0.5 -0.1   3.5 0.5 0
