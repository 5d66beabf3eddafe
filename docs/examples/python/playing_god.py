# SPDX-License-Identifier: MIT
"""Playing God: forces and torques applied to a free block from the script (Klamp't's
simulation tutorial), on the block "pushed" of worlds/examples/two_blocks.xml. It rests on the
plane; from t = 0.5 s a 10 N push
through its centre of mass slides it for 0.5 s against friction (acceleration (F - mu m g) / m,
mu the blended friction of the pair that getContacts reports); then a torque about the
vertical spins it for 0.1 s (against the friction torque of its base).

    PYTHONPATH=build/python /usr/bin/python3 docs/examples/python/playing_god.py [--window]"""
import lamina
from example import drive, parse

args = parse(__doc__, duration=1.5)
world = lamina.WorldModel(str(lamina.WORLDS / "examples" / "two_blocks.xml"))
sim = lamina.Simulator(world)
block = sim.body(world.rigidObject("pushed"))
terrain = world.terrain(0)
sim.enableContactFeedback(world.rigidObject("pushed").getID(), terrain.getID())
dt = 0.01
seen = {}


def idle():
    t = sim.getTime()
    if 0.5 - 1e-9 <= t < 1.0 - 1e-9:
        if "mu" not in seen:  # resting: each contact row ends with the pair's friction
            seen["mu"] = sim.getContacts(world.rigidObject("pushed"), terrain)[0][6]
        center = block.getTransform()[1]  # the object frame's origin is its centre of mass
        block.applyForceAtPoint([10.0, 0.0, 0.0], center)
    elif 1.0 - 1e-9 <= t < 1.1 - 1e-9:
        seen.setdefault("pushed", block.getVelocity()[1][0])
        block.applyWrench([0.0, 0.0, 0.0], [0.0, 0.0, 1.0])
    sim.simulate(dt)


drive(sim, idle, args)
mu, m, g = seen["mu"], world.rigidObject("pushed").getMass(), 9.8
print(f"friction {mu:.3f}; speed after the push: {seen['pushed']:.3f} m/s "
      f"(expected (F - mu m g) / m * t = {(10.0 - mu * m * g) / m * 0.5:.3f})")
print(f"spin at the end: {block.getVelocity()[0][2]:.3f} rad/s")
