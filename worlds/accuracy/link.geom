Primitive
AABB
-0.5 -0.02 -0.02   0.5 0.02 0.02
