# SPDX-License-Identifier: MIT
"""ATHLETE follows a recorded motion (athlete_flex.path) streamed to its controller as PID
commands from t = 2 s: each control step sends the trajectory's configuration and velocity at
that time (Klamp't's simulation tutorial). Prints the tracking error of the driven joints.

    PYTHONPATH=build/python /usr/bin/python3 docs/examples/python/stream_path.py [--window]"""
import lamina
from lamina.model import trajectory
from example import drive, parse

args = parse(__doc__, duration=5.5)
world = lamina.WorldModel(str(lamina.WORLDS / "klampt" / "athlete_fractal_1.xml"))
sim = lamina.Simulator(world)
controller = sim.controller(0)
traj = trajectory.RobotTrajectory(world.robot(0))
traj.load(str(lamina.WORLDS / "klampt" / "motions" / "athlete_flex.path"))
dt = 0.01
errors = []  # per step while the path runs: each driven joint's |actual - path| (rad)


def idle():
    t = sim.getTime() - 2.0
    if t >= 0.0:
        controller.setPIDCommand(traj.eval(t), traj.deriv(t))
    sim.simulate(dt)
    if 0.0 <= t and t + dt <= traj.endTime():
        target = traj.eval(t + dt)  # the floating base (links 0-5) follows the terrain
        errors.append([abs(a - b) for a, b in zip(sim.getActualConfig(0)[6:], target[6:])])


drive(sim, idle, args)
final = [abs(a - b) for a, b in zip(sim.getActualConfig(0)[6:], traj.eval(1e9)[6:])]
print(f"t = {sim.getTime():.2f} s, status {sim.getStatusString()}")
print(f"tracking error while moving: mean {sum(map(sum, errors)) / sum(map(len, errors)):.4f}"
      f" rad, worst {max(map(max, errors)):.4f} rad")
print(f"error at the end: mean {sum(final) / len(final):.4f} rad, worst {max(final):.4f} rad")
