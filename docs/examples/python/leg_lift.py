# SPDX-License-Identifier: MIT
"""ATHLETE on fractal terrain lifts a leg: at t = 2 s hip pitch 1 (q[7]) is sent 1 rad up, then
1.5 rad back down, as milestones (Klamp't's simulation tutorial). The foot rises about 0.2 m
and comes back; the base stays.

    PYTHONPATH=build/python /usr/bin/python3 docs/examples/python/leg_lift.py [--window]"""
import lamina
from example import drive, parse

args = parse(__doc__, duration=6.0)
world = lamina.WorldModel(str(lamina.WORLDS / "klampt" / "athlete_fractal_1.xml"))
sim = lamina.Simulator(world)
controller = sim.controller(0)
foot = sim.body(world.robotlink(0, 11))  # ankle roll 1, the foot of leg 1
dt = 0.02
foot_z = {}  # foot height (m): at t = 2 s and the highest since
base = {}  # base position (m): at t = 2 s and the farthest from it while the leg is up


def idle():
    if sim.getTime() >= 2.0 and sim.getTime() - dt < 2.0:
        foot_z["start"] = foot_z["top"] = foot.getTransform()[1][2]
        base["start"], base["moved"] = sim.getActualConfig(0)[:3], 0.0
        q = controller.getCommandedConfig()
        q[7] -= 1.0
        controller.setMilestone(q)
        q[7] += 1.5
        controller.addMilestone(q)
    sim.simulate(dt)
    if foot_z and foot.getTransform()[1][2] > foot_z["start"] + 0.03:  # the leg is up
        foot_z["top"] = max(foot_z["top"], foot.getTransform()[1][2])
        moved = max(abs(a - b) for a, b in zip(sim.getActualConfig(0)[:3], base["start"]))
        base["moved"] = max(base["moved"], moved)


drive(sim, idle, args)
print(f"t = {sim.getTime():.2f} s, status {sim.getStatusString()}")
if foot_z:
    print(f"foot rise: {foot_z['top'] - foot_z['start']:.3f} m, "
          f"back to {foot.getTransform()[1][2] - foot_z['start']:+.3f} m")
    print(f"base moved at most {base['moved']:.4f} m while the leg was up")
