# SPDX-License-Identifier: MIT
"""Kinematic drive: a block with its dynamics turned off moves at the velocity the script sets,
whatever pushes back, and shoves a second block ahead of it (Klamp't's simulation tutorial;
worlds/examples/two_blocks.xml, the blocks 0.3 m apart, driven at 0.2 m/s).

    PYTHONPATH=build/python /usr/bin/python3 docs/examples/python/kinematic_push.py [--window]"""
import lamina
from example import drive, parse

args = parse(__doc__, duration=3.0)
world = lamina.WorldModel(str(lamina.WORLDS / "examples" / "two_blocks.xml"))
sim = lamina.Simulator(world)
pusher = sim.body(world.rigidObject("pusher"))
pushed = sim.body(world.rigidObject("pushed"))
pusher.enableDynamics(False)
pusher.setVelocity([0.0, 0.0, 0.0], [0.2, 0.0, 0.0])  # angular first, as Klamp't


def idle():
    sim.simulate(0.01)


drive(sim, idle, args)
print(f"t = {sim.getTime():.2f} s")
print(f"pusher x: {pusher.getTransform()[1][0]:.4f} m (0.2 m/s * t = {0.2 * sim.getTime():.4f})")
print(f"pushed x: {pushed.getTransform()[1][0]:.4f} m (started at 0.3)")
