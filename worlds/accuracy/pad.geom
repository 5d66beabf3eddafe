Primitive
AABB
-0.03 -0.03 -0.01   0.03 0.03 0.01
