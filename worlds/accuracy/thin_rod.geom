Primitive
AABB
-0.5 -0.005 -0.005   0.5 0.005 0.005
