Primitive
AABB
-0.05 -0.05 -0.05   0.05 0.05 0.05
