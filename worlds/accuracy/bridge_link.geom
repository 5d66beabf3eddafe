Primitive
AABB
-0.5 -0.125 -0.125   0.5 0.125 0.125
