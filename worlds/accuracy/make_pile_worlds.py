#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Writes the many-body worlds of numerics section 6 that are too long to write by hand
# (docs/accuracy.md; run from anywhere, the files land beside this script):
#   pyramid_20.xml         scene 7: a pyramid of 10 cm boxes with a base of 20 (210 boxes)
#   sphere_pile_666.xml    scene 7: SimBenchmark's "666", 6 x 6 x 6 frictionless spheres
#   bouncing_balls_49.xml  scene 6: SimBenchmark's "bouncing", 7 x 7 balls with e = 1 from 5 m
#   bridge_160.xml         scene 9: Solver2D's "Bridge", 160 hinged links pinned at both ends
#   kapla_102.xml          scene 7: SimBenchmark's "Kapla" tower of 102 blocks
# Deterministic: the same files on every run (the pile's perturbations come from a fixed seed).
# Units: m, kg. The floor's top is z = 0 (floor.geom, floor_wide.geom).
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))


def write(name, header, body):
    with open(os.path.join(HERE, name), "w") as out:
        out.write('<?xml version="1.0" encoding="UTF-8"?>\n')
        out.write("<!-- " + header.strip() + " -->\n<world>\n")
        out.write("".join(body))
        out.write("</world>\n")


def obj(name, x, y, z, geom, mass, surface):
    return (f'  <rigidObject name="{name}" position="{x:.6g} {y:.6g} {z:.6g}">\n'
            f'    <geometry mesh="{geom}"/>\n'
            f'    <physics mass="{mass}" automass="1"{" " + surface if surface else ""}/>\n'
            f'  </rigidObject>\n')


def floor_surface(restitution, friction):
    return ('  <simulation>\n    <terrain index="0">\n'
            f'      <geometry kRestitution="{restitution}" kFriction="{friction}" padding="0"/>\n'
            '    </terrain>\n  </simulation>\n')


# Pyramid: row k (0 at the floor) holds 20 - k boxes, centres 0.11 m apart (the 2.5 mm layers of
# neighbours leave 5 mm between them: no side contact), each box centred over the gap between two
# boxes below and resting on their padding layers (rows 0.105 m apart, the lowest at 0.0525 m).
# The last object is the top box.
PYRAMID_BASE = 20
PYRAMID_PITCH = 0.11
PYRAMID_ROW = 0.105


def pyramid():
    body = ['  <terrain name="floor" file="floor.geom"/>\n']
    surface = 'kRestitution="0" kFriction="0.5"'
    for row in range(PYRAMID_BASE):
        count = PYRAMID_BASE - row
        for i in range(count):
            x = (i - (count - 1) / 2) * PYRAMID_PITCH
            body.append(obj(f"box{row}_{i}", x, 0, 0.0525 + row * PYRAMID_ROW, "block.geom", 1,
                            surface))
    body.append(floor_surface(0, 0.5))
    write("pyramid_20.xml", """
Accuracy scene pyramid_20 (docs/accuracy.md; numerics section 6 scene 7, Solver2D's "Pyramid"
     with its debug base of 20): 210 boxes of 10 cm, 1 kg, in 20 rows on a rigid floor; row k
     holds 20 - k boxes 0.11 m apart (5 mm between neighbouring padding layers), each resting on
     the 2.5 mm padding layers of the two boxes below it. Friction 0.5, no restitution. Static
     answer: nothing moves; the top box (the last object) stays where it starts. Written by
     make_pile_worlds.py.""", body)


# 666: SimBenchmark's 666.yaml: radius 0.1 m, 10 kg, centres 0.21 m apart (1 cm between
# surfaces), the lowest layer's centres at 0.101 m, each centre moved by up to 1 mm in x and y
# (seed 42), restitution 0, friction 0. Lamina's radius 0.1 is the padded surface: a 0.0975 m
# sphere with the 2.5 mm default padding.
def sphere_pile():
    rng = random.Random(42)
    body = ['  <terrain name="floor" file="floor_wide.geom"/>\n']
    surface = 'kRestitution="0" kFriction="0"'
    for k in range(6):
        for j in range(6):
            for i in range(6):
                x = (i - 2.5) * 0.21 + rng.uniform(-0.001, 0.001)
                y = (j - 2.5) * 0.21 + rng.uniform(-0.001, 0.001)
                body.append(obj(f"ball{k}_{j}_{i}", x, y, 0.101 + k * 0.21, "pile_ball.geom", 10,
                                surface))
    body.append(floor_surface(0, 0))
    write("sphere_pile_666.xml", """
Accuracy scene sphere_pile_666 (docs/accuracy.md; numerics section 6 scene 7, SimBenchmark's
     "666"): 6 x 6 x 6 spheres of radius 0.1 m (a 0.0975 m core with the 2.5 mm padding), 10 kg,
     centres 0.21 m apart with the lowest layer's 1 mm above the floor, each moved by up to 1 mm
     sideways so the cube collapses. No friction (mu = 0), no restitution, on a 60 m rigid floor.
     Rigid answer: no two padded spheres, and no sphere and the floor, ever overlap. Written by
     make_pile_worlds.py.""", body)


# Bouncing: SimBenchmark's bouncing.yaml: 7 x 7 balls of radius 0.1 m, 10 kg, centres 5 m above
# the floor, restitution 1, friction 0; 1 m apart so they never meet.
def bouncing_balls():
    body = ['  <terrain name="floor" file="floor.geom"/>\n']
    surface = 'kRestitution="1" kFriction="0"'
    for j in range(7):
        for i in range(7):
            body.append(obj(f"ball{j}_{i}", i - 3.0, j - 3.0, 5.0, "ball.geom", 10, surface))
    body.append(floor_surface(1, 0))
    write("bouncing_balls_49.xml", """
Accuracy scene bouncing_balls_49 (docs/accuracy.md; numerics section 6 scene 6, SimBenchmark's
     "bouncing"): 7 x 7 balls of radius 0.1 m (2.5 mm padding), 10 kg, 1 m apart, released from
     rest with their centres 5 m above a rigid floor (top z = 0). Restitution 1 and no friction on
     all. Answer: the total energy stays E0 = 49 m g 5 m. Written by make_pile_worlds.py.""", body)


# Bridge: Solver2D's Bridge sample: 160 links of 1 m (0.25 m thick), hinged end to end at
# x = -80 ... 80 m, z = 20 m, the first and the last hinged to the world; the links are laid
# straight and level, exactly as long as the span. Solver2D's links are 20 kg/m^2 x 0.25 m^2 =
# 5 kg. No contact (links do not collide).
BRIDGE_LINKS = 160


def bridge():
    body = []
    for i in range(BRIDGE_LINKS):
        body.append(obj(f"link{i}", -80 + 0.5 + i, 0, 20, "bridge_link.geom", 5, ""))
    body.append('  <simulation>\n    <globals rigidObjectCollisions="0"/>\n')
    for i in range(BRIDGE_LINKS + 1):
        body.append(f'    <joint type="hinge" point="{-80 + i} 0 20" axis="0 1 0">\n')
        if i == 0:
            body.append('      <rigidObject name="link0"/>\n')
        elif i == BRIDGE_LINKS:
            body.append(f'      <rigidObject name="link{i - 1}"/>\n')
        else:
            body.append(f'      <rigidObject name="link{i}"/><rigidObject name="link{i - 1}"/>\n')
        body.append('    </joint>\n')
    body.append('  </simulation>\n')
    write("bridge_160.xml", """
Accuracy scene bridge_160 (docs/accuracy.md; numerics section 6 scene 9, Solver2D's "Bridge"):
     160 links of 1 x 0.25 x 0.25 m, 5 kg each, joined end to end by world-level hinges (axis y)
     at x = -80 ... 80 m, z = 20 m; the first and the last link are also hinged to the world, so
     the links lie straight and level, exactly as long as the span, and are released from rest.
     Links do not collide. Rigid answer: every hinge keeps its anchor points together (zero
     gap); a rigid bridge that long cannot sag at all. Written by make_pile_worlds.py.""", body)


# Kapla: SimBenchmark's KaplaBenchmark (bulletSim/KaplaBenchmark.cpp: shortLen 0.05, longLen 0.2,
# heightLen 0.1 m); each of 6 floors has 8 "base" blocks across y at x = 0, 0.2, ... 1.4 (centres
# 0.05 m above the floor's bottom) and on them "wall" blocks of 0.2 x 0.05 x 0.1 m along x at
# y = -0.1 (x = 0.1, 0.5, 0.9, 1.3) and y = +0.1 (x = 0.1, 0.3, 0.7, 1.1, 1.3), centres 0.15 m
# above it; floors 0.2 m apart: 6 x 17 = 102 blocks. The sizes of SimBenchmark's base.urdf and
# wall.urdf are not in the sources read: the bases here are 0.05 x 0.25 x 0.1 m, so that each wall
# rests across its whole width on the bases' ends (with 0.2 m bases a wall's centre of mass would
# stand exactly over their edge). Lamina's padded block is that block (cores 5 mm smaller under
# 2.5 mm of padding), so every block rests on the padding layers below it. 1 kg each, friction
# 0.5, no restitution (nor are the masses and friction in those sources). The last object is the
# top floor's last wall block, whose fall SimBenchmark takes as the collapse.
KAPLA_FLOORS = 6
KAPLA_BASES = 8


def kapla():
    body = ['  <terrain name="floor" file="floor.geom"/>\n']
    surface = 'kRestitution="0" kFriction="0.5"'
    walls = KAPLA_BASES // 2
    for floor in range(KAPLA_FLOORS):
        z = floor * 0.2
        for j in range(KAPLA_BASES):
            body.append(obj(f"base{floor}_{j}", j * 0.2, 0, z + 0.05, "kapla_base.geom", 1, surface))
        right = [j * 0.4 + 0.1 for j in range(walls)]
        left = [0.1] + [j * 0.4 + 0.3 for j in range(walls - 1)] + [(walls - 1) * 0.4 + 0.1]
        for k, x in enumerate(right):
            body.append(obj(f"wall{floor}_r{k}", x, -0.1, z + 0.15, "kapla_wall.geom", 1, surface))
        for k, x in enumerate(left):
            body.append(obj(f"wall{floor}_l{k}", x, 0.1, z + 0.15, "kapla_wall.geom", 1, surface))
    body.append(floor_surface(0, 0.5))
    write("kapla_102.xml", """
Accuracy scene kapla_102 (docs/accuracy.md; numerics section 6 scene 7, SimBenchmark's
     "Kapla"): a tower of 102 blocks (the padded surface: cores 5 mm smaller under 2.5 mm of
     padding), 1 kg each, in 6 floors of 8 blocks of 0.05 x 0.25 x 0.1 m across and 9 blocks of
     0.2 x 0.05 x 0.1 m along on their ends, every block resting on the padding layers below it
     (the walls wholly on the bases' ends). Friction 0.5, no
     restitution. Static answer: the tower stands; the top floor's last block (the last object)
     stays where it starts. Written by make_pile_worlds.py.""", body)


if __name__ == "__main__":
    pyramid()
    sphere_pile()
    bouncing_balls()
    bridge()
    kapla()
